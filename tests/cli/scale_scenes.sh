# scripts/scale-scenes: copies of a scene with every length times S, or moved far from the
# origin, render the visibility of the original (`hard` is exact to the float: one map, no
# sampling); scenes it cannot scale and bad arguments are refused with one line naming the
# file or flag.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
gen="$PENUMBRA_SOURCE_DIR/scripts/scale-scenes"

scene="$PENUMBRA_SOURCE_DIR/scenes/conformance/box_floating.json"
paths=$("$gen" --scale 0.01,1,30 --out a "$scene")
[ "$paths" = "a/box_floating_s0.01.json,a/box_floating_s1.json,a/box_floating_s30.json" ] ||
    fail "printed paths: $paths"
for s in 0.01 1 30; do
    "$PENUMBRA" render "a/box_floating_s$s.json" -t hard --size 64x48 -o "s$s.exr" --quiet ||
        fail "box_floating_s$s.json"
done
for s in 0.01 30; do
    "$PENUMBRA" compare s1.exr "s$s.exr" --channels visibility --fail 1e-6 >/dev/null ||
        fail "box_floating at $s does not render the visibility of 1"
done
# Moved 1000 m from the origin: the same visibility (`hard`: one map, relative biases).
"$gen" --scale 1 --offset 1000,0,-700 --out a "$scene" >/dev/null
moved=a/box_floating_s1_o1000_0_-700.json
grep -q '"translate": \[' "$moved" || fail "the moved copy has no translation"
"$PENUMBRA" render "$moved" -t hard --size 64x48 -o moved.exr --quiet || fail "$moved"
"$PENUMBRA" compare s1.exr moved.exr --channels visibility --fail 1e-6 >/dev/null ||
    fail "box_floating 1000 m away does not render the visibility at the origin"
# A glTF object's path becomes absolute, so the copy renders from any folder.
"$gen" --scale 2 --out b "$PENUMBRA_SOURCE_DIR/scenes/conformance/duck_resting.json" >/dev/null
grep -q "\"gltf\": \"/" b/duck_resting_s2.json || fail "the duck's path stayed relative"
"$PENUMBRA" render b/duck_resting_s2.json -t hard --size 32x24 -o duck.exr --quiet ||
    fail "duck_resting_s2.json"

walk="$PENUMBRA_SOURCE_DIR/scenes/walk.json"
expect_exit 1 "walk.json: animation" -- "$gen" --scale 2 --out c "$walk"
expect_exit 1 "nope.json: No such file" -- "$gen" --scale 2 --out c nope.json
expect_exit 2 "--scale: 0 is outside" -- "$gen" --scale 0 --out c "$scene"
expect_exit 2 "--scale: expected numbers" -- "$gen" --scale x --out c "$scene"
expect_exit 2 "--offset: expected 3 numbers" -- "$gen" --scale 1 --offset 1,2 --out c "$scene"
expect_exit 2 "--out" -- "$gen" --scale 2 "$scene"
[ ! -e c ] || fail "a refused run created its folder"
echo "scale_scenes ok"
