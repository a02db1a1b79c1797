# Only regular files are opened: a FIFO, a device or a folder given as the scene, as a glTF, as
# a glTF buffer or as a `penumbra compare` input is refused at once (one line naming the file;
# exit 2, compare's 4), never read or waited on.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
mkfifo pipe.json pipe.gltf pipe.bin pipe.exr
mkdir folder.json
# Every command gets 20 s: a blocked open would end in timeout's 124, not the expected code.
refused() { expect_exit "$1" "$2" -- timeout 20 "${@:3}"; }

refused 2 "^penumbra: pipe.json: is a FIFO$" "$PENUMBRA" render pipe.json -o out.exr
refused 2 "^penumbra: /dev/zero: is a device$" "$PENUMBRA" render /dev/zero -o out.exr
refused 2 "^penumbra: folder.json: is a folder$" "$PENUMBRA" render folder.json -o out.exr

write_scene_with_gltf gltf.json pipe.gltf
refused 2 "pipe.gltf: is a FIFO$" "$PENUMBRA" render gltf.json -o out.exr
write_triangle_gltf buffer.gltf pipe.bin
write_scene_with_gltf buffer.json buffer.gltf
refused 2 "buffer.gltf: buffers.0.uri: cannot read 'pipe.bin' \(is a FIFO\)$" \
    "$PENUMBRA" render buffer.json -o out.exr
[ ! -e out.exr ] && [ ! -d out ] || fail "a refused render left output"

# compare: unreadable input is exit 4.
"$PENUMBRA" render "$DATA/small.json" -f 1 -o ref.exr --quiet
refused 4 "pipe.exr: is a FIFO$" "$PENUMBRA" compare ref.exr pipe.exr
refused 4 "/dev/zero: is a device$" "$PENUMBRA" compare /dev/zero ref.exr
refused 4 "folder.json: is a folder$" "$PENUMBRA" compare ref.exr folder.json
echo "hostile_special_files ok"
