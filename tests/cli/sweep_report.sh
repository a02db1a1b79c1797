# scripts/sweep-report on a synthetic sweep folder (no renders): the plots are written, and
# index.html, opened from disk in headless Chromium, loads every image with a clean console.
# The last report stays in $PENUMBRA_TEST_TMP/sweep_report.last (screenshot.png included).
# Also: fronts per scene combination and technique (report.json), --pareto-metric, a sweep over
# technique.name (synthetic, and one real 32x24 sweep), a report over several folders, bad arguments.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
report="$PENUMBRA_SOURCE_DIR/scripts/sweep-report"
py=/usr/bin/python3
chromium=/usr/bin/chromium

[ -x "$report" ] || fail "$report is missing or not executable"
"$py" -c 'import matplotlib' 2>/dev/null \
    || fail "Debian's python3-matplotlib is not installed for $py (run scripts/setup)"
[ -x "$chromium" ] \
    || fail "headless Chromium ($chromium) is not installed: this test needs Debian's chromium (run scripts/setup)"

# make_sweep DIR KIND: a synthetic sweep folder (no renders).
#   main: 2 techniques (two sweeps' worth, as one) x pcf {1,3,5} x light size {[0.5,0.5],[1,1]} x
#         bias {1e-3,1e-2} (log), names that need escaping, one run whose shadow_mae is null,
#         time_ms.total_min/total_max on every run but run-0003 (its bars are left out).
#   names: technique.name {hard,pcss} x light size x pcf {1,3}: a sweep comparing techniques.
#   small: as main but 16x12 and no bias (another scene group, other varied keys).
make_sweep() {
"$py" - "$1" "$2" <<'EOF'
import json, os, struct, sys, zlib, itertools

def png(path, w, h, pixel):
    rows = b"".join(b"\0" + b"".join(bytes(pixel(x, y)) for x in range(w)) for y in range(h))
    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))

d, kind = sys.argv[1], sys.argv[2]
os.makedirs(os.path.join(d, "runs"))
os.makedirs(os.path.join(d, "cache"))
sizes = [[0.5, 0.5], [1, 1]]
if kind == "names":
    varied = [{"key": "technique.name", "values": ["hard", "pcss"], "scale": "linear"},
              {"key": "lights.0.size", "values": sizes, "scale": "linear"},
              {"key": "technique.pcf", "values": [1, 3], "scale": "linear"}]
    points = [(v[0], v[2], v[1], 0.001) for v in itertools.product(*[a["values"] for a in varied])]
else:
    varied = [{"key": "technique.pcf", "values": [1, 3, 5], "scale": "linear"},
              {"key": "lights.0.size", "values": sizes, "scale": "linear"}]
    if kind == "main":
        varied.append({"key": "technique.bias", "values": [0.001, 0.01], "scale": "log"})
    points = list(itertools.product(["hard", "pcss"], [1, 3, 5], sizes,
                                    [0.001, 0.01] if kind == "main" else [0.001]))
keys = [v["key"] for v in varied]
runs = []
for n, (tech, pcf, size, bias) in enumerate(points, 1):
    rid = f"run-{n:04d}"
    t = (30 if tech == "hard" else 55) + 6 * pcf + 10 * size[0] + 1000 * bias
    err = (0.08 if tech == "hard" else 0.03) / pcf ** 0.5 * size[0] + 2 * bias
    all_values = {"technique.name": tech, "technique.pcf": pcf, "lights.0.size": size,
                  "technique.bias": bias}
    ref = f"cache/reference-{int(size[0] * 10)}.exr"  # one reference per light size
    run = {"id": rid, "values": {k: all_values[k] for k in keys}, "technique": tech,
           "exr": f"runs/{rid}.exr", "preview": f"runs/{rid}.png", "heatmap": f"runs/{rid}.error.png",
           "reference": ref,
           "time_ms": {"total": round(t, 2), "passes": {"gbuffer": 10.0, "shadow_maps": 2.5,
                                                         "shadow_test": round(t - 30, 2), "shade": 17.5}},
           "metrics": {"mae": round(err / 4, 5), "rmse": round(err / 2, 5), "max": 0.9,
                       "p99": round(err * 3, 5), "shadow_mae": round(err, 5),
                       "shadow_pixels": 1234, "fail_fraction": round(err, 4)},
           "stats": {"maps_rendered": 1, "blocker_search": tech == "pcss"}}
    if kind == "main" and n != 3:
        run["time_ms"]["total_min"] = round(t * 0.9, 2)
        run["time_ms"]["total_max"] = round(t * 1.2, 2)
    if n == 5:
        run["metrics"]["shadow_mae"] = None
        run["metrics"]["shadow_pixels"] = 0
    open(os.path.join(d, run["exr"]), "wb").write(b"not a real exr")
    open(os.path.join(d, ref), "wb").write(b"not a real exr")
    png(os.path.join(d, run["preview"]), 32, 24, lambda x, y: (8 * x, 10 * y, 40 * pcf))
    png(os.path.join(d, run["heatmap"]), 32, 24, lambda x, y: (min(255, int(3000 * err * x / 32)), 0, 0))
    runs.append(run)
scene = "scenes/<b>odd & \"quoted\"</b>.json" if kind == "main" else "scenes/plain.json"
doc = {"schema": "penumbra-sweep", "schema_version": 1, "scene": scene, "technique": "hard",
       "size": [16, 12] if kind == "small" else [32, 24], "frame": 0, "varied": varied,
       "reference": {"technique": "reference", "overrides": {"technique.samples": 32}},
       "runs": runs}
json.dump(doc, open(os.path.join(d, "sweep.json"), "w"), indent=1)
open(os.path.join(d, "sweep.csv"), "w").write("id\n" + "\n".join(r["id"] for r in runs) + "\n")
EOF
}

dir="$WORK/sweep"
make_sweep "$dir" main

"$report" "$dir" >"$WORK/report.out" 2>&1 || { cat "$WORK/report.out" >&2; fail "sweep-report failed"; }
# No warnings on a complete folder (a missing preview or heatmap would be one).
if grep -q warning "$WORK/report.out"; then cat "$WORK/report.out" >&2; fail "sweep-report warned"; fi

# Plots: error against time, and every metric against every varied parameter, as PNG and SVG.
# check_plots DIR NAME...: each plot exists as PNG, SVG and PDF, and the page links all three.
check_plots() {
    local d=$1 name f
    shift
    for name in "$@"; do
        f="$d/plots/$name"
        [ -s "$f.png" ] || fail "plot $name.png missing"
        [ "$(head -c 8 "$f.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || fail "$name.png is not a PNG"
        grep -q '<svg' "$f.svg" || fail "plot $name.svg missing or not SVG"
        [ "$(head -c 4 "$f.pdf")" = "%PDF" ] || fail "plot $name.pdf missing or not PDF"
        for x in png svg pdf; do
            grep -q "href=\"plots/$name.$x\"" "$d/index.html" || fail "index.html does not link $name.$x"
        done
    done
}
plots=(error-vs-time heatmap)
for m in mae rmse p99 shadow_mae time_total; do
    for p in technique_pcf lights_0_size technique_bias; do plots+=("$m-vs-$p"); done
done
check_plots "$dir" "${plots[@]}"

# The page: relative links only, text escaped, every thumbnail and plot referenced.
html="$dir/index.html"
[ -s "$html" ] || fail "index.html missing"
if grep -Eq '(src|href)="(https?:|file:|/)' "$html"; then fail "index.html has a non-relative link"; fi
if grep -q '<b>odd' "$html"; then fail "index.html does not escape the scene name"; fi
grep -q '&lt;b&gt;odd &amp; &quot;quoted&quot;' "$html" || fail "escaped scene name not in index.html"
grep -q 'run-0024' "$html" || fail "run-0024 not in the table"
grep -q '\[0.5, 0.5\]' "$html" || fail "array value not shown as [0.5, 0.5]"
grep -q 'technique.samples' "$html" || fail "reference settings not shown"
nimg=$(grep -o '<img ' "$html" | wc -l)
[ "$nimg" -eq $((${#plots[@]} + 2 * 24)) ] || fail "expected $((${#plots[@]} + 48)) images in index.html, found $nimg"

# open_page HTML NAME: loads HTML from disk in headless Chromium; writes NAME.dom (the DOM after
# load, carrying the page's own image check: body data-images-ok="LOADED/TOTAL") and NAME.log
# (stderr, where console messages show as CONSOLE lines).
open_page() {
    local profile
    profile=$(mktemp -d "$WORK/chromium.XXXXXX")
    local rc=0
    timeout 90 "$chromium" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
        --disable-background-networking --disable-component-update --disable-sync \
        --user-data-dir="$profile" --enable-logging=stderr --v=0 --virtual-time-budget=10000 \
        --dump-dom "file://$1" >"$WORK/$2.dom" 2>"$WORK/$2.log" || rc=$?
    if [ "$rc" -ne 0 ] || ! grep -q '</html>' "$WORK/$2.dom"; then
        tail -20 "$WORK/$2.log" >&2
        fail "headless Chromium could not open $1 (exit $rc): see the log above"
    fi
}
images_ok() { grep -o 'data-images-ok="[0-9]*/[0-9]*"' "$WORK/$1.dom" | head -1 | sed 's/.*="\(.*\)"/\1/'; }

open_page "$html" page
got=$(images_ok page)
[ -n "$got" ] || fail "the page's image check did not run (no data-images-ok in the DOM)"
[ "$got" = "$nimg/$nimg" ] || { grep CONSOLE "$WORK/page.log" >&2 || true; fail "images loaded: $got, want $nimg/$nimg"; }
if grep -q 'CONSOLE' "$WORK/page.log"; then
    grep 'CONSOLE' "$WORK/page.log" >&2
    fail "the browser console is not clean"
fi

# The check itself catches a broken image: the same page with one preview gone.
broken="$WORK/broken"
cp -r "$dir" "$broken"
rm "$broken/runs/run-0007.png"
open_page "$broken/index.html" broken
[ "$(images_ok broken)" = "$((nimg - 1))/$nimg" ] || fail "a missing image went unnoticed: $(images_ok broken)"
grep -q 'CONSOLE.*run-0007.png' "$WORK/broken.log" || fail "a missing image left no console error"

# check_fronts DIR [METRIC]: report.json's fronts, checked against the sweep.json files: every
# run on exactly one front; a front's runs share one scene group, technique and value of each
# varied key not starting with "technique." (never two light sizes); its front is exactly the
# runs no other run of the front beats in both time and METRIC (shadow_mae: MAE where null).
# Labels stay inside the plot and never overlap, and every point's pixel in the PNG is drawn.
check_fronts() {
"$py" - "$1" "${2:-shadow_mae}" <<'EOF' || fail "report.json of $1 is wrong (above)"
import json, os, sys, matplotlib.image
d, metric = sys.argv[1], sys.argv[2]
rep = json.load(open(os.path.join(d, "report.json")))
assert rep["pareto_metric"] == metric, rep["pareto_metric"]
runs = {}
many = len(rep["sweeps"]) > 1
for s in rep["sweeps"]:
    doc = json.load(open(os.path.join(s["folder"], "sweep.json")))
    for r in doc["runs"]:
        runs[f"{s['label']}/{r['id']}" if many else r["id"]] = (s, doc, r)
seen = []
for f in rep["fronts"]:
    members = [runs[u] for u in f["runs"]]
    seen += f["runs"]
    assert len({m[0]["scene_group"] for m in members}) == 1, f
    assert {m[2]["technique"] for m in members} == {f["technique"]}, f
    for key in {k for m in members for k in m[2]["values"]}:
        if not key.startswith("technique."):
            vals = {json.dumps(m[2]["values"].get(key)) for m in members}
            assert len(vals) == 1, f"front {f['id']} mixes {key}: {vals}"
    def err(r):
        v = r["metrics"].get(metric)
        return r["metrics"]["mae"] if v is None and metric == "shadow_mae" else v
    pts = {u: (runs[u][2]["time_ms"]["total"], err(runs[u][2])) for u in f["runs"]}
    best = [u for u, (t, e) in pts.items()
            if not any((t2 < t and e2 <= e) or (t2 <= t and e2 < e) for t2, e2 in pts.values())]
    want = sorted({pts[u] for u in best})
    got = [pts[u] for u in f["front"]]
    assert got == want, f"front {f['id']}: {f['front']} {got}, want {want}"
assert sorted(seen) == sorted(runs), "not every run is on exactly one front"
for p in rep["plots"]:
    img = matplotlib.image.imread(os.path.join(d, "plots", p["name"] + ".png"))
    assert img.shape[:2] == (p["height"], p["width"]), (img.shape, p["width"], p["height"])
    boxes = [l["box"] for l in p["labels"]]
    for i, (x0, y0, x1, y1) in enumerate(boxes):
        assert 0 <= x0 < x1 <= p["width"] and 0 <= y0 < y1 <= p["height"], boxes[i]
        for bx0, by0, bx1, by1 in boxes[:i]:
            assert x1 <= bx0 or bx1 <= x0 or y1 <= by0 or by1 <= y0, f"labels overlap: {boxes[i]}"
    for pt in p["points"]:
        assert img[int(pt["y"]), int(pt["x"]), :3].min() < 0.9, f"no point drawn at {pt}"
    assert len(p["labels"]) + len(p["unlabelled"]) <= len(p["points"])
EOF
}
check_fronts "$dir"
"$py" -c 'import json, sys; r = json.load(open(sys.argv[1])); print(len(r["fronts"]), len(r["plots"][0]["labels"]))' \
    "$dir/report.json" >"$WORK/counts"
# 2 techniques x 2 light sizes; most points labelled.
read -r nfronts nlabels <"$WORK/counts"
[ "$nfronts" = 4 ] || fail "expected 4 fronts (technique x light size), got $nfronts"
[ "$nlabels" -ge 16 ] || fail "only $nlabels of 24 points labelled"
# Every point is a tooltip (an area of the plot's image map) linking to its run's row.
[ "$(grep -o '<area shape="circle"' "$html" | wc -l)" = 24 ] || fail "expected 24 point tooltips"
grep -q '<area [^>]*href="#r7" title="run-0007 · hard · technique.pcf=3, lights.0.size=\[1, 1\], technique.bias=0.001 · 59 ms · shadow_mae 0.04819 · front F2 (on it)"' "$html" \
    || fail "run-0007's tooltip is missing or does not name its values"
# Time bars: the min-max column where the run has them, "–" where it has not (run-0003).
grep -q '>37.8–50.4<' "$html" || fail "run-0001's min–max time (37.8–50.4) not in the table"
grep -q 'id="r3"[^>]*>.*<td class="num" data-sort="[^"]*">47</td><td>–</td>' "$html" \
    || fail "run-0003 (no total_min/total_max) should show – for its range"

# --pareto-metric: max is 0.9 everywhere, so each front is its fastest run alone.
cp -r "$dir" "$WORK/bymax"
"$report" "$WORK/bymax" --pareto-metric max >/dev/null 2>"$WORK/bymax.err" || { cat "$WORK/bymax.err" >&2; fail "--pareto-metric max failed"; }
check_fronts "$WORK/bymax" max
"$py" -c 'import json, sys; r = json.load(open(sys.argv[1])); assert all(len(f["front"]) == 1 for f in r["fronts"]), r["fronts"]' \
    "$WORK/bymax/report.json" || fail "--pareto-metric max did not change the fronts"
grep -q 'Pareto metric: max' "$WORK/bymax/index.html" || fail "the page does not name the Pareto metric"

# A sweep comparing techniques (--vary technique.name): one front per technique and light size,
# and the page names each run's technique.
names="$WORK/names"
make_sweep "$names" names
"$report" "$names" >/dev/null 2>"$WORK/names.err" || { cat "$WORK/names.err" >&2; fail "sweep-report on a technique.name sweep failed"; }
check_fronts "$names"
grep -q 'varied (technique.name): hard, pcss' "$names/index.html" || fail "the page does not say technique.name varies"
[ "$(grep -Eo '<td>run-000[1-4]</td><td>hard</td>|<td>run-000[5-8]</td><td>pcss</td>' "$names/index.html" | wc -l)" = 8 ] \
    || fail "the runs table does not name each run's technique"
check_plots "$names" error-vs-time heatmap mae-vs-technique_name

# The same end to end: a real sweep over technique.name, reported by the sweep itself.
real="$WORK/real"
"$PENUMBRA" sweep "$PENUMBRA_SOURCE_DIR/scenes/default.json" -t hard --vary technique.name=hard,reference \
    --size 32x24 --warmup 0 --repeat 1 -o "$real" >"$WORK/real.out" 2>&1 \
    || { tail -5 "$WORK/real.out" >&2; fail "penumbra sweep --vary technique.name=hard,reference failed"; }
check_fronts "$real"
"$py" -c 'import json, sys; r = json.load(open(sys.argv[1])); assert sorted(f["technique"] for f in r["fronts"]) == ["hard", "reference"], r["fronts"]' \
    "$real/report.json" || fail "a technique.name sweep should give one front per technique"
grep -q '<td>reference</td>' "$real/index.html" || fail "the page does not name the reference runs' technique"

# Several folders: the main sweep, the technique sweep (same scene group as neither: other
# scene) and a smaller one (another size: another group); keys not varied show "-".
small="$WORK/small"
make_sweep "$small" small
merged="$WORK/merged dir"
"$report" "$dir" "$names" "$small" -o "$merged" >/dev/null 2>"$WORK/merged.err" \
    || { cat "$WORK/merged.err" >&2; fail "sweep-report over three folders failed"; }
[ -s "$WORK/merged.err" ] && { cat "$WORK/merged.err" >&2; fail "sweep-report over three folders warned"; }
check_fronts "$merged"
"$py" -c 'import json, sys; r = json.load(open(sys.argv[1])); assert len(r["scene_groups"]) == 3 and len(r["plots"]) == 3, r["scene_groups"]' \
    "$merged/report.json" || fail "three folders of three scenes or sizes should be three scene groups"
check_plots "$merged" error-vs-time-g1 error-vs-time-g2 error-vs-time-g3 heatmap mae-vs-technique_name
grep -q '3 scene groups' "$merged/index.html" || fail "the merged page does not say its sweeps are kept apart"
grep -q '<td>small/run-0001</td>' "$merged/index.html" || fail "merged run ids are not prefixed with their folder"
grep -Eq '<td>small</td><td>hard</td><td[^>]*>1</td><td>\[0.5, 0.5\]</td><td>-</td><td>-</td>' "$merged/index.html" \
    || fail "a key the folder did not vary is not shown as -"
if grep -Eq '(src|href)="(https?:|file:|/)' "$merged/index.html"; then fail "merged index.html has a non-relative link"; fi
nmerged=$(grep -o '<img ' "$merged/index.html" | wc -l)
open_page "$merged/index.html" merged
[ "$(images_ok merged)" = "$nmerged/$nmerged" ] || fail "merged page: images loaded $(images_ok merged), want $nmerged/$nmerged"

# Bad arguments: one line naming the argument, exit 2, nothing written.
expect_exit 2 '^sweep-report: no sweep folder given' -- "$report"
expect_exit 2 '^sweep-report: -o OUT: needed with several' -- "$report" "$dir" "$names"
expect_exit 2 "^sweep-report: unknown option '--bogus'" -- "$report" --bogus "$dir"
expect_exit 2 '^sweep-report: -o needs a value' -- "$report" "$dir" -o
expect_exit 2 '^sweep-report: --pareto-metric needs a value' -- "$report" "$dir" --pareto-metric
expect_exit 2 "^sweep-report: --pareto-metric: unknown metric 'nope' \(one of: mae, rmse, max, p99, shadow_mae, fail_fraction\)" \
    -- "$report" "$dir" "$names" -o "$WORK/never" --pareto-metric nope
expect_exit 2 "^sweep-report: $WORK/nothing: not a folder" -- "$report" "$WORK/nothing"
expect_exit 2 "given twice" -- "$report" "$dir" "$dir/" -o "$WORK/never"
mkdir "$WORK/broken-json" && printf '{"schema": ' >"$WORK/broken-json/sweep.json"
expect_exit 2 "^sweep-report: $WORK/broken-json/sweep.json: not valid JSON" -- "$report" "$dir" "$WORK/broken-json" -o "$WORK/never"
[ ! -e "$WORK/never" ] || fail "a refused report wrote $WORK/never"
for f in "$WORK/stderr"; do [ "$(wc -l <"$f")" = 1 ] || fail "more than one line for a bad argument"; done
# A sweep folder named like an option is a folder (penumbra sweep -o -x passes it as is).
cp -r "$names" "$WORK/-dash"
(cd "$WORK" && "$report" -dash >/dev/null 2>&1) || fail "a folder named -dash was not reported"
[ -s "$WORK/-dash/report.json" ] || fail "no report.json in -dash"
"$report" --help >"$WORK/help" || fail "--help failed"
grep -q 'pareto-metric' "$WORK/help" || fail "--help does not describe --pareto-metric"

# Screenshot, and a look that it is not blank.
profile=$(mktemp -d "$WORK/chromium.XXXXXX")
timeout 90 "$chromium" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --user-data-dir="$profile" --hide-scrollbars --window-size=1280,2000 --virtual-time-budget=10000 \
    --screenshot="$dir/screenshot.png" "file://$html" >"$WORK/shot.log" 2>&1 \
    || { tail -20 "$WORK/shot.log" >&2; fail "headless Chromium could not take a screenshot"; }
"$py" - "$dir/screenshot.png" <<'EOF' || fail "screenshot missing or blank"
import sys, matplotlib.image
img = matplotlib.image.imread(sys.argv[1])
assert img.shape[0] >= 1000 and img.shape[1] >= 1000, img.shape
assert img[..., :3].std() > 0.05, "blank"
EOF

keep="${PENUMBRA_TEST_TMP:-/tmp}/sweep_report.last"
if mkdir -p "$(dirname "$keep")" && rm -rf "$keep" && cp -r "$dir" "$keep"; then
    echo "sweep_report ok ($nimg images; report and screenshot kept in $keep)"
else
    echo "sweep_report ok ($nimg images)"
fi
