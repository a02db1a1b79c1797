# scripts/conformance-diff: two conformance results compared scene by scene (better first, the
# counts, medians and worst), and its refusals, each one line naming the argument or file.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
diff_=("$PENUMBRA_SOURCE_DIR/scripts/conformance-diff")
mkdir before after
cat >before/results.csv <<'CSV'
scene,run,floor_mae,receiver_mae,all_mae,beauty_error,frame_ms
a,ssm,0.01,0.0200,0.02,0.001,5
b,ssm,0.01,0.0100,0.01,0.001,5
c,ssm,0.01,0.0050,0.01,0.001,5
a,css,0.01,0.0300,0.03,nan,5
CSV
cat >after/results.csv <<'CSV'
scene,run,floor_mae,receiver_mae,all_mae,beauty_error,frame_ms
a,ssm,0.01,0.0100,0.02,0.001,5
b,ssm,0.01,0.0120,0.01,0.001,5
c,ssm,0.01,0.0050,0.01,0.001,5
a,hard,0.01,0.3,0.3,0.1,5
CSV
out=$("${diff_[@]}" before after) || fail "two folders"
echo "$out" | grep -q "^ssm:" || fail "the run both hold is compared: $out"
! echo "$out" | grep -qE "^(css|hard):" || fail "a run of one side only is left out: $out"
first=$(echo "$out" | grep -E "^  [abc] " | head -1)
[[ "$first" == *"a "*"0.0200 -> 0.0100 (-0.0100)"* ]] || fail "better first: $first"
echo "$out" | grep -q "b .*0.0100 -> 0.0120 (+0.0020)" || fail "the worse scene: $out"
! echo "$out" | grep -qE "^  c " || fail "an unchanged scene is not listed: $out"
summary="3 scenes: better 1, worse 1, unchanged 1; median 0.0100 -> 0.0100; worst 0.0200 (a)"
echo "$out" | grep -qF "$summary -> 0.0120 (b)" || fail "the summary line: $out"
# A change within --min is unchanged; files work as well as folders.
"${diff_[@]}" before/results.csv after/results.csv --min 0.005 |
    grep -q "better 1, worse 0, unchanged 2" || fail "--min 0.005"
"${diff_[@]}" before after --metric floor_mae | grep -q "better 0, worse 0, unchanged 3" ||
    fail "--metric floor_mae"

expect_exit 2 "--metric: 'nope' is not one of" -- "${diff_[@]}" before after --metric nope
expect_exit 2 "--runs: 'css' is not a run of both results" -- "${diff_[@]}" before after --runs css
expect_exit 2 "missing: No such file" -- "${diff_[@]}" missing after
echo "scene,x" >bad.csv
expect_exit 2 "bad.csv: not a conformance results.csv with column 'receiver_mae'" -- \
    "${diff_[@]}" bad.csv after
echo "conformance_diff ok"
