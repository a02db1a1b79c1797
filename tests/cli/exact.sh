# `exact` end to end: renders with the ray caster, reports its rays and threads in the timing
# JSON, refuses out-of-range parameters naming them, and is the sweep's default truth.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
"$PENUMBRA" render "$PENUMBRA_SOURCE_DIR/scenes/default.json" -t exact --size 64x48 \
    -D technique.samples=4 -D technique.threads=2 -o e.exr --timings e.json --quiet
python3 - <<'PY'
import json
t = json.load(open("e.json"))
s = t["stats"]
assert t["technique"] == "exact", t["technique"]
assert s["threads"] == 2, s
# Every covered pixel casts 4 x 4 rays; the default scene covers most of a 64 x 48 image.
assert 16 * 1000 < s["rays_cast"] <= 16 * 64 * 48, s
assert s["rays_per_second"] > 0 and s["triangles"] > 1000, s
names = [p["name"] for p in t["passes"]]
assert {"exact_setup", "exact_rays", "exact_upload", "shade"} <= set(names), names
PY
expect_exit 2 "technique.samples" -- "$PENUMBRA" render "$PENUMBRA_SOURCE_DIR/scenes/default.json" \
    -t exact -D technique.samples=65 -o bad.exr
[ ! -e bad.exr ] || fail "a refused render wrote its EXR"
"$PENUMBRA" sweep --help | grep -q "default: exact" || fail "sweep's default truth is exact"
echo "exact ok"
