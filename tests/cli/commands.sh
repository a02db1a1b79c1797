# Every command answers --help; techniques and info print text and valid JSON.
source "$(dirname "$0")/lib.sh"
for cmd in render compare techniques info contact-sheet; do
    "$PENUMBRA" "$cmd" --help | grep -q "usage: penumbra $cmd" || fail "$cmd --help"
done
"$PENUMBRA" --help | grep -q "usage: penumbra" || fail "penumbra --help"
# grep without -q reads the whole listing: with -q it exits at the match, and once the listing
# passes one 4 KiB stdio buffer the writer dies of SIGPIPE, which pipefail reports.
"$PENUMBRA" techniques | grep "^reference:" >/dev/null || fail "techniques lists reference"
"$PENUMBRA" techniques --json | python3 -c '
import json, sys
ts = {t["name"]: t for t in json.load(sys.stdin)}
assert {"hard", "reference"} <= set(ts), ts.keys()
for t in ts.values():
    for p in t["params"]:
        assert {"key", "type", "default", "doc"} <= set(p), p
samples = [p for p in ts["reference"]["params"] if p["key"] == "samples"][0]
assert samples["range"] == [1, 32], samples
'
"$PENUMBRA" techniques hard --json | python3 -c 'import json,sys; assert json.load(sys.stdin)["name"] == "hard"'
expect_exit 2 "unknown technique" -- "$PENUMBRA" techniques nope
"$PENUMBRA" info | grep -q "^chosen: " || fail "info"
"$PENUMBRA" info --json | python3 -c '
import json, sys
i = json.load(sys.stdin)
assert i["chosen"]["version"] and i["chosen"]["renderer"] and i["tried"], i
'
echo "commands ok"
