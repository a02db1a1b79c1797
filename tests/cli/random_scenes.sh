# scripts/random-scenes: deterministic scenes nobody tuned on, each one the binary renders;
# bad arguments are refused with one line naming the flag.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
gen="$PENUMBRA_SOURCE_DIR/scripts/random-scenes"

paths=$("$gen" --seed 7 --count 3 --size 32x24 --out a)
[ "$paths" = "a/rand7.json,a/rand8.json,a/rand9.json" ] || fail "printed paths: $paths"
"$gen" --seed 7 --count 3 --size 32x24 --out b >/dev/null
for k in 7 8 9; do
    cmp "a/rand$k.json" "b/rand$k.json" || fail "rand$k.json differs between two runs"
    "$PENUMBRA" render "a/rand$k.json" -t hard -o "rand$k.exr" --quiet || fail "rand$k.json"
done
# Seeds differ from each other.
! cmp -s a/rand7.json a/rand8.json || fail "seeds 7 and 8 wrote the same scene"

# mixed: its own names, deterministic, the duck copied beside them, and every scene renders.
paths=$("$gen" --kind mixed --seed 5 --count 4 --size 32x24 --out m)
[ "$paths" = "m/mix5.json,m/mix6.json,m/mix7.json,m/mix8.json" ] || fail "mixed paths: $paths"
"$gen" --kind mixed --seed 5 --count 4 --size 32x24 --out n >/dev/null
cmp -s "$PENUMBRA_SOURCE_DIR/scenes/assets/duck.glb" m/assets/duck.glb || fail "no duck in m/assets"
for k in 5 6 7 8; do
    cmp "m/mix$k.json" "n/mix$k.json" || fail "mix$k.json differs between two runs"
    "$PENUMBRA" render "m/mix$k.json" -t hard -o "mix$k.exr" --quiet || fail "mix$k.json"
done
expect_exit 2 "--kind: invalid choice" -- "$gen" --kind odd --out c
expect_exit 2 "--count: 0 is outside" -- "$gen" --count 0 --out c
expect_exit 2 "--size: expected WxH" -- "$gen" --size 12 --out c
expect_exit 2 "--out" -- "$gen"
[ ! -e c ] || fail "a refused run created its folder"
echo "random_scenes ok"
