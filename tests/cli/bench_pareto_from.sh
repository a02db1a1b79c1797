# scripts/bench pareto --pareto-from: the tables from an earlier run's sweep.csv files (a device
# run's tarball), no rendering; a missing sweep is left out, named, and the exit is 1; scene
# files by their stem, and the scene lists refused.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
mkdir -p from/light_size_2/reference from/light_size_2/css from/light_size_2/css_every_pixel
cat >from/light_size_2/reference/sweep.csv <<'CSV'
id,technique,technique.samples,total_ms,mae,shadow_mae,exr
run-0001,reference,1,10.0,0.01,0.10,runs/run-0001.exr
run-0002,reference,2,20.0,0.005,0.05,runs/run-0002.exr
run-0003,reference,4,40.0,0.002,0.02,runs/run-0003.exr
CSV
# At the defaults (order 4, map 256, sat), at reference N = 2's error in half its time: 0.25;
# order 2 at N = 4's error: 0.1 (a null shadow MAE falls back to the MAE, as sweep-report's).
cat >from/light_size_2/css/sweep.csv <<'CSV'
id,technique,technique.order,technique.map_size,technique.filter,total_ms,mae,shadow_mae,exr
run-0001,css,4,256,sat,5.0,0.004,0.05,runs/run-0001.exr
run-0002,css,2,256,sat,4.0,0.02,null,runs/run-0002.exr
CSV
# The defaults with every pixel evaluated: at N = 2's error in 0.4 of its time.
cat >from/light_size_2/css_every_pixel/sweep.csv <<'CSV'
id,technique,technique.order,technique.interpolate,total_ms,mae,shadow_mae,exr
run-0001,css,4,0,8.0,0.004,0.05,runs/run-0001.exr
CSV
bench() {
    "$PENUMBRA_SOURCE_DIR/scripts/bench" pareto --no-build --binary "$PENUMBRA" \
        --pareto-scenes light_size_2 --pareto-samples 1,2,4 --pareto-from from --out out "$@"
}
bench --pareto-techniques css >log 2>&1 || { cat log; fail "--pareto-from failed"; }
grep -q '^| `css` | 0.25 / 0.10 |' log || { cat log; fail "css's ratios are not 0.25 / 0.10"; }
grep -q "css, one light (goal <= 0.2): light_size_2 0.25: NOT met" log || fail "no css goal line"
[ -f out/pareto/pareto.csv ] || fail "no pareto.csv"
[ ! -e out/pareto/report ] || fail "a report from sweep.csv files, which hold no images"
# ssm's sweep is not there: its runs are left out, the others' tables stand, the exit is 1.
rc=0
bench --pareto-techniques css,ssm >log 2>&1 || rc=$?
[ $rc = 1 ] || { cat log; fail "a missing sweep exited $rc, not 1"; }
grep -q "no from/light_size_2/ssm/sweep.csv; ssm on light_size_2 is left out" log ||
    fail "the missing sweep is not named"
grep -q "these sweeps failed and are left out: light_size_2 ssm" log || fail "no summary"
grep -q '^| `css` | 0.25 / 0.10 |' log || fail "css's table is gone with ssm's sweep"
# A scene file (a word ending in .json) is named by its stem: its sweeps are DIR/STEM/SWEEP.
mkdir -p scenes/a scenes/b
cp "$PENUMBRA_SOURCE_DIR/scenes/conformance/light_size_2.json" scenes/a/mine.json
cp scenes/a/mine.json scenes/b/mine.json
cp -r from/light_size_2 from/mine
"$PENUMBRA_SOURCE_DIR/scripts/bench" pareto --no-build --binary "$PENUMBRA" --pareto-samples 1,2,4 \
    --pareto-scenes scenes/a/mine.json --pareto-from from --out out2 --pareto-techniques css \
    >log 2>&1 || { cat log; fail "a scene file's sweeps were not read"; }
grep -q '^| technique | mine |' log || { cat log; fail "the scene file's rows are not named mine"; }
grep -q '^| `css` | 0.25 / 0.10 |' log || { cat log; fail "the scene file's ratios are wrong"; }
# A goal some scenes meet and others not says how many: mine2's css at 3 ms is 0.15.
cp scenes/a/mine.json scenes/a/mine2.json
cp -r from/light_size_2 from/mine2
sed -i 's/^run-0001,css,4,256,sat,5.0,/run-0001,css,4,256,sat,3.0,/' from/mine2/css/sweep.csv
"$PENUMBRA_SOURCE_DIR/scripts/bench" pareto --no-build --binary "$PENUMBRA" --pareto-samples 1,2,4 \
    --pareto-scenes light_size_2,scenes/a/mine2.json --pareto-from from --out out2 \
    --pareto-techniques css >log 2>&1 || { cat log; fail "two scenes' sweeps were not read"; }
grep -q "css, one light (goal <= 0.2): light_size_2 0.25, mine2 0.15: NOT met (met on 1 of 2)" log ||
    { cat log; fail "no count of the scenes that meet the goal"; }
refused() {  # --pareto-scenes VALUE, the message expected
    rc=0
    "$PENUMBRA_SOURCE_DIR/scripts/bench" pareto --no-build --binary "$PENUMBRA" \
        --pareto-scenes "$1" --pareto-from from --out out3 >log 2>&1 || rc=$?
    [ $rc = 2 ] && grep -q "$2" log || { cat log; fail "--pareto-scenes $1: exit $rc"; }
}
refused scenes/none.json "no scene file 'scenes/none.json'"
refused scenes/a/mine.json,scenes/b/mine.json "two scenes named 'mine'"
cp scenes/a/mine.json scenes/a/light_size_2.json
refused light_size_2,scenes/a/light_size_2.json "two scenes named 'light_size_2'"
refused nosuchscene "no conformance scene 'nosuchscene'"
[ ! -e out3 ] || fail "a refused --pareto-scenes wrote out3"
echo "bench_pareto_from ok"
