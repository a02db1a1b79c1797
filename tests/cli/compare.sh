#!/usr/bin/env bash
# `penumbra compare` end to end: every exit code (0 pass, 1 warn, 2 fail, 3 cannot compare,
# 4 file error, 5 bad command line), --json, --no-fail, --diff (.exr, .png) and --help.
set -euo pipefail

: "${PENUMBRA:?set PENUMBRA to the penumbra binary}"
: "${PENUMBRA_TEST_TMP:?set PENUMBRA_TEST_TMP to a scratch folder}"
command -v oiiotool >/dev/null || { echo "compare.sh: oiiotool is required" >&2; exit 1; }
command -v python3 >/dev/null || { echo "compare.sh: python3 is required" >&2; exit 1; }
PENUMBRA=$(realpath "$PENUMBRA")

mkdir -p "$PENUMBRA_TEST_TMP"
T=$(mktemp -d "$PENUMBRA_TEST_TMP/compare.XXXXXX")
trap 'rm -rf "$T"' EXIT
cd "$T"

failures=0
fail() {
    echo "FAIL: $*" >&2
    failures=$((failures + 1))
}

# run EXPECTED_EXIT ARGS...: runs `penumbra compare ARGS`, keeping stdout and stderr in
# out.txt and err.txt, and checks the exit status.
run() {
    local expected=$1
    shift
    local rc=0
    "$PENUMBRA" compare "$@" >out.txt 2>err.txt || rc=$?
    if [[ $rc -ne $expected ]]; then
        fail "compare $* exited $rc, expected $expected"
        sed 's/^/  stdout: /' out.txt >&2
        sed 's/^/  stderr: /' err.txt >&2
    fi
}

# expect_in FILE TEXT: FILE contains TEXT.
expect_in() {
    grep -qF -- "$2" "$1" || fail "$1 lacks '$2': $(head -c 400 "$1")"
}

# --- Test images (32x32 unless said otherwise) ---
oiiotool --pattern constant:color=0.5,0.5,0.5 32x32 3 -o a.exr
cp a.exr same.exr
oiiotool --pattern constant:color=0.52,0.5,0.5 32x32 3 -o off.exr  # R off by 0.02 everywhere
# 16 of 1024 pixels (1.5625 %) off by 0.4 in every channel.
oiiotool a.exr --box:color=0.9,0.9,0.9:fill=1 0,0,3,3 -o box.exr
oiiotool --pattern constant:color=0.5,0.5,0.5 16x16 3 -o small.exr
oiiotool --pattern constant:color=0.5,0.5,0.5,0.7 32x32 4 --chnames R,G,B,visibility -o vis.exr
oiiotool --pattern constant:color=0.5,0.5,0.5,0.75 32x32 4 --chnames R,G,B,visibility -o vis2.exr
echo "not an image" >text.exr
cp box.exr truncated.exr
truncate -s 300 truncated.exr

# --- 0: pass ---
run 0 a.exr same.exr
expect_in out.txt PASS
expect_in out.txt '"a.exr"'
run 0 a.exr off.exr --fail 0.1 --warn 0.1
run 0 a.exr box.exr --fail 0.5 --warn 0.45
run 0 a.exr box.exr --fail 0.1 --failpercent 2 --warn 0.1 --warnpercent 2
run 0 a.exr off.exr --channels G,B
run 0 a.exr vis.exr --fail 0 --warn 0  # the test image may have extra channels

# --- 1: warn ---
run 1 a.exr off.exr --fail 0.1 --warn 0.01
expect_in out.txt WARNING
run 1 a.exr off.exr -fail 0.1 -warn 0.01  # idiff's spellings
run 1 a.exr box.exr --fail=0.5 --warn=0.1 --warnpercent=1

# --- 2: fail ---
run 2 a.exr off.exr
expect_in out.txt FAILURE
run 2 a.exr box.exr --fail 0.1 --failpercent 1
expect_in out.txt "16 pixels"
run 2 a.exr off.exr --fail 0.1 --warn 0.1 --hardfail 0.01
run 2 a.exr box.exr -fail 1 -failpercent 100 -hardfail 0.3

# --- 3: size or channel mismatch ---
run 3 a.exr small.exr
expect_in err.txt "penumbra: compare:"
expect_in err.txt "32x32"
expect_in err.txt "16x16"
run 3 vis.exr a.exr  # every reference channel must be in the test image
expect_in err.txt "a.exr"
expect_in err.txt "visibility"
run 3 a.exr same.exr --channels R,Z
expect_in err.txt "'Z'"
run 3 a.exr same.exr --ids 0  # --ids needs the reference's `id` channel
expect_in err.txt "'id'"
oiiotool --pattern constant:color=0.5,0.5,0.5,2 32x32 4 --chnames R,G,B,id -o ids.exr
run 0 ids.exr ids.exr --ids 2
run 3 ids.exr ids.exr --ids 0,1  # a selection of no pixel cannot be compared
expect_in err.txt "penumbra: compare: ids.exr: --ids 0,1 selects no pixel"
[[ ! -s out.txt ]] || fail "--ids selecting nothing printed: $(cat out.txt)"

# --- 4: unreadable ---
run 4 missing.exr a.exr
expect_in err.txt "penumbra: compare: missing.exr:"
run 4 a.exr missing.exr
expect_in err.txt "penumbra: compare: missing.exr:"
run 4 a.exr text.exr
expect_in err.txt "penumbra: compare: text.exr:"
run 4 truncated.exr a.exr
expect_in err.txt "penumbra: compare: truncated.exr:"

# --- bad command lines: 5 (not idiff's 2, a failure), one line naming the flag ---
run 5 a.exr same.exr --bogus
expect_in err.txt "--bogus"
run 5 a.exr same.exr --fail abc
expect_in err.txt "--fail"
run 5 a.exr same.exr --failpercent 150
expect_in err.txt "--failpercent"
run 5 a.exr same.exr --warn -1
expect_in err.txt "--warn"
run 5 a.exr same.exr --hardfail
expect_in err.txt "--hardfail"
run 5 a.exr same.exr --channels R,,G
expect_in err.txt "--channels"
run 5 a.exr same.exr --ids 1,one
expect_in err.txt "--ids"
run 5 a.exr same.exr --ids 1,1
expect_in err.txt "--ids"
run 5 a.exr same.exr --diff d.tif
expect_in err.txt "penumbra: compare: --diff: 'd.tif' must end in .exr or .png"
run 5 a.exr same.exr --diff-scale 0 --diff d.png
expect_in err.txt "--diff-scale"
run 5 a.exr same.exr --diff-scale 1 --diff d.exr
expect_in err.txt "--diff-scale: needs a --diff OUT.png"
# diff_overwrites_input: `--diff` onto REF replaced a CI job's golden image with the difference.
cp a.exr golden.exr && mkdir -p sub
run 5 golden.exr same.exr --diff ./golden.exr
expect_in err.txt "penumbra: compare: --diff: './golden.exr' is REF; writing the difference there"
run 5 same.exr golden.exr --diff sub/../golden.exr
expect_in err.txt "--diff: 'sub/../golden.exr' is TEST; "
if ! cmp -s a.exr golden.exr; then
    echo "FAIL: a refused --diff changed its input" >&2
    failures=$((failures + 1))
fi
run 5 a.exr
run 5 a.exr same.exr third.exr
expect_in err.txt "third.exr"
for f in err.txt; do
    [[ $(wc -l <"$f") -eq 1 ]] || fail "bad-flag message is not one line: $(cat "$f")"
done

# --- --help ---
run 0 --help
expect_in out.txt "usage: penumbra compare"
expect_in out.txt "--failpercent"
run 0 a.exr missing.exr --help

# --- --json: only the JSON object on stdout, exit code still the verdict ---
run 2 vis.exr vis2.exr --json
python3 -c 'import json,sys; json.load(sys.stdin)' <out.txt || fail "--json output does not parse"
python3 - out.txt <<'EOF' || fail "--json content"
import json, sys
j = json.load(open(sys.argv[1]))
assert j["verdict"] == "fail", j["verdict"]
assert j["channels"] == ["R", "G", "B", "visibility"], j["channels"]
assert abs(j["max"] - 0.05) < 1e-6, j["max"]
assert j["max_channel"] == "visibility", j["max_channel"]
assert j["shadow_pixels"] == 1024, j["shadow_pixels"]
assert abs(j["shadow_mae"] - 0.05) < 1e-6, j["shadow_mae"]
assert j["fail_pixels"] == 1024 and j["fail_fraction"] == 1.0
for key in ("mae", "rmse", "p99", "warn_fraction", "per_channel", "thresholds", "reference", "test"):
    assert key in j, key
EOF
run 1 a.exr off.exr --json --fail 0.1 --warn 0.01
python3 -c 'import json,sys; assert json.load(sys.stdin)["verdict"] == "warn"' <out.txt ||
    fail "--json verdict warn"
run 0 a.exr same.exr --json
python3 -c 'import json,sys; j = json.load(sys.stdin); assert j["verdict"] == "pass" and j["shadow_mae"] is None' <out.txt ||
    fail "--json verdict pass"

# --- --diff: written even when the comparison fails, atomically ---
run 2 a.exr box.exr --diff out/diff.exr
[[ -f out/diff.exr ]] || fail "--diff did not write out/diff.exr"
[[ $(ls -A out) == diff.exr ]] || fail "--diff left other files: $(ls -A out)"
oiiotool out/diff.exr --printstats >stats.txt 2>&1 || fail "oiiotool cannot read the diff image"
expect_in stats.txt "Stats Max: 0.400000 0.400000 0.400000"
run 0 a.exr same.exr --diff out/same.exr --json
[[ -f out/same.exr ]] || fail "--diff did not write out/same.exr"
python3 -c 'import json,sys; assert json.load(sys.stdin)["diff"] == "out/same.exr"' <out.txt ||
    fail "--json lacks the diff path"
mkdir -p out/taken.exr/inside
run 4 a.exr same.exr --diff out/taken.exr  # cannot write: a file error, never a verdict
expect_in err.txt "out/taken.exr"

# --- --diff OUT.png: a heatmap with a colour bar below, scaled to the max or --diff-scale ---
run 2 a.exr box.exr --diff heat.png
expect_in out.txt "Heatmap heat.png: white = 0.4"
oiiotool --info heat.png >heat.txt 2>&1 || fail "oiiotool cannot read heat.png"
expect_in heat.txt "32 x   40"  # 32 rows of image, 2 of gap, 6 of colour bar
# The box's pixels (0.4, the max) are white-ish; the rest (0) black; the bar ends white.
oiiotool heat.png --crop 1x1+0+0 -o box_px.exr && oiiotool box_px.exr --printstats >s1.txt 2>&1
expect_in s1.txt "Stats Min: 1.000000 1.000000"
oiiotool heat.png --crop 1x1+20+20 -o zero_px.exr && oiiotool zero_px.exr --printstats >s2.txt 2>&1
expect_in s2.txt "Stats Max: 0.000000 0.000000"
run 2 a.exr box.exr --diff heat8.png --diff-scale 0.8 --json
python3 -c 'import json,sys; j = json.load(sys.stdin); assert j["diff"] == "heat8.png" and j["diff_scale"] == 0.8, j' <out.txt ||
    fail "--json lacks diff_scale"
cmp -s heat.png heat8.png && fail "--diff-scale 0.8 drew the same heatmap as 0.4"

# --- --no-fail: metrics only, exit 0 whatever the verdict, unless it cannot compare ---
run 0 a.exr off.exr --no-fail
expect_in out.txt FAILURE
run 0 a.exr off.exr --no-fail --json
python3 -c 'import json,sys; assert json.load(sys.stdin)["verdict"] == "fail"' <out.txt ||
    fail "--no-fail --json verdict"
run 3 a.exr small.exr --no-fail
run 4 a.exr missing.exr --no-fail

# --- --json when it cannot compare: a JSON object with `error` and `exit`, nothing else ---
json_error() {  # json_error CODE: stdout is one JSON object with that exit and an error
    python3 -c 'import json, sys
j = json.load(open("out.txt"))
assert j["exit"] == int(sys.argv[1]) and j["error"].startswith("compare: "), j' "$1" ||
        fail "--json error object: $(cat out.txt)"
}
run 3 a.exr small.exr --json
json_error 3
expect_in out.txt "size mismatch"
run 4 a.exr missing.exr --json
json_error 4
run 3 ids.exr ids.exr --ids 7 --json
json_error 3
run 5 a.exr same.exr --json --fail x
json_error 5
[[ $(wc -l <err.txt) -eq 1 ]] || fail "usage error with --json is not one line on stderr"

if [[ $failures -ne 0 ]]; then
    echo "compare.sh: $failures check(s) failed" >&2
    exit 1
fi
echo "compare.sh: all checks passed"
