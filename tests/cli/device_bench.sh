# scripts/device-bench: its guard against spending device time on a software renderer, and its
# refusals of bad arguments, each one line naming the option or the missing bundle.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
db="$PENUMBRA_SOURCE_DIR/scripts/device-bench"

"$db" --help | grep -q "scripts/device-bench pack" || fail "--help prints no usage"
expect_exit 2 "usage" -- "$db"
expect_exit 2 "unknown option '--fast'" -- "$db" run out --fast
expect_exit 2 "--minutes: expected a whole number, got 'x'" -- "$db" run out --minutes x
mkdir empty
expect_exit 2 "no bundle in .*/empty: run .scripts/device-bench pack." -- \
    "$db" run out --bundle empty
expect_exit 2 "--binary: .*/missing is not an executable file" -- "$db" run out --binary missing
[ ! -e out ] || fail "a refused run created its folder"
# Where the binary renders on a software rasteriser (CI's machines), the run stops after
# `penumbra info`, before any bench: a device session must not spend its minutes there.
if "$PENUMBRA" info --json | grep -q llvmpipe; then
    expect_exit 1 "a software renderer answered, not the GPU" -- "$db" run out --binary "$PENUMBRA"
    grep -q llvmpipe out/info.json || fail "info.json is not penumbra info's"
    [ ! -e out/bench.log ] || fail "a bench ran on the software renderer"
fi
echo "device_bench ok"
