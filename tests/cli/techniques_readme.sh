# The README's parameter tables and lists agree with `penumbra techniques NAME --json`: a table
# (| parameter | default | ... |, under a heading naming the technique) has every key of the
# technique once, each default as the table has it, every choice of an enum in its row, and a
# range as the table states it; a list ("Parameters (`penumbra techniques NAME`): ...") names
# every key. A row or key the technique does not have fails too.
source "$(dirname "$0")/lib.sh"
"$PENUMBRA" techniques --json >"$WORK/techniques.json"
python3 - "$PENUMBRA_SOURCE_DIR/README.md" "$WORK/techniques.json" <<'PY'
import json, re, sys

readme = open(sys.argv[1], encoding="utf-8").read().split("\n")
techniques = {t["name"]: {p["key"]: p for p in t["params"]} for t in json.load(open(sys.argv[2]))}
problems = []


def same_default(text, spec):
    text = text.strip()
    value = spec["default"]
    if text.startswith("`") and text.endswith("`"):
        text = text[1:-1]
    if spec["type"] in ("enum", "string"):
        return text == ('""' if value == "" else value)
    if spec["type"] == "bool":
        return text == ("true" if value else "false")
    try:
        return float(text) == float(value)
    except ValueError:
        return False


def check_table(name, rows, line):
    params = techniques[name]
    header = [c.strip() for c in rows[0].strip("|").split("|")]
    seen = []
    for row in rows[2:]:
        cells = [c.strip() for c in row.strip("|").split("|")]
        cell = dict(zip(header, cells))
        keys = re.findall(r"`([a-z0-9_]+)`", cell["parameter"])
        defaults = [d.strip() for d in cell.get("default", "").split(",")]
        if "default" in cell and len(defaults) != len(keys):
            problems.append(f"README.md:{line}: {name}: row {keys}: {len(keys)} keys, "
                            f"{len(defaults)} defaults")
            continue
        for i, key in enumerate(keys):
            seen.append(key)
            spec = params.get(key)
            if spec is None:
                problems.append(f"README.md:{line}: {name}: `{key}` is no parameter of it")
                continue
            if "default" in cell and not same_default(defaults[i], spec):
                problems.append(f"README.md:{line}: {name}.{key}: default {defaults[i]}, but "
                                f"`penumbra techniques` says {json.dumps(spec['default'])}")
            if "range" in cell and "range" in spec:
                nums = [float(x) for x in re.findall(r"-?[0-9.]+(?:e-?[0-9]+)?", cell["range"])]
                if nums[:2] != [float(x) for x in spec["range"]]:
                    problems.append(f"README.md:{line}: {name}.{key}: range {cell['range']}, but "
                                    f"`penumbra techniques` says {spec['range']}")
            if len(keys) == 1 and "choices" in spec:
                named = set(re.findall(r"`([^`]+)`", row))
                missing = [c for c in spec["choices"] if c not in named]
                if missing:
                    problems.append(f"README.md:{line}: {name}.{key}: choices {missing} missing")
    for key in params:
        if seen.count(key) != 1:
            problems.append(f"README.md:{line}: {name}: `{key}` listed {seen.count(key)} times")


def check_list(name, text, line):
    named = set(re.findall(r"`([a-z0-9_]+)`", text))
    for key in techniques[name]:
        if key not in named:
            problems.append(f"README.md:{line}: {name}: the parameter list lacks `{key}`")


heading_technique = None
checked = 0
i = 0
while i < len(readme):
    text = readme[i]
    if text.startswith("#"):
        found = [n for n in re.findall(r"`([a-z]+)`", text) if n in techniques]
        heading_technique = found[0] if found else None
    m = re.match(r"Parameters \(`penumbra techniques ([a-z]+)`\):", text)
    if m:
        start = i
        while i < len(readme) and readme[i].strip():
            i += 1
        check_list(m.group(1), "\n".join(readme[start:i]), start + 1)
        checked += 1
        continue
    if re.match(r"\|\s*parameter\s*\|", text):
        if heading_technique is None:
            problems.append(f"README.md:{i + 1}: a parameter table under no technique's heading")
        start = i
        while i < len(readme) and readme[i].startswith("|"):
            i += 1
        if heading_technique:
            check_table(heading_technique, readme[start:i], start + 1)
            checked += 1
        continue
    i += 1
if checked < 2:
    problems.append(f"README.md: found {checked} parameter tables or lists, expected css's and "
                    "bitmask's at least")
if problems:
    sys.exit("\n".join(problems))
print(f"{checked} README parameter tables and lists agree with `penumbra techniques`")
PY
