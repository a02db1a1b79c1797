# The EXR for compositors, read back by OpenImageIO: every attribute with its type, camera
# matrices that reproject P onto its pixel, Z = +inf on the background, Cryptomatte, per-light
# visibility. Needs oiiotool.
source "$(dirname "$0")/lib.sh"
command -v oiiotool >/dev/null || fail "exr_attributes.sh: oiiotool is required"
cd "$WORK"
scene="$PENUMBRA_SOURCE_DIR/scenes/default.json"

# A camera off every axis with a fov that is no integer, at 64x48 (fast).
"$PENUMBRA" render "$scene" -t hard --size 64x48 -o one.exr --quiet \
    -D camera.position=[2.5,1.7,3.9] -D camera.fov_y=37.5
oiiotool --info:format=xml -v one.exr | sed -n '/^<ImageSpec/,$p' >info.xml
oiiotool --dumpdata one.exr >pixels.txt

python3 - info.xml pixels.txt <<'PY' || fail "attributes or reprojection"
import json, re, sys, xml.etree.ElementTree as ET
spec = ET.parse(sys.argv[1]).getroot()
names = [c.text for c in spec.iter("channelname")]
attrs = {a.get("name"): (a.get("type"), a.text) for a in spec.iter("attrib")}
want = {
    "penumbra/version": "string", "penumbra/commit": "string", "penumbra/technique": "string",
    "penumbra/params": "string", "penumbra/scene": "string", "penumbra/backend": "string",
    "penumbra/gl_vendor": "string", "penumbra/gl_renderer": "string",
    "penumbra/gl_version": "string", "penumbra/frame": "int", "penumbra/samples": "int",
    "penumbra/camera/fov_y": "float", "penumbra/camera/near": "float",
    "penumbra/camera/far": "float", "worldToCamera": "matrix", "worldToNDC": "matrix",
    "cryptomatte/3ae39a5/name": "string", "cryptomatte/3ae39a5/hash": "string",
    "cryptomatte/3ae39a5/conversion": "string", "cryptomatte/3ae39a5/manifest": "string",
}
for name, kind in want.items():
    assert name in attrs, f"attribute {name} missing"
    assert attrs[name][0] == kind, f"{name} is {attrs[name][0]}, expected {kind}"
assert attrs["penumbra/frame"][1] == "0" and attrs["penumbra/samples"][1] == "1"
assert float(attrs["penumbra/camera/fov_y"][1]) == 37.5
assert attrs["cryptomatte/3ae39a5/name"][1] == "CryptoObject"
assert attrs["cryptomatte/3ae39a5/hash"][1] == "MurmurHash3_32"
assert attrs["cryptomatte/3ae39a5/conversion"][1] == "uint32_to_float32"
manifest = json.loads(attrs["cryptomatte/3ae39a5/manifest"][1])
assert "floor" in manifest and all(re.fullmatch("[0-9a-f]{8}", v) for v in manifest.values())
for c in ("CryptoObject00.R", "CryptoObject00.G", "CryptoObject00.B", "CryptoObject00.A"):
    assert c in names, c
assert not any(n.startswith("visibility.") for n in names), "per-light channels with one light"

# Imath's row-vector matrices: p' = p M.
def matrix(name):
    v = [float(x) for x in attrs[name][1].split(",")]
    return [v[4 * i:4 * i + 4] for i in range(4)]
def apply(m, p):
    q = [sum((p + [1.0])[i] * m[i][j] for i in range(4)) for j in range(4)]
    return q
ndc, cam = matrix("worldToNDC"), matrix("worldToCamera")

width, height = 64, 48
index = {n: i for i, n in enumerate(names)}
worst, checked, background = 0.0, 0, 0
for line in open(sys.argv[2]):
    m = re.match(r"\s*Pixel \((\d+), (\d+)\): (.*)", line)
    if not m:
        continue
    x, y = int(m.group(1)), int(m.group(2))
    v = [float(t) for t in m.group(3).split()]
    if v[index["A"]] == 0:
        assert v[index["Z"]] == float("inf"), f"Z at background ({x}, {y}) is {v[index['Z']]}"
        assert v[index["CryptoObject00.G"]] == 0
        background += 1
        continue
    p = [v[index["P.X"]], v[index["P.Y"]], v[index["P.Z"]]]
    q = apply(ndc, p)
    px, py = q[0] / q[3] * width - 0.5, q[1] / q[3] * height - 0.5
    worst = max(worst, abs(px - x), abs(py - y))
    c = apply(cam, p)
    assert abs(c[2] - v[index["Z"]]) < 1e-3 * v[index["Z"]], (x, y, c[2], v[index["Z"]])
    assert v[index["CryptoObject00.G"]] == 1
    checked += 1
assert checked > 1000 and background > 0, (checked, background)
assert worst < 0.01, f"P reprojects {worst} px from its pixel"
print(f"reprojection: {checked} pixels, worst {worst:.5f} px")
PY

# Two lights: visibility.0 and visibility.1 beside visibility.
"$PENUMBRA" render "$PENUMBRA_SOURCE_DIR/tests/data/gl/two_lights.json" -t hard --size 64x48 \
    -o two.exr --quiet
oiiotool --info:format=xml -v two.exr | sed -n '/^<ImageSpec/,$p' >two.xml
oiiotool --dumpdata two.exr >two.txt
python3 - two.xml two.txt <<'PY' || fail "per-light visibility"
import re, sys, xml.etree.ElementTree as ET
names = [c.text for c in ET.parse(sys.argv[1]).getroot().iter("channelname")]
assert "visibility.0" in names and "visibility.1" in names and "visibility.2" not in names, names
i, a, b = names.index("visibility"), names.index("visibility.0"), names.index("visibility.1")
shadowed = 0
for line in open(sys.argv[2]):
    m = re.match(r"\s*Pixel \((\d+), (\d+)\): (.*)", line)
    if not m:
        continue
    v = [float(t) for t in m.group(3).split()]
    # The irradiance-weighted mean of the lights' visibilities lies between them.
    assert min(v[a], v[b]) - 1e-4 <= v[i] <= max(v[a], v[b]) + 1e-4, (m.group(1), m.group(2), v[i], v[a], v[b])
    assert 0 <= v[a] <= 1 and 0 <= v[b] <= 1
    shadowed += min(v[a], v[b]) < 0.5
assert shadowed > 0, "no pixel is shadowed from either light"
PY
# The lights a technique makes of an environment get no channel of their own (`reference`'s
# env_samples would be hundreds): the two scene lights keep theirs.
python3 - "$PENUMBRA_SOURCE_DIR/tests/data/gl" <<'PY' >two_env.json
import json, os, sys
scene = json.load(open(os.path.join(sys.argv[1], "two_lights.json")))
scene["environment"] = {"image": os.path.join(sys.argv[1], "sky_sun.exr"), "intensity": 1.0}
print(json.dumps(scene))
PY
"$PENUMBRA" render two_env.json -t reference --size 32x24 -o two_env_render.exr --quiet \
    -D technique.samples=2 -D technique.env_samples=16
names=$(oiiotool --info:format=xml -v two_env_render.exr | grep -o '<channelname>visibility[^<]*' |
    sed 's/<channelname>//' | tr '\n' ' ')
[ "$names" = "visibility visibility.0 visibility.1 " ] ||
    fail "per-light channels with an environment: $names"
echo "exr_attributes ok"
