# `penumbra fit-lights`: JSON and picture of a fit on a generated map; every bad input is one
# line naming the file or flag, exit 2, and leaves no output file behind.
source "$(dirname "$0")/lib.sh"
command -v oiiotool >/dev/null || fail "oiiotool (openimageio-tools) is needed to make a map"
oiiotool --pattern constant:color=0.1,0.15,0.2 128x64 3 \
    --box:color=60,50,40:fill=1 70,20,78,26 -d float -o "$WORK/sky.exr"

"$PENUMBRA" fit-lights --help | grep -q "usage: penumbra fit-lights" || fail "--help"
"$PENUMBRA" fit-lights "$WORK/sky.exr" --max 3 -o "$WORK/lights.json" --png "$WORK/fit.png" \
    2>"$WORK/stderr" || fail "fit-lights failed: $(cat "$WORK/stderr")"
grep -q "3 lights" "$WORK/stderr" || fail "summary line: $(cat "$WORK/stderr")"
python3 - "$WORK/lights.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
assert d["schema"] == "penumbra-lights" and len(d["lights"]) == 3, d
first = d["lights"][0]
# The box is the brightest part: the first light holds most of the map's energy.
assert first["energy_share"] > 0.5, first
assert abs(sum(l["energy_share"] for l in d["lights"]) - d["captured_share"]) < 1e-9
for l in d["lights"]:
    assert {"direction", "extent_deg", "radiance", "energy_share", "face"} <= set(l), l
PY
head -c 8 "$WORK/fit.png" | od -An -c | grep -q "P   N   G" || fail "--png wrote no PNG"
# Standard output without -o.
"$PENUMBRA" fit-lights "$WORK/sky.exr" --max 1 --shape square 2>/dev/null |
    python3 -c 'import json,sys; assert len(json.load(sys.stdin)["lights"]) == 1'

# Bad inputs: exit 2, the flag or file named, nothing written.
out=(-o "$WORK/bad.json" --png "$WORK/bad.png")
expect_exit 2 "missing.exr: no such file" -- "$PENUMBRA" fit-lights "$WORK/missing.exr" "${out[@]}"
expect_exit 2 "missing ENV.exr" -- "$PENUMBRA" fit-lights "${out[@]}"
expect_exit 2 "--threshold: expected a number in \(0, 1\)" -- \
    "$PENUMBRA" fit-lights "$WORK/sky.exr" --threshold 1.5 "${out[@]}"
expect_exit 2 "--threshold" -- "$PENUMBRA" fit-lights "$WORK/sky.exr" --threshold x "${out[@]}"
expect_exit 2 "--max" -- "$PENUMBRA" fit-lights "$WORK/sky.exr" --max -1 "${out[@]}"
expect_exit 2 "--shape: expected square or rect" -- \
    "$PENUMBRA" fit-lights "$WORK/sky.exr" --shape circle "${out[@]}"
expect_exit 2 "--face-size" -- "$PENUMBRA" fit-lights "$WORK/sky.exr" --face-size 2 "${out[@]}"
expect_exit 2 "--residual" -- "$PENUMBRA" fit-lights "$WORK/sky.exr" --residual 1 "${out[@]}"
expect_exit 2 "--bogus" -- "$PENUMBRA" fit-lights "$WORK/sky.exr" --bogus "${out[@]}"
expect_exit 2 "not-an-image.txt: expected an .exr or .hdr" -- \
    "$PENUMBRA" fit-lights "$WORK/not-an-image.txt" "${out[@]}"
[ ! -e "$WORK/bad.json" ] && [ ! -e "$WORK/bad.png" ] || fail "a failed run left output"
[ -z "$(ls -A "$WORK" | grep '\.tmp$' || true)" ] || fail "temporary files left behind"
# A scene with an environment: css fits its lights, or reads them from env_lights_file.
scene="$PENUMBRA_SOURCE_DIR/tests/data/gl/environment.json"
"$PENUMBRA" fit-lights "$PENUMBRA_SOURCE_DIR/tests/data/gl/sky_sun.exr" --max 4 --shape square \
    -o "$WORK/sky_lights.json" 2>/dev/null
"$PENUMBRA" render "$scene" --size 64x48 -D "technique.env_lights_file=\"$WORK/sky_lights.json\"" \
    -o "$WORK/env.exr" --quiet || fail "render with env_lights_file"
python3 -c 'import json,sys; s=json.load(open(sys.argv[1]))["stats"]; assert s["lights_fitted"] == 4, s' \
    "$WORK/env.json"
expect_exit 2 "technique.env_lights_file: .*missing.json" -- "$PENUMBRA" render "$scene" \
    --size 64x48 -D technique.env_lights_file=missing.json -o "$WORK/bad.exr"
[ ! -e "$WORK/bad.exr" ] || fail "a refused render left an EXR"
echo "fit-lights ok"
