# docs/scene.schema.json against the loader: every shipped scene validates; each bad document
# below is refused by both the loader (exit 2) and the schema; good variants pass both; every
# key of the schema is documented in docs/scene-format.md.
source "$(dirname "$0")/lib.sh"
python3 -c 'import jsonschema' 2>/dev/null || fail "python3-jsonschema missing (scripts/setup)"
cd "$WORK"
python3 - "$PENUMBRA" "$PENUMBRA_SOURCE_DIR" "$DATA/small.json" <<'PY'
import copy, glob, json, os, re, subprocess, sys
import jsonschema
binary, src, small = sys.argv[1:4]
schema = json.load(open(os.path.join(src, "docs/scene.schema.json")))
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)

shipped = [f for f in glob.glob(os.path.join(src, "scenes/**/*.json"), recursive=True)]
assert len(shipped) >= 5, shipped
for f in shipped:
    errors = list(validator.iter_errors(json.load(open(f))))
    assert not errors, f"{f}: {errors[0].message}"

base = json.load(open(small))

# A glTF with a camera (assimp's Cameras.gltf) and one with a punctual light, for the
# {"gltf": ...} camera and light entries.
cameras = "/usr/share/assimp/models/glTF2/cameras/Cameras.gltf"
lit = json.load(open(cameras))
import base64
bin_bytes = open(os.path.join(os.path.dirname(cameras), lit["buffers"][0]["uri"]), "rb").read()
lit["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(bin_bytes).decode()
lit["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 5}]}}
lit["nodes"].append({"translation": [0, 3, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}})
lit["scenes"][0]["nodes"].append(len(lit["nodes"]) - 1)
lit_path = os.path.abspath("lit.gltf")

def loader(doc):
    path = "case.json"
    json.dump(doc, open(path, "w"))
    r = subprocess.run([binary, "render", path, "--list-frames"], capture_output=True, text=True)
    return r.returncode, r.stderr.strip()

def case(edit):
    doc = copy.deepcopy(base)
    edit(doc)
    return doc

def setter(path, value):
    def edit(doc):
        *parents, last = path
        node = doc
        for p in parents: node = node[p]
        if value is KeyError: del node[last]
        else: node[last] = value
    return edit

bad = {
    "unknown top-level key": setter(["techniqe"], {"name": "hard"}),
    "unknown camera key": setter(["camera", "fov"], 40),
    "fov_y 180": setter(["camera", "fov_y"], 180),
    "near 0": setter(["camera", "near"], 0),
    "image.samples 3": setter(["image", "samples"], 3),
    "image.width 0": setter(["image", "width"], 0),
    "image.width 1.5": setter(["image", "width"], 1.5),
    "light size 0": setter(["lights", 0, "size"], [0, 1]),
    "light colour < 0": setter(["lights", 0, "color"], [1, -1, 1]),
    "light intensity < 0": setter(["lights", 0, "intensity"], -1),
    "light type spot": setter(["lights", 0, "type"], "spot"),
    "light unknown key": setter(["lights", 0, "radius"], 1),
    "format wrong": setter(["format"], "penumbra-scene/2"),
    "format missing": setter(["format"], KeyError),
    "name with /": setter(["name"], "a/b"),
    "name ..": setter(["name"], ".."),
    "objects missing": setter(["objects"], KeyError),
    "objects empty": setter(["objects"], []),
    "object unknown key": setter(["objects", 1, "colour"], [1, 0, 0]),
    "object with no shape": setter(["objects", 1, "box"], KeyError),
    "object with two shapes": setter(["objects", 1, "sphere"], {"radius": 1}),
    "box size < 0": setter(["objects", 1, "box", "size"], [1, -1, 1]),
    "plane unknown key": setter(["objects", 0, "plane", "width"], 2),
    "shadow role": setter(["objects", 0, "shadow"], "caster"),
    "base_color > 1": setter(["objects", 1, "material"], {"base_color": [2, 0, 0]}),
    "base_color 2 numbers": setter(["objects", 1, "material"], {"base_color": [1, 0]}),
    "material unknown key": setter(["objects", 1, "material"], {"roughness": 0.5}),
    "transform and matrix": setter(["objects", 1, "matrix"], [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]),
    "scale 0": setter(["objects", 1, "transform", "scale"], 0),
    "rotate 2 numbers": setter(["objects", 1, "transform", "rotate"], [0, 1]),
    "sphere segments 2": lambda d: d["objects"].append({"sphere": {"segments": 2}}),
    "technique without name": setter(["technique"], {"map_size": 256}),
    "environment without image": setter(["environment"], {"intensity": 1}),
    "animation unknown key": setter(["animation", "loop"], True),
    "track without keys": setter(["animation", "tracks", 0, "keys"], KeyError),
    "track of the animation": setter(["animation", "tracks", 0, "key"], "animation.frames"),
    "track with no keys": setter(["animation", "tracks", 0, "keys"], []),
    "gltf camera with a camera key": setter(["camera"], {"gltf": cameras, "fov_y": 30}),
    "gltf camera index and name": setter(["camera"], {"gltf": cameras, "index": 0, "name": "a"}),
    "gltf camera index -1": setter(["camera"], {"gltf": cameras, "index": -1}),
    "gltf camera index 0.5": setter(["camera"], {"gltf": cameras, "index": 0.5}),
    "gltf camera empty path": setter(["camera"], {"gltf": ""}),
    "camera index without gltf": setter(["camera", "index"], 0),
    "gltf lights unknown key": lambda d: d["lights"].append({"gltf": lit_path, "sise": [1, 1]}),
    "gltf lights size 0": lambda d: d["lights"].append({"gltf": lit_path, "size": [0, 1]}),
    "gltf lights with a rect key": lambda d: d["lights"].append({"gltf": lit_path, "intensity": 3}),
}
json.dump(lit, open(lit_path, "w"))
for name, edit in bad.items():
    doc = case(edit)
    rc, message = loader(doc)
    assert rc == 2 and message.startswith("penumbra: "), f"{name}: loader exit {rc}: {message}"
    assert "\n" not in message, f"{name}: more than one line: {message}"
    assert list(validator.iter_errors(doc)), f"{name}: the schema accepts what the loader refuses ({message})"

def use_matrix(doc):
    crate = doc["objects"][1]
    del crate["transform"]
    crate["matrix"] = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0.6, 0, 1]

good = {
    "as shipped": lambda d: None,
    "scale per axis": setter(["objects", 1, "transform", "scale"], [1, 2, 0.5]),
    "base_color RGBA": setter(["objects", 1, "material"], {"base_color": [1, 0.5, 0, 1]}),
    "matrix": use_matrix,
    "sphere defaults": lambda d: d["objects"].append({"sphere": {}}),
    "samples 4": setter(["image", "samples"], 4),
    "no name": setter(["name"], KeyError),
    "gltf camera": setter(["camera"], {"gltf": cameras}),
    "gltf camera by index": setter(["camera"], {"gltf": cameras, "index": 0}),
    "gltf lights": lambda d: d["lights"].append({"gltf": lit_path, "size": [0.5, 0.25]}),
    "gltf lights, default size": lambda d: d["lights"].append({"gltf": lit_path}),
}
for name, edit in good.items():
    doc = case(edit)
    rc, message = loader(doc)
    assert rc == 0, f"{name}: the loader refuses: {message}"
    errors = list(validator.iter_errors(doc))
    assert not errors, f"{name}: the schema refuses: {errors[0].message}"

# Every property the schema names is documented.
doc_text = open(os.path.join(src, "docs/scene-format.md")).read()
def names(node):
    if isinstance(node, dict):
        for k, v in node.get("properties", {}).items():
            yield k
        for v in node.values():
            yield from names(v)
    elif isinstance(node, list):
        for v in node: yield from names(v)
missing = sorted({n for n in names(schema) if f"`{n}`" not in doc_text})
assert not missing, f"docs/scene-format.md does not document: {missing}"
print(f"schema: {len(shipped)} shipped scenes valid, {len(bad)} bad cases refused by both, {len(good)} good ones accepted")
PY
