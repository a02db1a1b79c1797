# scripts/ab-passes: one technique in two builds, alternated, per-pass medians and the frame's
# ratio; --same compares their pixels; bad arguments exit 2 with one line naming them.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
ab=("$PENUMBRA_SOURCE_DIR/scripts/ab-passes")
scene="$PENUMBRA_SOURCE_DIR/scenes/default.json"
out=$("${ab[@]}" --baseline "$PENUMBRA" --binary "$PENUMBRA" -t reference --size 32x24 \
    --rounds 2 --same -D technique.samples=2 "$scene") || fail "the same build twice: $out"
echo "$out" | grep -qE "^default \(reference, 32x24, median of 2 rounds\): frame [0-9.]+ -> [0-9.]+ ms \([0-9.]+x\)$" ||
    fail "the frame line: $out"
echo "$out" | grep -qE "^  shadow_test +[0-9.]+ -> +[0-9.]+ ms$" || fail "a pass line: $out"
# A baseline that renders another image: --same says so and exits 1.
cat >other <<WRAP
#!/usr/bin/env bash
exec "$PENUMBRA" "\$@" -D technique.samples=3
WRAP
chmod +x other
rc=0
out=$("${ab[@]}" --baseline ./other --binary "$PENUMBRA" -t reference --size 32x24 --rounds 1 \
    --same -D technique.samples=2 "$scene") || rc=$?
[ "$rc" -eq 1 ] || fail "different images must exit 1, got $rc: $out"
echo "$out" | grep -q "^default: the images differ$" || fail "the difference named: $out"
# --glsl: this build with a changed copy of the shaders (here a shade pass whose beauty is black),
# the baseline with its own.
cp -r "$PENUMBRA_SOURCE_DIR/glsl" variant
sed -i 's|^void main() {|void main() { o_beauty = vec4(0.0); return;|' variant/passes/shade.frag
grep -q "o_beauty = vec4(0.0); return;" variant/passes/shade.frag || fail "the variant's edit"
rc=0
out=$("${ab[@]}" --baseline "$PENUMBRA" --glsl variant -t hard --size 32x24 --rounds 1 --same \
    "$scene") || rc=$?
[ "$rc" -eq 1 ] || fail "--glsl's variant must render another image, got $rc: $out"
out=$("${ab[@]}" --baseline "$PENUMBRA" --glsl "$PENUMBRA_SOURCE_DIR/glsl" -t hard --size 32x24 \
    --rounds 1 --same "$scene") || fail "--glsl with the same shaders: $out"
# --baseline-define: the same build with another setting as the baseline.
rc=0
out=$("${ab[@]}" --baseline "$PENUMBRA" --baseline-define technique.samples=3 -t reference \
    --size 32x24 --rounds 1 --same -D technique.samples=2 "$scene") || rc=$?
[ "$rc" -eq 1 ] || fail "--baseline-define's other samples must render another image: $rc $out"
expect_exit 2 "^ab-passes: --baseline-define samples: expected KEY=VALUE$" -- \
    "${ab[@]}" --baseline "$PENUMBRA" --baseline-define samples -t hard --size 32x24 "$scene"
expect_exit 2 "^ab-passes: --glsl nowhere: not a folder$" -- \
    "${ab[@]}" --baseline "$PENUMBRA" --glsl nowhere -t hard --size 32x24 "$scene"
expect_exit 2 "^ab-passes: --size 32by24: expected WxH$" -- \
    "${ab[@]}" --baseline "$PENUMBRA" -t hard --size 32by24 "$scene"
expect_exit 2 "^ab-passes: nowhere.json: no such scene file$" -- \
    "${ab[@]}" --baseline "$PENUMBRA" -t hard --size 32x24 nowhere.json
expect_exit 2 "^ab-passes: ./missing: not an executable$" -- \
    "${ab[@]}" --baseline ./missing -t hard --size 32x24 "$scene"
echo "ab_passes: ok"
