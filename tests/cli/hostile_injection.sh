# Hostile names and values through scripts/sequence and `penumbra sweep -j 2`: $(...), ;, quotes,
# spaces and GNU parallel's replacement strings in scene names, output patterns and -D values
# are data: no injected command runs, and every frame and run is written by the parallel jobs.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
sequence="$PENUMBRA_SOURCE_DIR/scripts/sequence"
no_injection() {
    [ -z "$(find "$WORK" -name 'PWNED*')" ] || fail "an injected command ran: $(find "$WORK" -name 'PWNED*')"
}

mkdir "dir with space"
scene="dir with space/s\$(touch PWNED1);touch PWNED2 'q\"{}.json"
cp "$DATA/small.json" "$scene"
pattern="out C/f\$(touch PWNED3);x'{=system(\"touch PWNED4\")=}.####.exr"
"$sequence" "$scene" -j 2 --binary "$PENUMBRA" -- -o "$pattern" -D 'lights.0.size=[2, 2]' \
    -D "name=x;touch PWNED5;true" -D 'technique.map_size=128' >summary.txt 2>stderr.txt ||
    { cat summary.txt stderr.txt; fail "sequence with hostile names failed"; }
grep -q "3 frames: 3 written, 0 skipped (already there), 0 failed" summary.txt ||
    { cat summary.txt stderr.txt; fail "sequence summary"; }
for f in 1 2 3; do
    [ -f "out C/f\$(touch PWNED3);x'{=system(\"touch PWNED4\")=}.000$f.exr" ] || fail "frame $f missing"
done
no_injection

# The same frame through one process (the scene as sequence names it, absolute): the jobs got
# the same values, the light size too.
"$PENUMBRA" render "$WORK/$scene" -f 2 -o one.exr -D 'lights.0.size=[2, 2]' -D "name=x;touch PWNED5;true" \
    -D 'technique.map_size=128' --quiet
cmp one.exr "out C/f\$(touch PWNED3);x'{=system(\"touch PWNED4\")=}.0002.exr" ||
    fail "a parallel job rendered other values than one process"

# penumbra sweep -j 2: its jobs get the same hostile values; none is retried serially.
"$PENUMBRA" sweep "$scene" -t hard --vary technique.pcf=1,5 -D 'lights.0.size=[2, 2]' \
    -D "name=x;touch PWNED6;true" -D "technique.map_size=128" \
    --reference-set 'technique.samples=2' --repeat 1 --warmup 0 --no-report -j 2 \
    -o "sw \$(touch PWNED7);'{}" 2>log.txt || { cat log.txt; fail "sweep -j 2 failed"; }
grep -q "2 runs (2 rendered, 0 reused, 0 failed)" log.txt || { cat log.txt; fail "sweep summary"; }
grep -q "retrying them here" log.txt && { cat log.txt; fail "the parallel jobs failed"; }
for r in 1 2; do
    [ -f "sw \$(touch PWNED7);'{}/runs/run-000$r.exr" ] || fail "sweep run $r missing"
done
no_injection
echo "hostile_injection ok"
