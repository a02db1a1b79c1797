# A sweep's cached files are reused only when they read back: a truncated reference gave
# "internal error" on every rerun, and a truncated run EXR was reused silently.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
sweep=("$PENUMBRA" sweep "$DATA/small.json" -t hard --vary technique.pcf=1,3 --size 32x24
       --reference-technique reference --reference-set technique.samples=2 --warmup 0 --repeat 1
       --no-report --quiet -o out)
"${sweep[@]}" 2>/dev/null || fail "first sweep"
ref=$(ls "$XDG_CACHE_HOME"/penumbra/references/reference-*.exr)
truncate -s 100 "$ref"
truncate -s 100 out/runs/run-0002.exr
expect_exit 0 "" -- "${sweep[@]}"
"$PENUMBRA" compare "$ref" "$ref" >/dev/null || fail "the truncated reference was not rendered again"
"$PENUMBRA" compare out/runs/run-0002.exr out/runs/run-0002.exr >/dev/null ||
    fail "the truncated run was reused"
echo "hostile_sweep_cache ok"
