# Paths: glTF buffer and image URIs stay inside the glTF's folder, relative or absolute, after
# percent-decoding and symlinks; a scene's name is a plain file name; outputs replace only
# regular files (never a device, FIFO or folder). One line, exit 2, no output.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
mkdir -p assets/sub outside
echo "secret" >outside/secret.bin
ln -s "$WORK/outside/secret.bin" assets/link.bin
no_output() { [ ! -e out.exr ] && [ ! -d out ] || fail "a refused render left output: $1"; }
# outside URI: a glTF in assets/sub whose buffer is URI is refused as outside its folder.
outside() {
    write_triangle_gltf assets/sub/model.gltf "$1"
    write_scene_with_gltf scene.json assets/sub/model.gltf
    expect_exit 2 "model.gltf: buffers.0.uri: '.*' is outside the glTF's folder$" -- \
        "$PENUMBRA" render scene.json -o out.exr
    no_output "$1"
}
outside "../../../../../../../../etc/passwd"
outside "../../outside/secret.bin"
outside "%2E%2E/%2E%2E/outside/secret.bin"
outside "/etc/passwd"
outside "$WORK/outside/secret.bin"
outside "../link.bin"
outside "."

# Inside the folder: relative, percent-encoded, absolute and through ../ that comes back in.
for uri in "tri.bin" "%74ri.bin" "$WORK/assets/sub/tri.bin" "../sub/tri.bin"; do
    write_triangle_gltf assets/sub/model.gltf "$uri" assets/sub/tri.bin
    write_scene_with_gltf scene.json assets/sub/model.gltf
    "$PENUMBRA" render scene.json -o inside.exr --quiet 2>stderr || { cat stderr; fail "inside URI '$uri'"; }
done
# An image URI outside the folder is refused as well.
python3 - assets/sub/model.gltf <<'PY'
import json, sys
g = json.load(open(sys.argv[1]))
g["images"] = [{"uri": "../../outside/secret.png"}]
json.dump(g, open(sys.argv[1], "w"))
PY
expect_exit 2 "model.gltf: images.0.uri: '../../outside/secret.png' is outside the glTF's folder$" -- \
    "$PENUMBRA" render scene.json -o out.exr

# A scene name that is a path would write outside out/.
for name in "../../x" "a/b" ".." "."; do
    expect_exit 2 "small.json: name: '$name' is not a plain file name" -- \
        "$PENUMBRA" render "$DATA/small.json" -f 1 -D "name=\"$name\""
done
[ -z "$(find .. -maxdepth 1 -name 'x.*')" ] || fail "a scene name wrote outside out/"
[ ! -d out ] || fail "a refused scene name left out/"

# Outputs: a device, a FIFO or a folder in the way is refused before rendering.
mkfifo pipe.json
mkdir folder.exr
expect_exit 2 "^penumbra: --timings: /dev/null: is a device \(an output replaces only a regular file\)$" -- \
    "$PENUMBRA" render "$DATA/small.json" -f 1 -o out.exr --timings /dev/null
no_output "--timings /dev/null"
expect_exit 2 "^penumbra: --timings: pipe.json: is a FIFO" -- \
    timeout 20 "$PENUMBRA" render "$DATA/small.json" -f 1 -o out.exr --timings pipe.json
expect_exit 2 "^penumbra: --output: folder.exr: is a folder" -- \
    "$PENUMBRA" render "$DATA/small.json" -f 1 -o folder.exr
expect_exit 2 "^penumbra: --output: /dev/null: is a device" -- \
    "$PENUMBRA" fit-lights "$PENUMBRA_SOURCE_DIR/tests/data/gl/sky_sun.exr" -o /dev/null
[ -p pipe.json ] && [ -d folder.exr ] || fail "an output replaced a FIFO or folder"
no_output "outputs"
echo "hostile_paths ok"
