# penumbra sweep end to end: the cartesian product, one cached reference per image-changing
# setting (in a cache shared by sweeps: a second sweep renders none), CSV/JSON/images/report,
# the timing spread, resuming without rendering again, and bad input refused before anything
# renders.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
scene="$DATA/small.json"
args=(sweep "$scene" -t hard --vary technique.pcf=1,5 --vary 'lights.0.size=[0.5,0.5],[1.5,1.5]'
      --reference-set technique.samples=4 --repeat 1 -o sw)

"$PENUMBRA" "${args[@]}" 2>log.txt || { cat log.txt; fail "sweep failed"; }
grep -q "4 runs (4 rendered, 0 reused, 0 failed), 2 references (2 rendered)" log.txt ||
    { cat log.txt; fail "sweep summary"; }
cache="$XDG_CACHE_HOME/penumbra/references"  # the shared cache (lib.sh: one per test)
[ "$(ls "$cache"/reference-*.exr | wc -l)" -eq 2 ] || fail "one reference per light size expected"
[ ! -e sw/cache ] || fail "a sweep with the shared cache made its own DIR/cache"
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
    t = r["time_ms"]
    assert t["total"] > 0 and "shadow_maps" in t["passes"], t
    assert t["total_min"] == t["total"] == t["total_max"], t  # --repeat 1: one figure
    assert r["reference"].startswith(os.environ["XDG_CACHE_HOME"] + "/"), r["reference"]
    assert r["heatmap_scale"] == 0.25
    png = open(os.path.join(base, r["heatmap"]), "rb").read(24)  # IHDR: width, height
    w, h = int.from_bytes(png[16:20], "big"), int.from_bytes(png[20:24], "big")
    assert (w, h) == (64, 48 + 2 + 6), (w, h)  # the picture, 2 dark rows, the colour bar
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
grep -q "4 runs (4 rendered, 0 reused, 0 failed), 2 references (0 rendered)" log.txt ||
    { cat log.txt; fail "parallel sweep (its references are the first sweep's, cached)"; }
for f in sw/runs/run-*.exr; do cmp "$f" "sw2/runs/$(basename "$f")" || fail "$f differs in parallel"; done

# Timing spread over --repeat: min <= median <= max, in sweep.json and sweep.csv; a second
# sweep of the scene into another folder takes its reference from the shared cache.
"$PENUMBRA" sweep "$scene" -t hard --vary technique.pcf=1 --vary 'lights.0.size=[0.5,0.5]' \
    --reference-set technique.samples=4 --repeat 3 -o sw3 --no-report 2>log.txt
grep -q "1 runs (1 rendered, 0 reused, 0 failed), 1 references (0 rendered)" log.txt ||
    { cat log.txt; fail "a second sweep of the scene rendered a reference again"; }
head -1 sw3/sweep.csv | grep -q ",total_ms,total_ms_min,total_ms_max," || fail "csv spread columns"
python3 - sw3/sweep.json sw3/sweep.csv <<'PY'
import csv, json, sys
t = json.load(open(sys.argv[1]))["runs"][0]["time_ms"]
assert 0 < t["total_min"] <= t["total"] <= t["total_max"], t
row = next(csv.DictReader(open(sys.argv[2])))
assert float(row["total_ms_min"]) == t["total_min"] and float(row["total_ms_max"]) == t["total_max"]
PY

# --cache none: the sweep's own DIR/cache, recorded relative to DIR; --cache DIR: there.
one=(sweep "$scene" -t hard --vary technique.pcf=1 --vary 'lights.0.size=[0.5,0.5]'
     --reference-set technique.samples=4 --repeat 1 --no-report)
"$PENUMBRA" "${one[@]}" -o sw4 --cache none 2>log.txt
grep -q "1 references (1 rendered)" log.txt || { cat log.txt; fail "--cache none reused"; }
ls sw4/cache/reference-*.exr >/dev/null || fail "--cache none: no DIR/cache"
grep -q '"reference": "cache/reference-' sw4/sweep.json || fail "--cache none: reference path"
# Two sweeps at once into one new cache: both finish, one readable reference, no temporaries.
"$PENUMBRA" "${one[@]}" -o sw5 --cache mine 2>log5.txt & p5=$!
"$PENUMBRA" "${one[@]}" -o sw6 --cache mine 2>log6.txt & p6=$!
wait "$p5" || { cat log5.txt; fail "concurrent sweep 1"; }
wait "$p6" || { cat log6.txt; fail "concurrent sweep 2"; }
[ "$(ls -A mine)" = "$(cd mine && ls reference-*.exr)" ] ||
    { ls -A mine; fail "--cache DIR: one reference and nothing else expected"; }
ref=$(ls mine/reference-*.exr)
"$PENUMBRA" compare "$ref" "$ref" >/dev/null || fail "the cached reference does not read back"
expect_exit 2 "--cache: empty" -- "$PENUMBRA" "${one[@]}" -o bad --cache ''
touch a-file
expect_exit 2 "^penumbra: --cache: a-file/sub: cannot create folder" -- \
    "$PENUMBRA" "${one[@]}" -o bad --cache a-file/sub

# A varied technique name acts as -t: the scene's technique block (default.json: reference with
# samples 8) is kept for the technique it names and dropped for another (hard has no samples).
"$PENUMBRA" sweep "$PENUMBRA_SOURCE_DIR/scenes/default.json" --vary technique.name=hard,reference \
    --size 64x48 --reference-set technique.samples=4 --repeat 1 --no-report -o by-name \
    2>log.txt || { cat log.txt; fail "a sweep over technique.name"; }
python3 - by-name/sweep.json <<'PY'
import json, sys
runs = json.load(open(sys.argv[1]))["runs"]
assert [r["technique"] for r in runs] == ["hard", "reference"], runs
assert runs[1]["metrics"]["mae"] < runs[0]["metrics"]["mae"], runs
PY

# Bad input: exit 2, nothing created.
expect_exit 2 "--vary technique.pcf=1:5:0" -- "$PENUMBRA" sweep "$scene" --vary technique.pcf=1:5:0 -o bad
expect_exit 2 "technique.pcf" -- "$PENUMBRA" sweep "$scene" -t hard --vary technique.pcf=1,99 -o bad
expect_exit 2 "nothing to vary" -- "$PENUMBRA" sweep "$scene" -o bad
expect_exit 2 "missing -o" -- "$PENUMBRA" sweep "$scene" --vary technique.pcf=1
expect_exit 2 "bogus" -- "$PENUMBRA" sweep "$scene" -t hard --vary technique.bogus=1 -o bad
[ ! -e bad ] || fail "bad input created the output folder"
echo "sweep ok"
