# bitmask's image budget map (technique.budget_map): listed by `techniques`, read relative to
# the scene file, and every bad file refused with one line naming the key and the path, exit 2,
# nothing written.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
# (grep without -q reads to the end: -q stops at the match, and with pipefail the writer's
# SIGPIPE on the longer list failed the line)
"$PENUMBRA" techniques bitmask | grep "^  budget_map " >/dev/null ||
    fail "techniques bitmask lists budget_map"

# A copy of the small scene with the shipped example map beside it.
cp "$DATA/small.json" scene.json
cp "$PENUMBRA_SOURCE_DIR/scenes/budget_ramp.png" ramp.png
render=("$PENUMBRA" render scene.json -t bitmask -f 1 -D technique.map_size=256)
"${render[@]}" -D technique.budget_map=ramp.png -o good.exr --quiet || fail "render with budget_map"
python3 -c 'import json,sys; p=json.load(open(sys.argv[1]))["params"]; assert p["budget_map"] == "ramp.png", p' \
    good.json

bad() {  # bad FILE PATTERN: the render with FILE as budget map is refused with PATTERN
    expect_exit 2 "^penumbra: technique\.budget_map: .*$2" -- \
        "${render[@]}" -D "technique.budget_map=$1" -o bad.exr
    [ "$(wc -l <"$WORK/stderr")" -eq 1 ] || fail "more than one line for $1"
    [ ! -e bad.exr ] && [ ! -e bad.json ] || fail "a refused render left output ($1)"
}
bad missing.png "missing.png: no such file"
bad ramp.jpg "ramp.jpg: expected a .png or .exr image"
echo "not a png" >text.png
bad text.png "text.png: cannot read image"
mkdir folder.png
bad folder.png "folder.png: is a folder"
[ -z "$(ls -A | grep '\.tmp$' || true)" ] || fail "temporary files left behind"
echo "budget_map ok"
