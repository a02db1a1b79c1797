# The frame pipeline of a sequence: files written on the writer threads (the default, one, or
# three) while the next frames render are the bytes the serial path writes
# (PENUMBRA_SERIAL_WRITES=1); a
# sequence stopped by SIGINT or SIGTERM mid-write leaves no temporary and no partial file, one
# killed by SIGKILL no partial file (its temporaries go with the next run); the program binary
# cache is hit by a second process, and a corrupt cache file is ignored with the same output;
# every --exr-compression gives the same pixels.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
scene="$DATA/anim6.json"

# 1. Pipelined and serial writes: the same EXR and PNG bytes, every frame.
sequence() {  # sequence FOLDER [ENV...]: the six frames of $scene with previews into FOLDER
    local dir=$1
    shift
    env "$@" "$PENUMBRA" render "$scene" -o "$dir/f.####.exr" --preview "$dir/f.####.png" --quiet
}
same_frames() {  # same_frames A B WHAT: every frame's EXR and PNG in A are the bytes of B's
    local f ext name
    for f in 1 2 3 4 5 6; do
        for ext in exr png; do
            name=$(printf 'f.%04d.%s' "$f" "$ext")
            cmp "$1/$name" "$2/$name" || fail "$name differs between $3"
        done
    done
}
sequence pipe
sequence serial PENUMBRA_SERIAL_WRITES=1
same_frames pipe serial "pipelined and serial writes"
sequence one PENUMBRA_WRITER_THREADS=1
same_frames one serial "one writer and serial"
for f in 1 2 3 4 5 6; do
    [ -s "pipe/$(printf 'f.%04d.json' "$f")" ] || fail "frame $f has no timing JSON"
done

# 1a. Three writer threads (frames written at once, out of order): the same bytes again; frame
# 4 rendered alone (nothing reused) is the bytes of frame 4 of the sequence, whose pixel storage
# held frames 1-3 before; a bad PENUMBRA_WRITER_THREADS is refused before anything is written.
sequence three PENUMBRA_WRITER_THREADS=3
same_frames three serial "three writers and serial"
"$PENUMBRA" render "$scene" -f 4 -o "alone/f.####.exr" --quiet
cmp alone/f.0004.exr pipe/f.0004.exr || fail "frame 4 alone differs from frame 4 of the sequence"
for bad in 0 17 x; do
    expect_exit 2 "^penumbra: PENUMBRA_WRITER_THREADS: '$bad' is not a number from 1 to 16" -- \
        env PENUMBRA_WRITER_THREADS="$bad" "$PENUMBRA" render "$scene" -o "badw/f.####.exr"
    [ ! -e badw ] || fail "PENUMBRA_WRITER_THREADS=$bad wrote something"
done

# 1b. --exr-compression: every method is lossless (the default's pixels, to the bit, pipelined
# and serial alike), named in the header (the default: zips); an unknown or lossy one is
# refused before rendering.
oiiotool --info -v pipe/f.0002.exr | grep -q 'compression: "zips"' || fail "the default is not zips"
for c in zip zip:1 zip:9 zips:1 rle none piz; do
    "$PENUMBRA" render "$scene" -f 2 -o "comp/$c.exr" --exr-compression "$c" --quiet
    "$PENUMBRA" compare pipe/f.0002.exr "comp/$c.exr" --fail 0 --warn 0 >/dev/null ||
        fail "--exr-compression $c changed the pixels"
    oiiotool --info -v "comp/$c.exr" | grep -q "compression: \"${c%%:*}\"" ||
        fail "--exr-compression $c: the header says $(oiiotool --info -v "comp/$c.exr" | grep compression)"
done
PENUMBRA_SERIAL_WRITES=1 "$PENUMBRA" render "$scene" -f 2 -o comp/serial.exr \
    --exr-compression zip:1 --quiet
cmp comp/zip:1.exr comp/serial.exr || fail "zip:1 differs between pipelined and serial writes"
for bad in dwaa zip:0 rle:2 ''; do
    expect_exit 2 "^penumbra: render: --exr-compression: '$bad' is not zip, zips, rle, none or piz" -- \
        "$PENUMBRA" render "$scene" -f 2 -o "bad/f.exr" --exr-compression "$bad"
    [ ! -e bad ] || fail "--exr-compression $bad wrote something"
done

# 2. Interrupted while a temporary exists: SIGINT and SIGTERM remove it; SIGKILL cannot, but
# leaves no file under a final name that is not complete, and the rerun clears it.
set -m  # background jobs keep SIGINT's default action (without job control they ignore it)
interrupt() {  # interrupt SIGNAL FOLDER: starts a sequence, signals it mid-write; exit code in RC
    local sig=$1 dir=$2
    "$PENUMBRA" render "$DATA/small.json" -f 1-30 --size 192x144 -o "$dir/f.####.exr" \
        --preview "$dir/f.####.png" --quiet &
    local pid=$! seen=0
    for _ in $(seq 1 4000); do
        if compgen -G "$dir/.*.tmp" >/dev/null; then
            seen=1
            break
        fi
        sleep 0.005
    done
    kill "-$sig" "$pid" 2>/dev/null || fail "$sig: the render finished before it could be signalled"
    RC=0
    wait "$pid" || RC=$?
    [ "$seen" -eq 1 ] || fail "$sig: never saw a temporary file to interrupt"
}
complete_frames() {  # every EXR under its final name reads back
    local f
    for f in "$1"/*.exr; do
        [ -e "$f" ] || continue
        "$PENUMBRA" compare "$f" "$f" >/dev/null || fail "$f is not a complete EXR"
    done
}
for sig in INT TERM; do
    interrupt "$sig" "k_$sig"
    [ "$RC" -eq $((128 + $(kill -l "$sig"))) ] || fail "SIG$sig: expected death by the signal, got $RC"
    left=$(find "k_$sig" -name '*.tmp')
    [ -z "$left" ] || fail "SIG$sig left temporaries: $left"
    complete_frames "k_$sig"
done
interrupt KILL k_KILL
complete_frames k_KILL
"$PENUMBRA" render "$DATA/small.json" -f 1-30 --size 192x144 -o "k_KILL/f.####.exr" \
    --preview "k_KILL/f.####.png" --quiet --skip-existing
left=$(find k_KILL -name '*.tmp')
[ -z "$left" ] || fail "the rerun after SIGKILL left temporaries: $left"
[ "$(find k_KILL -name '*.exr' | wc -l)" -eq 30 ] || fail "the rerun did not complete the sequence"
set +m

# 3. The program cache ($XDG_CACHE_HOME is this test's own, lib.sh): a second process loads
# every program from it; corrupt files are compiled again, with identical output.
process() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['process'][sys.argv[2]])" "$@"; }
export XDG_CACHE_HOME="$WORK/program-cache"  # cold: the renders above filled the other
cache="$XDG_CACHE_HOME/penumbra/programs"
"$PENUMBRA" render "$DATA/small.json" -f 1 -o c1/f.#.exr --quiet
[ "$(process c1/f.1.json programs_from_cache)" -eq 0 ] || fail "a cold cache gave programs"
compiled=$(process c1/f.1.json programs_compiled)
[ "$compiled" -gt 0 ] || fail "no program compiled"
if [ -z "$(ls -A "$cache" 2>/dev/null)" ]; then
    echo "the driver offers no program binaries: the cache stays empty (nothing more to check)"
    echo "frame pipeline ok (serial = pipelined bytes, interrupts clean)"
    exit 0
fi
"$PENUMBRA" render "$DATA/small.json" -f 1 -o c2/f.#.exr --quiet
[ "$(process c2/f.1.json programs_from_cache)" -eq "$compiled" ] || fail "a warm cache missed"
[ "$(process c2/f.1.json programs_compiled)" -eq 0 ] || fail "a warm cache still compiled"
cmp c1/f.1.exr c2/f.1.exr || fail "the cached programs render other bytes"
for f in "$cache"/*.bin; do  # flip bytes in the binary, and truncate another copy
    python3 -c "import sys; p=sys.argv[1]; b=bytearray(open(p,'rb').read()); b[-100]^=0xff; open(p,'wb').write(b)" "$f"
done
"$PENUMBRA" render "$DATA/small.json" -f 1 -o c3/f.#.exr --quiet 2>c3.err
[ ! -s c3.err ] || { cat c3.err; fail "a corrupt cache file printed something"; }
[ "$(process c3/f.1.json programs_compiled)" -eq "$compiled" ] || fail "corrupt files were used"
cmp c1/f.1.exr c3/f.1.exr || fail "after a corrupt cache the output differs"
for f in "$cache"/*.bin; do truncate -s 40 "$f"; done
"$PENUMBRA" render "$DATA/small.json" -f 1 -o c4/f.#.exr --quiet
cmp c1/f.1.exr c4/f.1.exr || fail "after a truncated cache the output differs"
PENUMBRA_PROGRAM_CACHE=0 "$PENUMBRA" render "$DATA/small.json" -f 1 -o c5/f.#.exr --quiet
[ "$(process c5/f.1.json programs_from_cache)" -eq 0 ] || fail "PENUMBRA_PROGRAM_CACHE=0 used it"
echo "frame pipeline ok (serial = pipelined bytes, interrupts clean, program cache hit)"
