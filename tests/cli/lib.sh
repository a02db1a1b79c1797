# Shared helpers for the CLI tests (sourced, not a test): a scratch folder, the binary, and
# expectations on exit codes and messages.
set -euo pipefail
: "${PENUMBRA:?set PENUMBRA to the penumbra binary}"
: "${PENUMBRA_SOURCE_DIR:?set PENUMBRA_SOURCE_DIR to the source tree}"
DATA="$PENUMBRA_SOURCE_DIR/tests/data/cli"
WORK=$(mktemp -d "${PENUMBRA_TEST_TMP:-/tmp}/cli.XXXXXX" 2>/dev/null || mktemp -d)
trap 'rm -rf "$WORK"' EXIT
# penumbra sweep's shared reference cache ($XDG_CACHE_HOME/penumbra/references): per test, never
# the user's. Mesa's shader cache and matplotlib's stay where they were (cold, they cost about
# 1.3 s and 0.6 s a process).
user_cache=${XDG_CACHE_HOME:-${HOME:-/tmp}/.cache}
mkdir -p "$user_cache" 2>/dev/null || true  # Mesa makes only the last folder of its cache's path
export MESA_SHADER_CACHE_DIR="${MESA_SHADER_CACHE_DIR:-$user_cache/mesa_shader_cache}"
export MPLCONFIGDIR="${MPLCONFIGDIR:-$user_cache/matplotlib}"
export XDG_CACHE_HOME="$WORK/xdg-cache"

fail() { echo "FAIL: $*" >&2; exit 1; }

# expect_exit CODE PATTERN -- COMMAND...: runs COMMAND, checks its exit code and that stderr
# matches the extended regex PATTERN (empty: anything).
expect_exit() {
    local want=$1 pattern=$2
    shift 3
    local rc=0
    "$@" >"$WORK/stdout" 2>"$WORK/stderr" || rc=$?
    if [ "$rc" -ne "$want" ]; then
        cat "$WORK/stderr" >&2
        fail "expected exit $want, got $rc: $*"
    fi
    if [ -n "$pattern" ] && ! grep -Eq -- "$pattern" "$WORK/stderr"; then
        cat "$WORK/stderr" >&2
        fail "stderr does not match /$pattern/: $*"
    fi
    if [ "$want" -ne 0 ] && [ "$(wc -l <"$WORK/stderr")" -lt 1 ]; then
        fail "no message for a failure: $*"
    fi
}

# write_triangle_gltf FILE.gltf BUFFER_URI [BIN]: a one-triangle glTF whose buffer is BUFFER_URI
# (written as BIN, 36 bytes, when given).
write_triangle_gltf() {
    python3 - "$@" <<'PY'
import json, struct, sys
gltf, uri = sys.argv[1], sys.argv[2]
data = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
if len(sys.argv) > 3:
    open(sys.argv[3], "wb").write(data)
json.dump({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
           "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                          "min": [0, 0, 0], "max": [1, 1, 0]}],
           "bufferViews": [{"buffer": 0, "byteLength": 36}],
           "buffers": [{"uri": uri, "byteLength": 36}]}, open(gltf, "w"))
PY
}

# write_scene_with_gltf SCENE.json GLTF: tests/data/cli/small.json, still, with GLTF as an object.
write_scene_with_gltf() {
    python3 - "$DATA/small.json" "$@" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
del scene["animation"]
scene["objects"].append({"name": "asset", "gltf": sys.argv[3]})
json.dump(scene, open(sys.argv[2], "w"))
PY
}
