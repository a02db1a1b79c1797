# scripts/scale-scenes: copies of a scene with every length times S, moved far from the origin
# or turned render the visibility of the original, mirrored its mirror image (`hard`: one map,
# no sampling); scenes it cannot carry and bad arguments are refused with one line naming the
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
# Renders copy $1 with `hard` into $2 and fails with $3 unless its visibility is s1.exr's
# (within $4; $2 flopped first when $5 is "flop").
same_as_original() {
    "$PENUMBRA" render "$1" -t hard --size 64x48 -o "$2" --quiet || fail "$1"
    local test="$2"
    if [ "${5:-}" = flop ]; then oiiotool "$2" --flop -o "flopped_$2"; test="flopped_$2"; fi
    "$PENUMBRA" compare s1.exr "$test" --channels visibility --fail "$4" >/dev/null || fail "$3"
}
# Moved 1000 m from the origin: the same visibility (`hard`: one map, relative biases).
"$gen" --scale 1 --offset 1000,0,-700 --out a "$scene" >/dev/null
moved=a/box_floating_s1_o1000_0_-700.json
grep -q '"translate": \[' "$moved" || fail "the moved copy has no translation"
same_as_original "$moved" moved.exr "box_floating 1000 m away is not the one at the origin" 1e-6
# Turned about the origin with its camera and light: the same visibility; mirrored in x (every
# object's winding flipped): the flopped visibility (1e-5 for the floats the turn rounds).
"$gen" --scale 1 --rotate 30,45,-20 --out a "$scene" >/dev/null
turned=a/box_floating_s1_r30_45_-20.json
grep -q '"matrix": \[' "$turned" || fail "the turned copy's objects have no matrix"
same_as_original "$turned" turned.exr "box_floating turned is not the original" 1e-5
"$gen" --scale 1 --mirror x --out a "$scene" >/dev/null
same_as_original a/box_floating_s1_mx.json mirrored.exr \
    "box_floating mirrored is not the original's mirror image" 1e-5 flop
# The same light by its other axes: size [h, w], up its former right; `hard`'s one map turns a
# quarter with it over a square window, so the same visibility.
"$gen" --scale 1 --swap-light-axes --out a "$scene" \
    "$PENUMBRA_SOURCE_DIR/scenes/conformance/light_aspect_1to4.json" >/dev/null
python3 - a/light_aspect_1to4_s1_lswap.json <<'PY' || fail "the swapped light is not the same"
import json, sys
light = json.load(open(sys.argv[1]))["lights"][0]
assert light["size"] == [0.5, 2.0] and max(abs(u - v) for u, v in zip(light["up"], [1, 0, 0])) < 1e-9
PY
same_as_original a/box_floating_s1_lswap.json swapped.exr "box_floating's light swapped differs" 1e-6
# The objects in the opposite order: the same visibility, the ids reversed.
"$gen" --scale 1 --reverse-objects --out a "$scene" >/dev/null
grep -q '"name": "box_floating_s1_rev"' a/box_floating_s1_rev.json || fail "no reversed copy"
same_as_original a/box_floating_s1_rev.json reversed.exr "box_floating reversed differs" 1e-6
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
# A value that starts with a minus sign is a value, not a flag.
"$gen" --scale 1 --rotate -30,45,-20 --offset -5,0,0 --out n "$scene" >/dev/null ||
    fail "--rotate -30,45,-20 --offset -5,0,0 refused"
[ -f n/box_floating_s1_r-30_45_-20_o-5_0_0.json ] || fail "no copy turned by -30,45,-20"
expect_exit 2 "--rotate: expected 3 angles" -- "$gen" --scale 1 --rotate 1,2 --out c "$scene"
expect_exit 2 "--mirror: invalid choice" -- "$gen" --scale 1 --mirror w --out c "$scene"
sky="$PENUMBRA_SOURCE_DIR/scenes/bench/environment.json"
[ -f "$sky" ] || fail "scenes/bench/environment.json is gone: name another scene with an environment"
expect_exit 1 "environment.json: environment" -- "$gen" --scale 1 --mirror x --out c "$sky"
[ ! -e c ] || fail "a refused run created its folder"
echo "scale_scenes ok"
