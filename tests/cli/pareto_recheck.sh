# scripts/pareto-recheck: the equal-error ratio at the defaults of a pareto run, re-timed with the
# technique and reference's bracketing N alternated. A stand-in binary with fixed frame times
# checks the arithmetic (the bracket from the run's errors, time interpolated by the error's
# share); the real one, that it runs; bad arguments exit 2 with one line naming them.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
recheck=("$PENUMBRA_SOURCE_DIR/scripts/pareto-recheck")
scene="$PENUMBRA_SOURCE_DIR/scenes/default.json"
mkdir -p run
# reference's front: N = 1 error 0.10, N = 2 0.02 (N = 3 slower and no better: off the front);
# hard at its defaults has 0.05: 5/8 of the way from N = 1 to 2.
cat >run/pareto.json <<'JSON'
{"size": "32x24", "reference_fronts": {"default": [[1, 0.10, 10.0], [2, 0.02, 40.0],
  [3, 0.03, 90.0]]},
 "rows": [{"scene": "default", "technique": "hard", "defaults": true, "error": 0.05,
           "ratio": 0.5}]}
JSON
# Frame times: hard 20 ms, reference N = 1 10 ms, N = 2 42 ms: reference at 0.05 is
# 10 + 5/8 x 32 = 30 ms, the ratio 0.67.
cat >fixed <<'WRAP'
#!/usr/bin/env bash
out= ms=20
while [ $# -gt 0 ]; do
    case $1 in
        -o) out=$2; shift ;;
        technique.samples=1) ms=10 ;;
        technique.samples=2) ms=42 ;;
    esac
    shift
done
echo "{\"totals\": {\"frame_ms\": $ms}}" >"${out%.exr}.json"
WRAP
chmod +x fixed
out=$("${recheck[@]}" --pareto run -t hard --binary ./fixed --rounds 2 "$scene") ||
    fail "the stand-in: $out"
echo "$out" | grep -qF "default: hard 20.0 ms (error 0.0500), reference N = 1.6 30.0 ms (N = 1 10.0, N = 2 42.0): ratio 0.67 (the pareto run: 0.50), median of 2 rounds, 32x24" ||
    fail "the stand-in's line: $out"
echo "$out" | grep -q "^median ratio 0.67 over 1 scenes$" || fail "the median: $out"
out=$("${recheck[@]}" --pareto run -t hard --binary "$PENUMBRA" --rounds 1 "$scene") ||
    fail "the real binary: $out"
echo "$out" | grep -qE "^default: hard [0-9.]+ ms .*: ratio [0-9.]+ " || fail "its line: $out"
expect_exit 2 "^pareto-recheck: nowhere/pareto.json: not a pareto run's pareto.json" -- \
    "${recheck[@]}" --pareto nowhere -t hard "$scene"
expect_exit 2 "^pareto-recheck: run/pareto.json: no run of css at its defaults$" -- \
    "${recheck[@]}" --pareto run -t css "$scene"
expect_exit 2 "^pareto-recheck: default: not a conformance scene; give its file$" -- \
    "${recheck[@]}" --pareto run -t hard
expect_exit 2 "^pareto-recheck: ./missing: not an executable$" -- \
    "${recheck[@]}" --pareto run -t hard --binary ./missing "$scene"
echo "pareto_recheck: ok"
