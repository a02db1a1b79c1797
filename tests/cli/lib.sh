# Shared helpers for the CLI tests (sourced, not a test): a scratch folder, the binary, and
# expectations on exit codes and messages.
set -euo pipefail
: "${PENUMBRA:?set PENUMBRA to the penumbra binary}"
: "${PENUMBRA_SOURCE_DIR:?set PENUMBRA_SOURCE_DIR to the source tree}"
DATA="$PENUMBRA_SOURCE_DIR/tests/data/cli"
WORK=$(mktemp -d "${PENUMBRA_TEST_TMP:-/tmp}/cli.XXXXXX" 2>/dev/null || mktemp -d)
trap 'rm -rf "$WORK"' EXIT

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
