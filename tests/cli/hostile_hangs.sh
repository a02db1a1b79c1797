# Inputs that hung or took quadratic time: a truncated Radiance HDR texture in a glTF (stb's
# HDR decoder looped forever; now decoded by OpenImageIO) and 3,000 animation tracks (25 s).
source "$(dirname "$0")/lib.sh"
cd "$WORK"
FUZZ="$PENUMBRA_SOURCE_DIR/tests/data/fuzz"

# truncated_hdr_texture: refused in well under the 20 s a hang would take.
cp "$FUZZ/gltf/hdr_texture_truncated.gltf" tex.gltf
write_scene_with_gltf tex.json tex.gltf
expect_exit 2 "^penumbra: tex.json: objects.2.gltf: tex.gltf: images.0: cannot read pixels" -- \
    timeout 20 "$PENUMBRA" render tex.json -o out.exr
[ ! -e out.exr ] || fail "a refused render left output"

# animation_tracks_linear: 3,000 tracks, each keyed at frames of its own, load in seconds.
python3 - "$DATA/small.json" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["objects"] = [scene["objects"][0]] + [
    {"box": {"size": [0.1, 0.1, 0.1]}, "transform": {"translate": [0, 0.1, 0]}} for _ in range(3000)]
scene["animation"] = {"frames": "1", "tracks": [
    {"key": "objects.%d.transform.translate" % (i + 1), "keys": [[i, [0, 0.1, 0]], [i + 3, [1, 0.1, 0]]]}
    for i in range(3000)]}
json.dump(scene, open("tracks.json", "w"))
PY
start=$(date +%s)
expect_exit 0 "" -- timeout 60 "$PENUMBRA" render tracks.json --list-frames
elapsed=$(( $(date +%s) - start ))
[ "$elapsed" -le 10 ] || fail "3000 tracks took ${elapsed} s to load (quadratic?)"

# One track per value: a second track on the same key is refused.
python3 - "$DATA/small.json" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["animation"]["tracks"].append(scene["animation"]["tracks"][0])
json.dump(scene, open("twice.json", "w"))
PY
expect_exit 2 "animation.tracks.1.key: 'lights.0.position' is animated by animation.tracks.0 already" -- \
    "$PENUMBRA" render twice.json --list-frames

# animated_image_width: the image size is one per render, so animating it is refused.
python3 - "$DATA/small.json" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["animation"]["tracks"] = [{"key": "image.width", "keys": [[1, 64], [3, 64]]}]
json.dump(scene, open("width.json", "w"))
PY
expect_exit 2 "animation.tracks.0.key: 'image.width' cannot be animated" -- \
    "$PENUMBRA" render width.json --list-frames
echo "hostile_hangs ok"
