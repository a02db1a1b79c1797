# scripts/conformance --variant: runs of one's own (a technique and its overrides) against
# `exact`, labelled in the results; malformed variants are refused with one line naming them.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
conf=("$PENUMBRA_SOURCE_DIR/scripts/conformance" --no-build --binary "$PENUMBRA" --size 32x24
      --exact-samples 2 --no-oiiotool)
scene=$("$PENUMBRA_SOURCE_DIR/scripts/random-scenes" --seed 7 --count 1 --size 32x24 --out s)

"${conf[@]}" --scenes "$scene" --out out --variant ref2=reference,technique.samples=2 \
    --variant ref2_centres=reference,technique.samples=2,technique.jitter=false >/dev/null ||
    fail "two variants"
runs=$(cut -d, -f2 out/results.csv | tail -n +2 | tr '\n' ' ')
[ "$runs" = "ref2 ref2_centres " ] || fail "only the variants run, in order: $runs"
python3 -c 'import json, sys; sys.exit(json.load(open(sys.argv[1]))["params"]["jitter"] is not False)' \
    out/runs/rand7.ref2_centres.json || fail "the override did not reach render"
# With --techniques, a variant joins the named runs.
"${conf[@]}" --scenes "$scene" --out out2 --techniques hard,ref2 \
    --variant ref2=reference,technique.samples=2 >/dev/null || fail "--techniques with a variant"
[ "$(cut -d, -f2 out2/results.csv | tail -n +2 | tr '\n' ' ')" = "hard ref2 " ] ||
    fail "--techniques hard,ref2"

# A JSON value with commas stays one override.
"${conf[@]}" --scenes "$scene" --out out3 --variant 'far=hard,camera.position=[0, 3, 6]' \
    >/dev/null || fail "a list value"
grep -q '^rand7,far,' out3/results.csv || fail "the list-valued variant has no result"

expect_exit 2 "'bad': expected LABEL=TECHNIQUE" -- "${conf[@]}" --variant bad --out r
expect_exit 2 "'nosuch': not a technique" -- "${conf[@]}" --variant x=nosuch --out r
expect_exit 2 "'samples': expected KEY=VALUE" -- "${conf[@]}" --variant x=reference,samples --out r
expect_exit 2 "label 'hard' is taken" -- "${conf[@]}" --variant hard=reference --out r
expect_exit 2 "a label is letters" -- "${conf[@]}" --variant ../x=reference --out r
[ ! -e r ] || fail "a refused run created its folder"
# A key render refuses: its own line, then one naming the run, exit 1.
expect_exit 1 "rand7.x.exr: penumbra exited 2" -- "${conf[@]}" --scenes "$scene" --out bad \
    --variant x=reference,technique.nosuch=1
echo "conformance_variants ok"
