# Every backend renders, and they agree: EGL device, EGL surfaceless and OSMesa.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
scene="$DATA/small.json"
"$PENUMBRA" render "$scene" -f 1 --backend egl -o egl.exr --quiet
"$PENUMBRA" render "$scene" -f 1 --backend egl-surfaceless -o surfaceless.exr --quiet
grep -q '"api": "egl-surfaceless"' surfaceless.json || fail "surfaceless backend not used"
"$PENUMBRA" render "$scene" -f 1 --backend osmesa -o osmesa.exr --quiet
grep -q '"api": "egl-' egl.json || fail "egl backend not used"
grep -q '"api": "osmesa"' osmesa.json || fail "osmesa backend not used"
# Same Mesa rasteriser behind both: identical up to half-float rounding.
"$PENUMBRA" compare egl.exr osmesa.exr --fail 1e-3 >/dev/null || fail "egl and osmesa differ"
"$PENUMBRA" compare egl.exr surfaceless.exr --fail 1e-3 >/dev/null || fail "egl device and surfaceless differ"
echo "backends ok"
