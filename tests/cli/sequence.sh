# scripts/sequence: a 6-frame animated scene rendered as parallel jobs (2 at a time) gives
# byte-identical EXRs to the same sequence rendered in one process; resuming renders nothing
# twice; --frame-from-env renders the frame a farm names.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
scene="$DATA/anim6.json"
sequence="$PENUMBRA_SOURCE_DIR/scripts/sequence"

"$PENUMBRA" render "$scene" -o "one/f.####.exr" --quiet
"$sequence" "$scene" -j 2 --binary "$PENUMBRA" -- -o "par/f.####.exr" >summary.txt
grep -q "6 frames: 6 written, 0 skipped (already there), 0 failed" summary.txt ||
    { cat summary.txt; fail "sequence summary"; }
for f in 1 2 3 4 5 6; do
    name=$(printf 'f.%04d.exr' "$f")
    cmp "one/$name" "par/$name" || fail "frame $f differs between one process and parallel jobs"
done
cmp -s one/f.0001.exr one/f.0006.exr && fail "the animation does not change the image"

# Resume: remove two frames; only those are rendered again.
rm par/f.0002.exr par/f.0005.exr
before=$(stat -c %Y par/f.0001.exr)
sleep 1
"$sequence" "$scene" -j 2 --binary "$PENUMBRA" -- -o "par/f.####.exr" >summary.txt
grep -q "6 frames: 2 written, 4 skipped" summary.txt || { cat summary.txt; fail "resume summary"; }
[ "$(stat -c %Y par/f.0001.exr)" = "$before" ] || fail "resume re-rendered frame 1"
cmp one/f.0005.exr par/f.0005.exr || fail "resumed frame 5 differs"

# A failing frame: exit 1 and counted (its folder cannot be created: a file is in the way).
echo "not a folder" >blocker
rc=0
"$sequence" "$scene" -j 2 --binary "$PENUMBRA" --joblog fail.log -- -f 1-2 -o "blocker/f.####.exr" \
    >summary.txt 2>/dev/null || rc=$?
[ "$rc" -eq 1 ] || fail "a failed frame should exit 1, got $rc"
grep -q "2 frames: 0 written, 0 skipped (already there), 2 failed" summary.txt ||
    { cat summary.txt; fail "failure summary"; }
# Bad input is refused before any job runs.
expect_exit 2 "^penumbra: --output: plain.exr: no # for the frame number" -- "$sequence" "$scene" --binary "$PENUMBRA" -- -o plain.exr
expect_exit 2 "frames" -- "$sequence" "$scene" --binary "$PENUMBRA" -- -f 9-1 -o "x.#.exr"

# A farm task index: frame = $TASK + offset, same bytes as the sequence's frame 4.
TASK=3 "$PENUMBRA" render "$scene" --frame-from-env TASK --frame-offset 1 -o "farm/f.####.exr" --quiet
cmp one/f.0004.exr farm/f.0004.exr || fail "--frame-from-env frame differs"
expect_exit 2 "TASK='x' is not a whole number" -- env TASK=x "$PENUMBRA" render "$scene" \
    --frame-from-env TASK -o y.exr
expect_exit 2 "NOT_SET is not set" -- "$PENUMBRA" render "$scene" --frame-from-env NOT_SET -o y.exr
expect_exit 2 "only with --frame-from-env" -- "$PENUMBRA" render "$scene" --frame-offset 2 -o y.exr
echo "sequence ok"
