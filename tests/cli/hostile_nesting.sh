# JSON nested deeper than 256 levels is refused while parsing, before anything recurses over it:
# a scene's technique, a glTF's extras, a fit-lights file and a -D value. One line naming the
# file (or flag), exit 2, no output.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
nest() { python3 -c 'import sys; n = int(sys.argv[1]); print("[" * n + "]" * n)' "$1"; }
one_line() { [ "$(wc -l <"$WORK/stderr")" -eq 1 ] || { cat "$WORK/stderr"; fail "not one line: $1"; }; }
# scene_with_x OUT.json N: small.json, still, with technique.x = N nested arrays.
scene_with_x() {
    python3 - "$DATA/small.json" "$@" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
del scene["animation"]
n = int(sys.argv[3])
text = json.dumps(scene).replace('"map_size": 256', '"map_size": 256, "x": ' + "[" * n + "]" * n)
open(sys.argv[2], "w").write(text)
PY
}

scene_with_x deep.json 100000
expect_exit 2 "^penumbra: deep.json: nesting deeper than 256 levels$" -- \
    "$PENUMBRA" render deep.json -o out.exr
one_line "deep scene"
# 256 levels (the scene, its technique, 254 arrays) parse, then fail as an unknown parameter,
# quoted short; 257 do not.
scene_with_x ok.json 254
expect_exit 2 "technique" -- "$PENUMBRA" render ok.json -o out.exr
grep -q "nesting" "$WORK/stderr" && fail "256 levels refused for depth"
[ "$(wc -c <"$WORK/stderr")" -lt 300 ] || fail "a long message: $(head -c 300 "$WORK/stderr")"
scene_with_x over.json 255
expect_exit 2 "over.json: nesting deeper than 256 levels" -- "$PENUMBRA" render over.json -o out.exr

# A glTF whose extras nest 20,000 deep.
echo "{\"asset\": {\"version\": \"2.0\"}, \"extras\": $(nest 20000)}" >deep.gltf
write_scene_with_gltf gltf.json deep.gltf
expect_exit 2 "deep.gltf: nesting deeper than 256 levels$" -- "$PENUMBRA" render gltf.json -o out.exr
one_line "deep glTF"

# A -D value and a fit-lights file.
expect_exit 2 "^penumbra: -D technique.x: nesting deeper than 256 levels$" -- \
    "$PENUMBRA" render "$DATA/small.json" -D "technique.x=$(nest 50000)" -o out.exr
nest 20000 >lights.json
expect_exit 2 "lights.json: nesting deeper than 256 levels$" -- "$PENUMBRA" render \
    "$PENUMBRA_SOURCE_DIR/tests/data/gl/environment.json" --size 64x48 \
    -D "technique.env_lights_file=\"$WORK/lights.json\"" -o out.exr
one_line "deep fit-lights file"
[ ! -e out.exr ] && [ ! -d out ] || fail "a refused render left output"
echo "hostile_nesting ok"
