# OpenImageIO lives in libpenumbra_oiio.so, loaded only by what reads images or draws contact
# sheets: the binary links none of its ~260 libraries, renders with the module absent, and a
# command that needs it without it (or with a file in its place that is no module) fails with
# one line naming the module, exit 1, nothing written.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
module="$(dirname "$PENUMBRA")/libpenumbra_oiio.so"
[ -f "$module" ] || fail "no $module beside the binary"

# 1. No OpenImageIO among the binary's shared libraries (they cost every process 0.25 s).
if ldd "$PENUMBRA" | grep -q OpenImageIO; then fail "the binary links OpenImageIO"; fi

# 2. A copy of the binary alone in a folder renders a sequence (EXR, preview, JSON)...
mkdir alone
cp "$PENUMBRA" alone/penumbra
alone/penumbra render "$DATA/anim6.json" -f 1-2 -o 'a.####.exr' --preview 'a.####.png' --quiet ||
    fail "render without the module"
"$PENUMBRA" render "$DATA/anim6.json" -f 1-2 -o 'b.####.exr' --preview 'b.####.png' --quiet
for f in a.0001.exr a.0002.exr a.0001.png a.0002.png; do
    cmp "$f" "b${f#a}" || fail "$f differs from the render beside the module"
done
# ... but a contact sheet needs the module: one line naming it, exit 1, no sheet.
expect_exit 1 "cannot load the OpenImageIO module .*alone/libpenumbra_oiio.so .*needed to read images and draw contact sheets.*not found" -- \
    alone/penumbra contact-sheet a.0001.exr -o sheet.png --quiet
[ "$(wc -l <stderr)" -eq 1 ] || fail "more than one line: $(cat stderr)"
[ ! -e sheet.png ] || fail "a sheet was written without the module"
# A scene whose environment map is an OpenEXR file renders without it (the project's own EXR
# reader), the image rendered beside the module; one whose map is a Radiance .hdr needs it.
env_scene="$PENUMBRA_SOURCE_DIR/scenes/bench/environment.json"
alone/penumbra render "$env_scene" -t css --size 32x24 -o env.exr --quiet ||
    fail "an .exr environment without the module"
"$PENUMBRA" render "$env_scene" -t css --size 32x24 -o env_build.exr --quiet
"$PENUMBRA" compare env.exr env_build.exr --fail 0 --warn 0 >/dev/null ||
    fail "the .exr environment renders differently without the module"
sed -e "s|\"sky_sun.exr\"|\"$PENUMBRA_SOURCE_DIR/tests/data/scene/sky.hdr\"|" \
    -e "s|\"\\.\\./assets/|\"$PENUMBRA_SOURCE_DIR/scenes/assets/|" "$env_scene" >hdr.json
grep -q 'sky.hdr' hdr.json || fail "hdr.json names no .hdr"
expect_exit 1 "cannot load the OpenImageIO module" -- \
    alone/penumbra render hdr.json -t hard --size 32x24 -o hdr.exr --quiet
[ ! -e hdr.exr ] || fail "hdr.exr was written without the module"

# 3. A file in its place that is no module, or a library without the module's entry: refused.
printf 'not a library' >alone/libpenumbra_oiio.so
expect_exit 1 "cannot load the OpenImageIO module .*alone/libpenumbra_oiio.so" -- \
    alone/penumbra contact-sheet a.0001.exr -o sheet.png --quiet
libz=$(ldd "$PENUMBRA" | awk '/libz\.so/ {print $3}')
[ -f "$libz" ] || fail "no libz among the binary's libraries to stand in for a module"
cp "$libz" alone/libpenumbra_oiio.so
expect_exit 1 "alone/libpenumbra_oiio.so: not a penumbra OpenImageIO module" -- \
    alone/penumbra contact-sheet a.0001.exr -o sheet.png --quiet
[ ! -e sheet.png ] || fail "a sheet was written with a stand-in module"

# 4. The module beside the copy: the sheet is the one the build tree's binary draws.
cp "$module" alone/
alone/penumbra contact-sheet a.0001.exr a.0002.png -o sheet.png --quiet || fail "sheet with module"
"$PENUMBRA" contact-sheet a.0001.exr a.0002.png -o sheet_build.png --quiet
cmp sheet.png sheet_build.png || fail "the sheets differ"
