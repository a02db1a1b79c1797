# `render MODEL.glb` and `penumbra scene MODEL.glb -o SCENE.json`: the direct render writes an
# EXR named after the file's stem; the written scene renders to the same visibility and beauty;
# a glTF camera is used; scenes name a glTF's camera and lights; bad input exits 2 with the
# flag, file or key named and nothing written.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
cp "$PENUMBRA_SOURCE_DIR/scenes/assets/duck.glb" duck.glb
CAMERAS=/usr/share/assimp/models/glTF2/cameras/Cameras.gltf

# Direct render: out/<stem>.####.exr, a preview, the floor and the duck in the id channel.
"$PENUMBRA" render duck.glb --size 64x48 --preview out/duck.png --quiet
[ -s out/duck.0000.exr ] && [ -s out/duck.png ] || fail "render duck.glb wrote no EXR or preview"
for id in 0 1; do  # compare exits 3 when no pixel has the id
    "$PENUMBRA" compare out/duck.0000.exr out/duck.0000.exr --ids $id --channels visibility >/dev/null ||
        fail "object $id (0 the duck, 1 the floor) is not in view"
done

# The written scene renders as the direct render does (soft shadows: reference, 4x4 samples).
mkdir sub
for flags in "" "--light-size 0.3x0.1 --no-floor"; do
    # shellcheck disable=SC2086
    "$PENUMBRA" scene duck.glb -o sub/s.json --size 64x48 $flags
    grep -q '"gltf": "../duck.glb"' sub/s.json || fail "the glTF is not named relative to sub/"
    # shellcheck disable=SC2086
    "$PENUMBRA" render duck.glb --size 64x48 $flags -t reference -D technique.samples=4 -o d.exr --quiet
    "$PENUMBRA" render sub/s.json -t reference -D technique.samples=4 -o s.exr --quiet
    "$PENUMBRA" compare d.exr s.exr --channels visibility,R,G,B,id --fail 0 >/dev/null ||
        fail "scene.json renders differently from duck.glb (flags: $flags)"
done
grep -q '"plane"' sub/s.json && fail "--no-floor wrote a floor"
soft=(-t reference -D technique.samples=4 --size 64x48 --quiet)
"$PENUMBRA" render duck.glb "${soft[@]}" -o small.exr
"$PENUMBRA" render duck.glb "${soft[@]}" --light-size 2 -o big.exr
"$PENUMBRA" compare small.exr big.exr --channels visibility >/dev/null &&
    fail "--light-size 2 gave the penumbrae of the default size"

# A glTF's camera: Cameras.gltf places a perspective camera at (0.5, 0.5, 3) (yfov 0.7, znear
# 0.01, zfar 100) and an orthographic one.
"$PENUMBRA" scene "$CAMERAS" -o cams.json
python3 - cams.json <<'PY'
import json, math, sys
c = json.load(open(sys.argv[1]))["camera"]
assert c["position"] == [0.5, 0.5, 3], c
assert abs(c["fov_y"] - math.degrees(0.7)) < 1e-4 and c["near"] == 0.01 and c["far"] == 100, c
PY
"$PENUMBRA" render "$CAMERAS" --size 32x24 -o cams.exr --quiet
cat >named.json <<EOF
{"format": "penumbra-scene/1", "camera": {"gltf": "$CAMERAS", "index": 0},
 "lights": [{"position": [0, 3, 0]}], "objects": [{"gltf": "$CAMERAS"}]}
EOF
"$PENUMBRA" render named.json --size 32x24 -o ref.exr --quiet

# Bad input: exit 2, one line naming what is wrong, nothing written.
mkdir clean && cd clean
expect_exit 2 "^penumbra: .*Cameras.gltf: cameras.1: an orthographic camera" -- \
    "$PENUMBRA" render ../named.json -D camera.index=1
python3 - "$CAMERAS" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
d["nodes"][1]["camera"] = 1  # the first placed camera is now the orthographic one
d["buffers"][0]["uri"] = "data:application/octet-stream;base64," + __import__("base64").b64encode(
    open(sys.argv[1].rsplit("/", 1)[0] + "/" + d["buffers"][0]["uri"], "rb").read()).decode()
json.dump(d, open("ortho.gltf", "w"))
d["cameras"][0]["perspective"]["yfov"] = float("nan")
json.dump(d, open("nan.gltf", "w"))
PY
expect_exit 2 "^penumbra: ortho.gltf: cameras.1: an orthographic camera" -- "$PENUMBRA" render ortho.gltf
expect_exit 2 "^penumbra: ortho.gltf: cameras.1: an orthographic camera" -- "$PENUMBRA" scene ortho.gltf -o s.json
expect_exit 2 "^penumbra: nan.gltf: " -- "$PENUMBRA" render nan.gltf
rm ortho.gltf nan.gltf
for bad in 0 -1 1x nan 2x0 x1 1e7 1e-50 1x1x1; do
    expect_exit 2 "^penumbra: render: --light-size: " -- "$PENUMBRA" render ../duck.glb --light-size "$bad"
    expect_exit 2 "^penumbra: scene: --light-size: " -- "$PENUMBRA" scene ../duck.glb --light-size "$bad" -o s.json
done
expect_exit 2 "^penumbra: scene: missing -o SCENE.json" -- "$PENUMBRA" scene ../duck.glb
expect_exit 2 "^penumbra: scene: --output: ../duck.glb: the file name must end in .json" -- \
    "$PENUMBRA" scene ../duck.glb -o ../duck.glb
cmp -s ../duck.glb "$PENUMBRA_SOURCE_DIR/scenes/assets/duck.glb" || fail "scene -o overwrote the model"
expect_exit 2 "^penumbra: scene: missing MODEL.glb" -- "$PENUMBRA" scene -o s.json
expect_exit 2 "^penumbra: scene: '../named.json' is not a .gltf or .glb file" -- "$PENUMBRA" scene ../named.json -o s.json
expect_exit 2 "^penumbra: render: --no-floor: only for a .gltf/.glb model" -- "$PENUMBRA" render ../named.json --no-floor
expect_exit 2 "^penumbra: render: --light-size: only for a .gltf/.glb model" -- "$PENUMBRA" render ../named.json --light-size 1
expect_exit 2 "^penumbra: missing.glb: " -- "$PENUMBRA" render missing.glb
expect_exit 2 "^penumbra: missing.glb: " -- "$PENUMBRA" scene missing.glb -o s.json
mkdir folder.glb
expect_exit 2 "^penumbra: folder.glb: is a folder" -- "$PENUMBRA" scene folder.glb -o s.json
rmdir folder.glb
head -c 100 ../duck.glb >cut.glb
expect_exit 2 "^penumbra: cut.glb: " -- "$PENUMBRA" render cut.glb
expect_exit 2 "^penumbra: cut.glb: " -- "$PENUMBRA" scene cut.glb -o s.json
rm cut.glb
expect_exit 2 "^penumbra: .*named.json: camera.index: camera 5 does not exist" -- \
    "$PENUMBRA" render ../named.json -D camera.index=5
expect_exit 2 "^penumbra: .*named.json: lights.0.gltf: .*Cameras.gltf has no KHR_lights_punctual light" -- \
    "$PENUMBRA" render ../named.json -D "lights.0={\"gltf\": \"$CAMERAS\"}"
expect_exit 2 "^penumbra: -D camera.fov: unknown key" -- "$PENUMBRA" render ../named.json -D camera.fov=3
[ -z "$(ls -A)" ] || fail "a refused command wrote: $(ls -A)"
echo "gltf_scene: ok"
