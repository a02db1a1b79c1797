# Allocations estimated before they are made: a render over the memory limit or a texture over
# llvmpipe's 2 GiB is refused naming the key (exit 2), as are ssm's splat work and images or
# accessors whose headers declare more than their files hold (fit-lights, compare,
# contact-sheet, glTF).
source "$(dirname "$0")/lib.sh"
cd "$WORK"
FUZZ="$PENUMBRA_SOURCE_DIR/tests/data/fuzz"
S="$DATA/small.json"
render() { "$PENUMBRA" render "$S" -f 1 -o out.exr "$@"; }

# samples_8_at_8192: was 7.5 GB then "framebuffer incomplete" (exit 1).
expect_exit 2 "small.json: image.samples: .* needs 8.0 GiB in one texture" -- \
    render -D image.samples=8 --size 8192x8192
# size_16384: was 4.4 GB, exit 1.
expect_exit 2 "small.json: image.width: the G-buffer position texture needs 4.0 GiB in one texture" -- \
    render --size 16384x16384
expect_exit 2 "small.json: image.width: the render needs about .* more than the memory limit of 1.0 GiB \(--memory-limit\)$" -- \
    render --size 8192x8192 --memory-limit 1G
# map_size_16384 for reference and adaptive, css order 16 at 4096: were exit 1.
expect_exit 2 "small.json: technique.map_size: the shadow map array \(16384\^2 x 32\)" -- \
    render -t reference -D technique.map_size=16384
expect_exit 2 "small.json: technique.map_size: the shadow map array \(16384\^2 x 4\)" -- \
    render -t adaptive -D technique.map_size=16384
expect_exit 2 "small.json: technique.order: the summed-area table array \(4097\^2 x 17 RGBA32F\)" -- \
    render -t css -D technique.order=16 -D technique.map_size=4096
expect_exit 2 "small.json: technique.order: the basis images \(4096\^2 x 17 RGBA32F, mipmapped\)" -- \
    render -t css -D technique.order=16 -D technique.map_size=4096 -D technique.filter=mipmap
# ssm_splat_bound: map 4096 x ssm 4096 ran past 300 s.
expect_exit 2 "small.json: technique.ssm_size: map_size x ssm_size = 4096 x 4096 exceeds" -- \
    render -t ssm -D technique.map_size=4096 -D technique.ssm_size=4096
# env_reference_1024: 513 environment lights' visibility layers (6.4 GB) were GL_OUT_OF_MEMORY,
# exit 1; then refused (each light's layer counted); now folded into one irradiance layer: 512
# directions at 256 x 192 (513 layers were 0.8 GB) render within 512 MiB.
"$PENUMBRA" render "$PENUMBRA_SOURCE_DIR/scenes/bench/environment.json" -t reference \
    -D technique.map_size=64 --size 256x192 -o env.exr --memory-limit 512M --quiet ||
    fail "the environment reference did not render within 512 MiB"
grep -q '"maps_rendered": 512' env.json || fail "env.json: not 512 maps"
rm env.exr env.json
expect_exit 2 "^penumbra: render: --memory-limit: expected a size" -- render --memory-limit lots
[ ! -e out.exr ] || fail "a refused render left output"

# Headers that declare more than the file holds cost only what the file holds (peak RSS).
peak() { /usr/bin/time -f %M -o rss "$@" >/dev/null 2>"$WORK/stderr" || true; cat rss | tail -1; }
# fit_lights_huge_hdr: a 2 KB .hdr declaring 16384^2 took 3.3 GB.
kb=$(peak "$PENUMBRA" fit-lights "$FUZZ/image/huge_header.hdr")
[ "$kb" -lt 600000 ] || fail "fit-lights on huge_header.hdr peaked at $kb KB"
expect_exit 2 "huge_header.hdr: cannot read pixels" -- "$PENUMBRA" fit-lights "$FUZZ/image/huge_header.hdr"
expect_exit 2 "huge_header.hdr: decoding its 16384x16384 pixels needs about 3.0 GiB, more than the memory limit of 64 MiB" -- \
    "$PENUMBRA" fit-lights "$FUZZ/image/huge_header.hdr" --memory-limit 64M
# compare_huge_exr and fit_lights_huge_exr: a small EXR declaring 16384^2 took 1.2-3.3 GB.
kb=$(peak "$PENUMBRA" compare "$FUZZ/exr/huge_window.exr" "$FUZZ/exr/huge_window.exr")
[ "$kb" -lt 600000 ] || fail "compare on huge_window.exr peaked at $kb KB"
expect_exit 4 "huge_window.exr: .*Unexpected data block" -- \
    "$PENUMBRA" compare "$FUZZ/exr/huge_window.exr" "$FUZZ/exr/huge_window.exr"
kb=$(peak "$PENUMBRA" fit-lights "$FUZZ/exr/huge_window.exr")
[ "$kb" -lt 600000 ] || fail "fit-lights on huge_window.exr peaked at $kb KB"
kb=$(peak "$PENUMBRA" contact-sheet "$FUZZ/exr/huge_window.exr" -o s.png)
[ "$kb" -lt 600000 ] || fail "contact-sheet on huge_window.exr peaked at $kb KB"
expect_exit 2 "huge_window.exr: .*Unexpected data block" -- \
    "$PENUMBRA" contact-sheet "$FUZZ/exr/huge_window.exr" -o s.png
# contact-sheet: a sheet over the limit is refused before it is drawn.
render --size 64x48 --quiet
expect_exit 2 "^penumbra: -o: s.png: the 16432x8224 sheet needs about 2.3 GiB, more than the memory limit of 1.0 GiB" -- \
    "$PENUMBRA" contact-sheet out.exr out.exr --tile 8192x8192 --no-labels --memory-limit 1G -o s.png
[ ! -e s.png ] || fail "contact-sheet wrote s.png"
rm out.exr out.json

# gltf_count_without_data: 231 bytes declaring 60M vertices took 3.4 GB and 18 s, exit 0.
for f in count_without_data count_beyond_buffer; do
    cp "$FUZZ/gltf/$f.gltf" .
    write_scene_with_gltf "$f.json" "$f.gltf"
    expect_exit 2 "$f.gltf: meshes.0.primitives.0.attributes.POSITION: accessor 0: " -- \
        timeout 20 "$PENUMBRA" render "$f.json" --list-frames
done
echo "hostile_memory ok"
