# First contact: "did you mean" everywhere, -D errors that name the flag, a glTF given as a
# scene, output extensions, frame numbers, unwritable folders; --version and --help everywhere.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
scene="$DATA/small.json"
anim="$DATA/anim6.json"
r=("$PENUMBRA" render "$scene" -f 1)

# Did you mean: flags, commands, techniques, parameters, scene keys, channels.
expect_exit 2 "^penumbra: render: unknown flag '--sise' \(did you mean --size\?" -- "${r[@]}" --sise 64x48
expect_exit 2 "^penumbra: rendr: unknown command \(did you mean render\?" -- "$PENUMBRA" rendr
expect_exit 2 "^penumbra: --technique: unknown technique 'hrad' \(did you mean 'hard'\?" -- "${r[@]}" -t hrad
expect_exit 2 "^penumbra: techniques: unknown technique 'hrad' \(did you mean 'hard'\?" -- "$PENUMBRA" techniques hrad
expect_exit 2 "^penumbra: -D technique.epslion: unknown parameter for technique 'adaptive' \(did you mean 'epsilon'\?" -- \
    "${r[@]}" -t adaptive -D technique.epslion=0.01
expect_exit 2 "^penumbra: -D techniqe.samples: unknown key 'techniqe' \(did you mean 'technique'\?" -- \
    "${r[@]}" -D techniqe.samples=3
expect_exit 2 "^penumbra: -D technique.pcf: expected an integer in 1\.\.15, got 0$" -- "${r[@]}" -D technique.pcf=0
sed 's/"fov_y"/"fov_u"/' "$scene" >typo.json
expect_exit 2 "^penumbra: typo.json: camera: unknown key 'fov_u' \(did you mean 'fov_y'\?" -- \
    "$PENUMBRA" render typo.json
"${r[@]}" -o a.exr --quiet
expect_exit 3 "reference has no channel 'visibilty' \(did you mean 'visibility'\?" -- \
    "$PENUMBRA" compare a.exr a.exr --channels visibilty
[ "$(wc -l <"$WORK/stderr")" -eq 1 ] || fail "more than one line for a bad channel"

# glTF flags on a scene file; wrong extensions; frames; folders. Nothing is written.
mkdir clean && cd clean
expect_exit 2 "^penumbra: render: --light-size: only for a .gltf/.glb model" -- \
    "$PENUMBRA" render "$scene" --light-size 1
expect_exit 2 "^penumbra: --output: x.png: the file name must end in .exr" -- "${r[@]}" -o x.png
expect_exit 2 "^penumbra: --preview: p.exr: the file name must end in .png" -- "${r[@]}" -o x.exr --preview p.exr
expect_exit 2 "^penumbra: --frames: frame -3 is negative" -- "$PENUMBRA" render "$scene" -f -3
expect_exit 2 "^penumbra: render: --frame-from-env: TASK=0 with --frame-offset -1 gives frame -1" -- \
    env TASK=0 "$PENUMBRA" render "$scene" --frame-from-env TASK --frame-offset -1
echo file >blocker
expect_exit 2 "^penumbra: --timings: blocker/t.json: 'blocker' is not a folder" -- \
    "${r[@]}" -o ok/x.exr --timings blocker/t.json
if [ "$(id -u)" -ne 0 ]; then
    mkdir ro && chmod 555 ro
    expect_exit 2 "^penumbra: --output: ro/x.exr: folder 'ro' is not writable" -- "${r[@]}" -o ro/x.exr
    rmdir ro
fi
expect_exit 2 "^penumbra: --output: /proc/x.exr: folder '/proc' is not writable" -- "${r[@]}" -o /proc/x.exr
rm blocker
[ -z "$(ls -A)" ] || fail "bad input left files: $(ls -A)"
cd ..
[ "$("$PENUMBRA" render "$scene" -f1-2 --list-frames | tr '\n' ' ')" = "1 2 " ] || fail "-f1-2 (attached value)"

# --version and --help everywhere; scripts answer --help without doing their work.
for cmd in render compare techniques info sweep fit-lights contact-sheet; do
    [[ "$("$PENUMBRA" "$cmd" --version)" == "penumbra "[0-9]* ]] || fail "$cmd --version"
done
for s in setup build demo sequence video; do
    [[ "$("$PENUMBRA_SOURCE_DIR/scripts/$s" --help)" == "usage: scripts/$s"* ]] || fail "scripts/$s --help"
done
expect_exit 2 "unknown flavour 'fast'" -- "$PENUMBRA_SOURCE_DIR/scripts/build" fast

# techniques: every parameter row's columns line up, however long a default is.
"$PENUMBRA" techniques >techniques.txt
python3 - techniques.txt <<'PY'
import re, sys
block = []
for line in open(sys.argv[1]).read().split("\n") + [""]:
    if line.startswith("  "):
        block.append(line)
        continue
    # key, type, "default X", range: the default and range columns start at one position
    starts = set()
    for l in block:
        m = re.match(r"(\s+\S+\s+\S+\s+)default \S+\s+", l)
        assert m, l
        starts.add((m.end(1), m.end()))
    assert len(starts) <= 1, f"misaligned rows: {block[:3]}"
    block = []
PY

# The man page and the completion come from the tables.
"$PENUMBRA" manpage >penumbra.1
grep -q '^\.SS render' penumbra.1 || fail "manpage lacks render"
grep -q 'technique.KEY' penumbra.1 || fail "manpage lacks render's --help"
"$PENUMBRA" completion bash >completion.bash
bash -n completion.bash || fail "completion is not bash"
grep -q 'render) flags="[^"]*--strict' completion.bash || fail "completion lacks --strict"
grep -q 'technique.epsilon=' completion.bash || fail "completion lacks parameters"

# A first render on a fresh account: the cache folder's parents are missing. Nothing on stderr
# (Mesa prints "Failed to create ... for shader cache" where its folder's parent is missing:
# the program cache's folder is made before the driver starts), and both caches exist after.
fresh="$WORK/fresh/deep/cache"
env -u MESA_SHADER_CACHE_DIR XDG_CACHE_HOME="$fresh" "${r[@]}" -o fresh.exr --quiet 2>fresh.err ||
    fail "a render with a missing cache folder"
[ ! -s fresh.err ] || fail "a render with a missing cache folder printed: $(cat fresh.err)"
[ -d "$fresh/penumbra/programs" ] || fail "the program cache folder was not made"
# With the program cache off, the same: the user's cache folder is made for Mesa's, no more.
off="$WORK/fresh-off/deep/cache"
env -u MESA_SHADER_CACHE_DIR XDG_CACHE_HOME="$off" PENUMBRA_PROGRAM_CACHE=0 "${r[@]}" \
    -o fresh-off.exr --quiet 2>fresh-off.err || fail "a render with the program cache off"
[ ! -s fresh-off.err ] || fail "a render with the program cache off printed: $(cat fresh-off.err)"
[ ! -e "$off/penumbra" ] || fail "the program cache off still made its folder"
