# scripts/sweep-report on a synthetic sweep folder (no renders): the plots are written, and
# index.html, opened from disk in headless Chromium, loads every image with a clean console.
# The last report stays in $PENUMBRA_TEST_TMP/sweep_report.last (screenshot.png included).
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

# A small sweep: 2 techniques x pcf {1,3,5} x light size {[0.5,0.5],[1,1]} x bias {1e-3,1e-2} (log),
# with names that need escaping and one run whose shadow_mae is null.
dir="$WORK/sweep"
"$py" - "$dir" <<'EOF'
import json, os, struct, sys, zlib, itertools

def png(path, w, h, pixel):
    rows = b"".join(b"\0" + b"".join(bytes(pixel(x, y)) for x in range(w)) for y in range(h))
    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))

d = sys.argv[1]
os.makedirs(os.path.join(d, "runs"))
os.makedirs(os.path.join(d, "cache"))
open(os.path.join(d, "cache", "reference-3f2a9c.exr"), "wb").write(b"not a real exr")
varied = [{"key": "technique.pcf", "values": [1, 3, 5], "scale": "linear"},
          {"key": "lights.0.size", "values": [[0.5, 0.5], [1, 1]], "scale": "linear"},
          {"key": "technique.bias", "values": [0.001, 0.01], "scale": "log"}]
runs = []
for n, (tech, pcf, size, bias) in enumerate(itertools.product(
        ["hard", "pcss"], *[v["values"] for v in varied]), 1):
    rid = f"run-{n:04d}"
    t = (30 if tech == "hard" else 55) + 6 * pcf + 10 * size[0] + 1000 * bias
    err = (0.08 if tech == "hard" else 0.03) / pcf ** 0.5 * size[0] + 2 * bias
    run = {"id": rid, "values": {"technique.pcf": pcf, "lights.0.size": size, "technique.bias": bias},
           "technique": tech,
           "exr": f"runs/{rid}.exr", "preview": f"runs/{rid}.png", "heatmap": f"runs/{rid}.error.png",
           "reference": "cache/reference-3f2a9c.exr",
           "time_ms": {"total": round(t, 2), "passes": {"gbuffer": 10.0, "shadow_maps": 2.5,
                                                         "shadow_test": round(t - 30, 2), "shade": 17.5}},
           "metrics": {"mae": round(err / 4, 5), "rmse": round(err / 2, 5), "max": 0.9,
                       "p99": round(err * 3, 5), "shadow_mae": round(err, 5),
                       "shadow_pixels": 1234, "fail_fraction": round(err, 4)},
           "stats": {"maps_rendered": 1, "blocker_search": tech == "pcss"}}
    if n == 5:
        run["metrics"]["shadow_mae"] = None
        run["metrics"]["shadow_pixels"] = 0
    open(os.path.join(d, run["exr"]), "wb").write(b"not a real exr")
    png(os.path.join(d, run["preview"]), 32, 24, lambda x, y: (8 * x, 10 * y, 40 * pcf))
    png(os.path.join(d, run["heatmap"]), 32, 24, lambda x, y: (min(255, int(3000 * err * x / 32)), 0, 0))
    runs.append(run)
doc = {"schema": "penumbra-sweep", "schema_version": 1,
       "scene": "scenes/<b>odd & \"quoted\"</b>.json", "technique": "hard", "size": [32, 24], "frame": 0,
       "varied": varied,
       "reference": {"technique": "reference", "overrides": {"technique.samples": 32}},
       "runs": runs}
json.dump(doc, open(os.path.join(d, "sweep.json"), "w"), indent=1)
open(os.path.join(d, "sweep.csv"), "w").write("id\n" + "\n".join(r["id"] for r in runs) + "\n")
EOF

"$report" "$dir" >"$WORK/report.out" 2>&1 || { cat "$WORK/report.out" >&2; fail "sweep-report failed"; }
# No warnings on a complete folder (a missing preview or heatmap would be one).
if grep -q warning "$WORK/report.out"; then cat "$WORK/report.out" >&2; fail "sweep-report warned"; fi

# Plots: error against time, and every metric against every varied parameter, as PNG and SVG.
plots=(error-vs-time)
for m in mae rmse p99 shadow_mae time_total; do
    for p in technique_pcf lights_0_size technique_bias; do plots+=("$m-vs-$p"); done
done
for name in "${plots[@]}"; do
    f="$dir/plots/$name"
    [ -s "$f.png" ] || fail "plot $name.png missing"
    [ "$(head -c 8 "$f.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || fail "$name.png is not a PNG"
    grep -q '<svg' "$f.svg" || fail "plot $name.svg missing or not SVG"
done

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
