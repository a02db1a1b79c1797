# Farm safety: patterns without # refused for farm tasks, frames outside the animation range,
# a frame done only when all of its files are, stale temporaries removed, the scene's name in
# outputs independent of the working folder, progress cut to the terminal, scripts/sequence's
# job log appended and its summary counted from disk.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
scene="$DATA/small.json"

# --frame-from-env with no # in a pattern: every task would write one file.
expect_exit 2 "^penumbra: --output: f.exr: no # for the frame number" -- \
    env TASK=2 "$PENUMBRA" render "$scene" --frame-from-env TASK -o f.exr
expect_exit 2 "^penumbra: --preview: p.png: no # " -- \
    env TASK=2 "$PENUMBRA" render "$scene" --frame-from-env TASK -o "f.#.exr" --preview p.png
[ ! -e f.exr ] && [ ! -e f.2.exr ] || fail "a refused farm task wrote"
# Outside the animation range (1-3): a warning, or an error with --strict.
expect_exit 0 "^penumbra: warning: --frames: frame 7 is outside the scene's animation range 1-3" -- \
    "$PENUMBRA" render "$scene" -f 7 -o w.exr
expect_exit 2 "^penumbra: --frame-from-env: frame 9 is outside .* \(--strict\)" -- \
    env TASK=9 "$PENUMBRA" render "$scene" --frame-from-env TASK -o "s.#.exr" --strict
[ "$("$PENUMBRA" render "$scene" -f 7 -o w.exr --quiet 2>&1)" = "" ] || fail "--quiet warned"

# A frame is done when all of its files are: a missing JSON or preview renders it again.
r=("$PENUMBRA" render "$scene" -f 1-2 -o "d/f.#.exr" --preview "d/f.#.png" --skip-existing --quiet)
"${r[@]}"
rm d/f.1.json
touch -d '2000-01-01' d/f.2.exr
"${r[@]}"
[ -f d/f.1.json ] || fail "a frame with its JSON missing was skipped"
[ "$(stat -c %Y d/f.2.exr)" -lt 1000000000 ] || fail "a complete frame rendered again"
rm d/f.2.png
[ "$("$PENUMBRA" render "$scene" -f 1-2 -o "d/f.#.exr" --preview "d/f.#.png" --skip-existing --list-frames)" = 2 ] ||
    fail "--list-frames counts a frame with its preview missing as done"
# Stale temporaries of our own outputs (a dead PID) go; a live process's and others' stay.
sleep 300 & live=$!
touch "d/.f.1.exr.999999999.tmp" "d/.f.1.json.999999999.tmp" "d/.f.1.exr.$live.tmp" \
      "d/.other.exr.999999999.tmp"
"$PENUMBRA" render "$scene" -f 1 -o "d/f.#.exr" --quiet
kill "$live"
[ ! -e "d/.f.1.exr.999999999.tmp" ] && [ ! -e "d/.f.1.json.999999999.tmp" ] ||
    fail "stale temporaries of a dead process were kept"
[ -e "d/.f.1.exr.$live.tmp" ] && [ -e "d/.other.exr.999999999.tmp" ] ||
    fail "a live process's or another output's temporary was removed"

# penumbra/scene is canonical: the same frame from the same folder, the scene typed three ways,
# has the same bytes; outside the working folder it is NAME@HASH, the same from anywhere.
mkdir -p sc/sub && cp "$scene" sc/small.json
(cd sc && "$PENUMBRA" render small.json -f 2 -o ../c1.exr --quiet)
(cd sc && "$PENUMBRA" render ./sub/../small.json -f 2 -o ../c2.exr --quiet)
(cd sc && "$PENUMBRA" render "$WORK/sc/small.json" -f 2 -o ../c3.exr --quiet)
cmp c1.exr c2.exr && cmp c1.exr c3.exr || fail "the scene path as typed changed the EXR's bytes"
(cd sc/sub && "$PENUMBRA" render ../small.json -f 2 -o ../../h1.exr --quiet)
mkdir other && (cd other && "$PENUMBRA" render "$WORK/sc/small.json" -f 2 -o ../h2.exr --quiet)
cmp h1.exr h2.exr || fail "two folders outside the scene's gave different bytes"
grep -aq 'small.json@[0-9a-f]\{16\}' h1.exr || fail "no NAME@HASH scene name"
python3 -c 'import json,sys; assert json.load(open("c1.json"))["scene"] == "small.json"'

# Progress on a (fake, 40-column) terminal: lines cut, never wrapped; ETA as 12s / 3m 05s.
if command -v script >/dev/null; then
    COLUMNS=40 script -qec "stty cols 40; $PENUMBRA render $scene -o 'p/f.#.exr'" /dev/null >tty.txt
    python3 - tty.txt <<'PY'
import re, sys
text = open(sys.argv[1], "rb").read().decode("utf-8", "replace")
lines = [l for l in re.split(r"\r|\n", re.sub(r"\x1b\[K", "", text)) if l.startswith("penumbra: frame")]
assert lines, text
assert all(len(l) <= 39 for l in lines), [l for l in lines if len(l) > 39]
PY
fi

# scripts/sequence appends to its job log, and when interrupted counts the frames on disk.
seq="$PENUMBRA_SOURCE_DIR/scripts/sequence"
"$seq" "$scene" -j 2 --binary "$PENUMBRA" --joblog j.log -- -o "q/f.#.exr" >/dev/null
rm q/f.2.exr
"$seq" "$scene" -j 2 --binary "$PENUMBRA" --joblog j.log -- -o "q/f.#.exr" >out.txt
grep -q "3 frames: 1 written, 2 skipped" out.txt || fail "sequence summary: $(cat out.txt)"
[ "$(grep -vc '^Seq' j.log)" -eq 4 ] || fail "the job log was not appended to: $(cat j.log)"
setsid "$seq" "$DATA/anim6.json" -j 1 --binary "$PENUMBRA" -- -o "i/f.#.exr" --size 320x240 >int.txt 2>&1 &
pid=$!
for _ in $(seq 100); do [ -f i/f.2.exr ] && break; sleep 0.1; done
kill -TERM -- "-$pid"  # as Ctrl-C's INT does (a background job ignores INT)
wait "$pid" && fail "an interrupted sequence exited 0" || true
on_disk=$(ls i/*.exr 2>/dev/null | wc -l)
grep -q "interrupted: $on_disk of 6 frames on disk" int.txt || fail "interrupt summary: $(cat int.txt), $on_disk on disk"
