# Wrong codes and messages: bad values in a fit-lights file, outputs that are one file under two
# names or an input of the scene, a corrupt PNG budget map (no libpng line), and long values
# quoted at most 80 characters.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
S="$DATA/small.json"

# env_lights_wrong_type and env_lights_radiance_1e39: were "internal error" (exit 1) and an
# inf/NaN beauty (exit 0).
scene="$PENUMBRA_SOURCE_DIR/tests/data/gl/environment.json"
"$PENUMBRA" fit-lights "$PENUMBRA_SOURCE_DIR/tests/data/gl/sky_sun.exr" --max 2 -o lights.json 2>/dev/null
edit() {  # edit OUT PYTHON: lights.json changed by PYTHON (j is the document)
    python3 -c "import json; j = json.load(open('lights.json')); $2; json.dump(j, open('$1', 'w'))"
}
env_bad() {  # env_bad FILE PATTERN
    expect_exit 2 "^penumbra: technique\.env_lights_file: .*$1: $2" -- "$PENUMBRA" render "$scene" \
        --size 32x24 -D "technique.env_lights_file=\"$WORK/$1\"" -o env.exr
    [ "$(wc -l <"$WORK/stderr")" -eq 1 ] || fail "more than one line for $1"
    [ ! -e env.exr ] || fail "a refused render left output ($1)"
}
edit typed.json 'j["total_energy"] = "lots"'
env_bad typed.json "total_energy: expected a number in 0\.\.1e\+30, got \"lots\"$"
edit radiance.json 'j["lights"][0]["radiance"] = [1e39, 1, 1]'
env_bad radiance.json "lights.0.radiance: expected 3 numbers within \+-3\.4e38, got \[1e\+39,1,1\]$"
edit absurd.json 'j["lights"][1]["radiance"] = [1e20, 1, 1]'
env_bad absurd.json "lights.1.radiance: expected 3 values in \[0, 1e10\], got \[1e\+20,1,1\]$"
edit share.json 'j["lights"][0]["energy_share"] = [1]'
env_bad share.json "lights.0.energy_share: expected a number in 0\.\.1, got \[1\]$"

# timings_same_file: `-o ./y.exr --timings y.exr` left y.exr holding the JSON.
expect_exit 2 "^penumbra: --timings: 'y.exr' is another output of frame 1$" -- \
    "$PENUMBRA" render "$S" -f 1 -o ./y.exr --timings y.exr
mkdir -p sub
expect_exit 2 "^penumbra: --timings: 'sub/../y.exr' is another output of frame 1$" -- \
    "$PENUMBRA" render "$S" -f 1 -o y.exr --timings sub/../y.exr
[ ! -e y.exr ] || fail "a refused render left output"

# output_overwrites_scene: `-o own.exr` beside own.json replaced the scene with its timing JSON;
# an explicit --timings onto the scene, or onto a glTF it reads, did the same.
cp "$S" own.json
expect_exit 2 "^penumbra: --output: 'own.json' \(its timing JSON\) is a file the scene reads; \
writing it would overwrite that input \(name another output\)$" -- "$PENUMBRA" render own.json \
    -f 1 -o own.exr
expect_exit 2 "^penumbra: --timings: 'sub/../own.json' is a file the scene reads; " -- \
    "$PENUMBRA" render own.json -f 1 -o z.exr --timings sub/../own.json
cmp -s own.json "$S" || fail "a refused render changed the scene file"
[ ! -e own.exr ] && [ ! -e z.exr ] || fail "a refused render left output"
cp "$PENUMBRA_SOURCE_DIR/scenes/assets/duck.glb" duck.glb
expect_exit 2 "^penumbra: --timings: 'duck.glb' is a file the scene reads; " -- \
    "$PENUMBRA" render duck.glb --size 32x24 -o duck.exr --timings duck.glb
cmp -s duck.glb "$PENUMBRA_SOURCE_DIR/scenes/assets/duck.glb" || fail "the glTF was changed"
# ... or onto a .gltf's external buffer.
write_triangle_gltf tri.gltf tri.bin tri.bin
write_scene_with_gltf tri.json tri.gltf
cp tri.bin tri.bin.orig
expect_exit 2 "^penumbra: --timings: 'tri.bin' is a file the scene reads; " -- \
    "$PENUMBRA" render tri.json -f 1 -o tri.exr --timings tri.bin
cmp -s tri.bin tri.bin.orig || fail "the glTF's buffer was changed"

# png_budget_map_corrupt: a PNG whose data is damaged printed a libpng line first.
cp "$S" scene.json
python3 - "$PENUMBRA_SOURCE_DIR/scenes/budget_ramp.png" <<'PY'
import sys
b = bytearray(open(sys.argv[1], "rb").read())
i = b.index(b"IDAT") + 8
b[i:i + 16] = bytes(range(16))
open("corrupt.png", "wb").write(b)
PY
expect_exit 2 "^penumbra: technique\.budget_map: .*corrupt.png: cannot read" -- "$PENUMBRA" render \
    scene.json -t bitmask -f 1 -D technique.map_size=256 -D technique.budget_map=corrupt.png -o bm.exr
[ "$(wc -l <"$WORK/stderr")" -eq 1 ] || { cat "$WORK/stderr" >&2; fail "more than one line on stderr"; }

# quote_80: no message repeats a whole long value (flags, -D, animation keys, texture URIs).
long=$(printf 'x%.0s' $(seq 1 500))
short_message() {
    [ "$(wc -c <"$WORK/stderr")" -lt 400 ] || { cat "$WORK/stderr" >&2; fail "$1: message too long"; }
}
expect_exit 2 "" -- "$PENUMBRA" render "$S" --size "$long"; short_message --size
expect_exit 2 "" -- "$PENUMBRA" render "$S" -D "$long"; short_message -D
expect_exit 2 "" -- "$PENUMBRA" render "$S" "--$long"; short_message "unknown flag"
expect_exit 5 "" -- "$PENUMBRA" compare a.exr b.exr --fail "$long"; short_message --fail  # compare: usage 5
expect_exit 2 "" -- "$PENUMBRA" fit-lights x.exr --shape "$long"; short_message --shape
python3 - "$S" "$long" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["animation"]["tracks"][0]["key"] = "lights.0." + sys.argv[2]
json.dump(scene, open("key.json", "w"))
PY
expect_exit 2 "animation.tracks.0.key: " -- "$PENUMBRA" render key.json --list-frames
short_message "animation key"
python3 - "$long" <<'PY'
import json, sys, struct, base64
data = base64.b64encode(struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)).decode()
json.dump({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
           "nodes": [{"mesh": 0}],
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
           "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
           "textures": [{"source": 0}], "images": [{"uri": sys.argv[1] + ".png"}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                          "min": [0, 0, 0], "max": [1, 1, 0]}],
           "bufferViews": [{"buffer": 0, "byteLength": 36}],
           "buffers": [{"uri": "data:application/octet-stream;base64," + data, "byteLength": 36}]},
          open("uri.gltf", "w"))
PY
write_scene_with_gltf uri.json uri.gltf
expect_exit 2 "uri.gltf: images.0" -- "$PENUMBRA" render uri.json --list-frames
short_message "texture URI"
echo "hostile_values ok"
