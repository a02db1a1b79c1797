# penumbra contact-sheet: files of different sizes, a sweep folder and a frame pattern in a
# grid; beauty cells equal render's --preview, scalar channels grey; PNG, JPEG and EXR sheets;
# bad input (missing or unreadable image, absent channel, folder output, no images, memory)
# refused with one line, exit 2 and nothing written.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
scene="$DATA/small.json"
"$PENUMBRA" render "$scene" -f 1 -o a.exr --preview a.png 2>/dev/null || fail "render a"
"$PENUMBRA" render "$scene" -f 2 --size 32x32 -o 'b c.exr' 2>/dev/null || fail "render b"

# Two EXRs (64x48, 32x32) and a PNG: 2 columns, tiles of the first image's size, labels.
"$PENUMBRA" contact-sheet a.exr 'b c.exr' a.png -o sheet.png 2>log.txt || { cat log.txt; fail "sheet"; }
grep -q "3 images" log.txt || fail "summary: $(cat log.txt)"
"$PENUMBRA" contact-sheet a.exr 'b c.exr' a.png -o bare.png --no-labels --quiet || fail "--no-labels"
/usr/bin/python3 - <<'PY'
import matplotlib.image as mpimg, numpy as np
s, b, a = (mpimg.imread(f)[:, :, :3] for f in ("sheet.png", "bare.png", "a.png"))
g = 2  # the gap at a 64-pixel tile
assert b.shape == (2 * 48 + 3 * g, 2 * 64 + 3 * g, 3), b.shape  # 2x2 grid, no label strips
assert s.shape[1] == b.shape[1] and s.shape[0] > b.shape[0] + 2 * 9, s.shape
# Cell 1 is a.exr tone-mapped as render's preview; cell 3 is a.png itself.
assert np.abs(b[g:g + 48, g:g + 64] - a).max() <= 1.5 / 255, "beauty differs from the preview"
assert np.abs(b[2 * g + 48:2 * g + 96, g:g + 64] - a).max() <= 1.5 / 255, "png cell"
# Cell 2 (32x32 scaled to fit 64x48: 48x48, centred) holds a picture, its sides background.
cell = b[g:g + 48, 2 * g + 64:2 * g + 128]
assert cell[:, 8:56].std() > 0.02 and np.ptp(cell[:, :7]) == 0 and np.ptp(cell[:, 57:]) == 0
# Labels: light text in the strips under the cells, none without labels.
strip = s[g + 48:g + 48 + 10, g:g + 64]
assert strip.max() > 0.6, "no label under cell 1"
PY

# A sweep folder: its runs in order, labelled by technique and values; --channel visibility grey.
"$PENUMBRA" sweep "$scene" -t hard --vary technique.pcf=1,5 --reference-set technique.samples=2 \
    --repeat 1 --no-report --quiet -o sw 2>/dev/null || fail "sweep"
"$PENUMBRA" contact-sheet --sweep sw --channel visibility --columns 2 -o vis.jpg --quiet ||
    fail "--sweep"
head -c 3 vis.jpg | od -An -tx1 | grep -q "ff d8 ff" || fail "vis.jpg is not a JPEG"
"$PENUMBRA" contact-sheet --sweep sw --channel visibility -o vis.png --quiet --no-labels
/usr/bin/python3 - <<'PY'
import matplotlib.image as mpimg, numpy as np
v = mpimg.imread("vis.png")[:, :, :3]
assert v.shape == (48 + 4, 2 * 64 + 6, 3), v.shape
assert np.abs(v[:, :, 0] - v[:, :, 1]).max() == 0 and np.abs(v[:, :, 0] - v[:, :, 2]).max() == 0
assert v.min() < 0.1 and v.max() > 0.9, "visibility should hold shadow and light"
PY
# A frame pattern with -f; Z (inf where nothing is) as grey; an EXR sheet reads back.
"$PENUMBRA" render "$scene" -f 1-3 -o 'fr/a.####.exr' 2>/dev/null || fail "render frames"
"$PENUMBRA" contact-sheet 'fr/a.####.exr' -f 1-3 --tile 32x24 --no-labels --channel Z \
    -o z.exr --quiet || fail "frames"
/usr/bin/python3 - <<'PY'
import struct
d = open("z.exr", "rb").read(4)
assert d == b"\x76\x2f\x31\x01", d  # the OpenEXR magic
PY
"$PENUMBRA" compare z.exr z.exr >/dev/null || fail "z.exr does not read back"
oiiotool --info z.exr | grep -q " 70 x  *54," || fail "2x2 cells of 32x24 (near-square): $(oiiotool --info z.exr)"

# Bad input: one line, exit 2, nothing written.
mkdir folder.png
printf 'not an exr' >bad.exr
touch notes.txt
expect_exit 2 "^penumbra: missing.exr: no such file" -- "$PENUMBRA" contact-sheet a.exr missing.exr -o x.png
expect_exit 2 "^penumbra: bad.exr: not an OpenEXR file" -- "$PENUMBRA" contact-sheet a.exr bad.exr -o x.png
expect_exit 2 "^penumbra: notes.txt: expected an .exr" -- "$PENUMBRA" contact-sheet notes.txt -o x.png
expect_exit 2 "^penumbra: a.exr: no channel 'nope' \(--channel\); it has R, G, B, A, .*visibility" -- \
    "$PENUMBRA" contact-sheet a.exr 'b c.exr' --channel nope -o x.png
expect_exit 2 "a.png: --channel visibility needs an EXR" -- \
    "$PENUMBRA" contact-sheet a.exr a.png --channel visibility -o x.png
expect_exit 2 "^penumbra: -o: folder.png: " -- "$PENUMBRA" contact-sheet a.exr -o folder.png
expect_exit 2 "no images" -- "$PENUMBRA" contact-sheet -o x.png
expect_exit 2 "missing -o" -- "$PENUMBRA" contact-sheet a.exr
expect_exit 2 "must end in .png, .exr, .jpg" -- "$PENUMBRA" contact-sheet a.exr -o x.tif
expect_exit 2 "^penumbra: --sweep: fr: no sweep.json" -- "$PENUMBRA" contact-sheet --sweep fr -o x.png
expect_exit 2 "^penumbra: --font: 'no-such.ttf'" -- "$PENUMBRA" contact-sheet a.exr --font no-such.ttf -o x.png
expect_exit 2 "memory limit" -- \
    "$PENUMBRA" contact-sheet a.exr a.exr --tile 8000x8000 --memory-limit 64M -o x.png
expect_exit 2 "more than 65535 pixels a side" -- \
    "$PENUMBRA" contact-sheet a.exr a.exr a.exr a.exr a.exr --columns 5 --tile 16000x10 -o x.png
# sheet_overwrites_input: `-o` onto one of the images (a glob over the sheet's own folder, run
# twice) replaced that image with the sheet.
cp a.exr again.exr
expect_exit 2 "^penumbra: -o: 'again.exr' is one of the images; writing the sheet there" -- \
    "$PENUMBRA" contact-sheet a.exr again.exr -o again.exr
cmp -s a.exr again.exr || fail "a refused sheet changed its input"
# A sweep.json naming a file outside its folder is refused, not read.
mkdir evil && printf '{"schema": "penumbra-sweep", "runs": [{"exr": "../a.exr"}]}' >evil/sweep.json
expect_exit 2 "inside the sweep folder" -- "$PENUMBRA" contact-sheet --sweep evil -o x.png
[ -z "$(ls -d x.* .x.* 2>/dev/null)" ] && [ -z "$(ls -A folder.png)" ] || fail "bad input wrote files"
echo "contact_sheet ok"
