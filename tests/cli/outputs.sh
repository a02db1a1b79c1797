# Frame specs and output patterns, --skip-existing, the timing JSON and the EXR channels.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
scene="$DATA/small.json"

# The scene's animation range (1-3) with a # pattern; timing JSON beside each EXR.
"$PENUMBRA" render "$scene" -o "seq/a.##.exr" --quiet
for f in 01 02 03; do
    [ -f "seq/a.$f.exr" ] && [ -f "seq/a.$f.json" ] || fail "missing seq/a.$f.exr or .json"
done
# Several frames and no # in a pattern: an error before anything renders (every frame would
# have written one file); with the default pattern the timing JSON follows the EXR's numbers.
expect_exit 2 "^penumbra: --output: plain.exr: no # for the frame number" -- \
    "$PENUMBRA" render "$scene" -f 1,3 -o plain.exr --quiet
expect_exit 2 "^penumbra: --timings: t/plain.json: no # " -- \
    "$PENUMBRA" render "$scene" -f 1,3 -o "p/plain.#.exr" --timings "t/plain.json" --quiet
[ ! -e plain.0001.exr ] && [ ! -e p ] && [ ! -e t ] || fail "output after a pattern error"
# One frame, no #: the name as given; --preview writes a PNG.
"$PENUMBRA" render "$scene" -f 2 -o one.exr --preview one.png --quiet
[ -f one.exr ] && [ -f one.png ] || fail "single frame output"
head -c 8 one.png | od -An -c | grep -q "P   N   G" || fail "one.png is not a PNG"

# The timing JSON: schema, passes with clocks, statistics; --repeat gives min/median/max.
"$PENUMBRA" render "$scene" -f 2 -o rep.exr --warmup 1 --repeat 3 --quiet
python3 - rep.json <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
assert t["schema"] == "penumbra-timing" and t["schema_version"] == 1, t
assert t["technique"] == "hard" and t["frame"] == 2
assert t["params"]["map_size"] == 256
names = [p["name"] for p in t["passes"]]
assert names[0] == "gbuffer" and "shade" in names and "shadow_maps[0]" in names, names
for p in t["passes"]:
    assert p["clock"] in ("gl_timer_query", "cpu_glfinish", "cpu"), p
    if p["name"] != "readback":
        assert len(p["samples_ms"]) == 3 and p["min_ms"] <= p["median_ms"] <= p["max_ms"], p
assert t["totals"]["repeats"] == 3 and t["totals"]["warmup"] == 1
assert t["stats"]["maps_rendered"] == 1
assert t["backend"]["renderer"]
PY

# Several lights: technique passes carry @<light>, the frame's own passes do not.
"$PENUMBRA" render "$PENUMBRA_SOURCE_DIR/tests/data/gl/two_lights.json" -o two.exr --quiet
python3 - two.json <<'PY'
import json, sys
names = [p["name"] for p in json.load(open(sys.argv[1]))["passes"]]
assert names[0] == "gbuffer" and "shade" in names, names
assert "shadow_maps[0]@0" in names and "shadow_test[0]@1" in names, names
PY

# Multisampling: its passes in the timing JSON, the sample count there and in the EXR header.
for n in 2 4 8; do
    "$PENUMBRA" render "$scene" -f 2 -D image.samples=$n -o "ms$n.exr" --quiet ||
        fail "render with image.samples=$n"
done
python3 - ms4.json rep.json <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
assert t["resolution"] == {"width": 64, "height": 48, "samples": 4}, t["resolution"]
names = [p["name"] for p in t["passes"]]
assert names[:2] == ["gbuffer", "gbuffer_msaa"] and names.index("shade") + 1 == names.index("shade_msaa"), names
assert 0 < t["stats"]["msaa_pixels"] < 64 * 48 and t["stats"]["msaa_share"] < 0.5, t["stats"]
one = json.load(open(sys.argv[2]))
assert one["resolution"]["samples"] == 1 and "shade_msaa" not in [p["name"] for p in one["passes"]]
PY
if command -v oiiotool >/dev/null; then
    oiiotool --info -v ms8.exr | grep -q 'penumbra/samples: 8$' || fail "samples attribute missing or not an int"
fi

# --skip-existing renders only what is missing.
rm seq/a.02.exr
before=$(stat -c %Y seq/a.01.exr)
sleep 1
"$PENUMBRA" render "$scene" -o "seq/a.##.exr" --skip-existing --quiet
[ -f seq/a.02.exr ] || fail "--skip-existing did not render the missing frame"
[ "$(stat -c %Y seq/a.01.exr)" = "$before" ] || fail "--skip-existing re-rendered frame 1"
# With every frame present there is nothing to do: no GL context is even needed.
env __EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json PENUMBRA_OSMESA_LIBRARY=/nonexistent \
    "$PENUMBRA" render "$scene" -o "seq/a.##.exr" --skip-existing --quiet ||
    fail "--skip-existing with nothing to render should succeed without a backend"

# Channels and header attributes (oiiotool from openimageio-tools).
if command -v oiiotool >/dev/null; then
    info=$(oiiotool --info -v one.exr)
    for ch in R G B A Z P.X P.Y P.Z N.X N.Y N.Z visibility id; do
        echo "$info" | grep -q "channel list:.*\b$ch\b" || echo "$info" | grep -Eq "(^|[ ,])$ch([ ,(]|$)" ||
            fail "channel $ch missing"
    done
    echo "$info" | grep -q "penumbra/technique: \"hard\"" || fail "technique attribute missing"
fi
# Identical inputs give identical images (a render farm depends on it).
"$PENUMBRA" render "$scene" -f 2 -o again.exr --quiet
cmp one.exr again.exr || fail "two renders of the same frame differ"
echo "outputs ok"
