# penumbra sweep end to end: the cartesian product, one cached reference per image-changing
# setting, CSV/JSON/images/report, resuming without rendering again, and bad input refused
# before anything renders.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
scene="$DATA/small.json"
args=(sweep "$scene" -t hard --vary technique.pcf=1,5 --vary 'lights.0.size=[0.5,0.5],[1.5,1.5]'
      --reference-set technique.samples=4 --repeat 1 -o sw)

"$PENUMBRA" "${args[@]}" 2>log.txt || { cat log.txt; fail "sweep failed"; }
grep -q "4 runs (4 rendered, 0 reused, 0 failed), 2 references (2 rendered)" log.txt ||
    { cat log.txt; fail "sweep summary"; }
[ "$(ls sw/cache/reference-*.exr | wc -l)" -eq 2 ] || fail "one reference per light size expected"
[ "$(tail -n +2 sw/sweep.csv | wc -l)" -eq 4 ] || fail "sweep.csv rows"
head -1 sw/sweep.csv | grep -q "^id,technique,technique.pcf,lights.0.size,total_ms" || fail "csv header"
python3 - sw/sweep.json <<'PY'
import json, os, sys
s = json.load(open(sys.argv[1]))
assert s["schema"] == "penumbra-sweep" and s["size"] == [64, 48], s["size"]
assert [a["key"] for a in s["varied"]] == ["technique.pcf", "lights.0.size"]
base = os.path.dirname(sys.argv[1])
for r in s["runs"]:
    for f in ("exr", "preview", "heatmap", "reference"):
        assert os.path.exists(os.path.join(base, r[f])), r[f]
    m = r["metrics"]
    assert 0 <= m["mae"] <= m["max"] <= 1 and m["shadow_mae"] > 0, m
    assert r["time_ms"]["total"] > 0 and "shadow_maps" in r["time_ms"]["passes"], r["time_ms"]
# A larger light makes hard shadows worse against the soft reference.
by = {(r["values"]["technique.pcf"], tuple(r["values"]["lights.0.size"])): r["metrics"]["shadow_mae"] for r in s["runs"]}
assert by[(1, (1.5, 1.5))] > by[(1, (0.5, 0.5))], by
PY
[ -f sw/index.html ] && [ -f sw/plots/error-vs-time.png ] || fail "report missing"

# Resume: nothing renders again.
"$PENUMBRA" "${args[@]}" --no-report 2>log.txt
grep -q "4 runs (0 rendered, 4 reused, 0 failed), 2 references (0 rendered)" log.txt ||
    { cat log.txt; fail "resume rendered again"; }

# The same sweep as 2 parallel jobs (GNU parallel, the engine of scripts/sequence): same images.
"$PENUMBRA" sweep "$scene" -t hard --vary technique.pcf=1,5 --vary 'lights.0.size=[0.5,0.5],[1.5,1.5]' \
    --reference-set technique.samples=4 --repeat 1 -o sw2 --no-report -j 2 2>log.txt
grep -q "4 runs (4 rendered, 0 reused, 0 failed)" log.txt || { cat log.txt; fail "parallel sweep"; }
for f in sw/runs/run-*.exr; do cmp "$f" "sw2/runs/$(basename "$f")" || fail "$f differs in parallel"; done

# Bad input: exit 2, nothing created.
expect_exit 2 "--vary technique.pcf=1:5:0" -- "$PENUMBRA" sweep "$scene" --vary technique.pcf=1:5:0 -o bad
expect_exit 2 "technique.pcf" -- "$PENUMBRA" sweep "$scene" -t hard --vary technique.pcf=1,99 -o bad
expect_exit 2 "nothing to vary" -- "$PENUMBRA" sweep "$scene" -o bad
expect_exit 2 "missing -o" -- "$PENUMBRA" sweep "$scene" --vary technique.pcf=1
expect_exit 2 "bogus" -- "$PENUMBRA" sweep "$scene" -t hard --vary technique.bogus=1 -o bad
[ ! -e bad ] || fail "bad input created the output folder"
echo "sweep ok"
