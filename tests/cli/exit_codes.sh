# Every exit code of `penumbra render`: 0 written, 1 run-time failure, 2 bad input (with a
# one-line message naming the file, key or flag, and nothing written), 3 no backend.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
scene="$DATA/small.json"

expect_exit 0 "" -- "$PENUMBRA" render "$scene" -f 1 -o ok.exr --quiet
[ -f ok.exr ] && [ -f ok.json ] || fail "exit 0 without ok.exr and ok.json"

# 2: bad command line
expect_exit 2 "^penumbra: render: unknown flag '--bogus'" -- "$PENUMBRA" render "$scene" --bogus
expect_exit 2 "--frames" -- "$PENUMBRA" render "$scene" -f 3-1 -o x.exr
expect_exit 2 "missing SCENE" -- "$PENUMBRA" render
expect_exit 2 "--size" -- "$PENUMBRA" render "$scene" --size 10by10
expect_exit 2 "--technique: unknown technique 'nope'" -- "$PENUMBRA" render "$scene" -t nope
expect_exit 2 "unknown command" -- "$PENUMBRA" frobnicate
expect_exit 2 "--device 9: no such EGL device" -- "$PENUMBRA" render "$scene" --device 9 -f 1 -o x.exr
expect_exit 2 "--backend: expected auto" -- "$PENUMBRA" render "$scene" --backend vulkan -o x.exr
# 2: bad input, naming the file and key
expect_exit 2 "no-such.json" -- "$PENUMBRA" render no-such.json -o x.exr
printf '{"format": "penumbra-scene/1",' >broken.json
expect_exit 2 "broken.json" -- "$PENUMBRA" render broken.json -o x.exr
expect_exit 2 "technique.map_size" -- "$PENUMBRA" render "$scene" -D technique.map_size=3 -o x.exr
expect_exit 2 "technique.bogus" -- "$PENUMBRA" render "$scene" -D technique.bogus=1 -o x.exr
expect_exit 2 "lights.0.size" -- "$PENUMBRA" render "$scene" -D 'lights.0.size=[0,1]' -o x.exr
expect_exit 2 "image.width" -- "$PENUMBRA" render "$scene" -D image.width=100000 -o x.exr
[ ! -e x.exr ] && [ ! -e x.0001.exr ] || fail "bad input left an output file"
[ "$(ls -A | grep -c '\.tmp$' || true)" -eq 0 ] || fail "bad input left a temporary file"

# 2: an output folder that cannot be made (a file is in the way) is found before rendering
echo "not a folder" >blocker
expect_exit 2 "^penumbra: --output: blocker/x.exr: 'blocker' is not a folder" -- \
    "$PENUMBRA" render "$scene" -f 1 -o blocker/x.exr
# 1: a frame fails at run time (its 246-byte name fits, its temporary name does not)
long=$(printf 'a%.0s' $(seq 246)).exr
expect_exit 1 "File name too long" -- "$PENUMBRA" render "$scene" -f 1 -o "$long"
[ -z "$(ls -A | grep aaaa || true)" ] || fail "a failed frame left a file"

# 3: no usable OpenGL backend (no EGL vendor, no OSMesa library)
expect_exit 3 "no usable OpenGL backend" -- env __EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json \
    PENUMBRA_OSMESA_LIBRARY=/nonexistent/libOSMesa.so "$PENUMBRA" render "$scene" -f 1 -o y.exr
[ ! -e y.exr ] || fail "exit 3 left an output file"
expect_exit 3 "osmesa" -- env PENUMBRA_OSMESA_LIBRARY=/nonexistent/libOSMesa.so \
    "$PENUMBRA" info --backend osmesa
echo "exit codes ok"
