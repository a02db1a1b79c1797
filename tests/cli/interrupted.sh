# A render killed mid-sequence leaves no file under a final name that is not complete: every
# EXR present reads back, and the frame being written when killed is absent.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
scene="$DATA/small.json"
"$PENUMBRA" render "$scene" -f 1-400 -D technique.name=reference -D technique.samples=6 \
    -o "k/f.####.exr" --quiet &
pid=$!
for _ in $(seq 1 600); do
    [ -n "$(ls k 2>/dev/null | grep '\.exr$' || true)" ] && break
    sleep 0.05
done
sleep 0.3
kill -9 "$pid" 2>/dev/null || fail "the render finished before it could be killed"
wait "$pid" 2>/dev/null || true
count=0
for f in k/*.exr; do
    [ -e "$f" ] || continue
    "$PENUMBRA" compare "$f" "$f" >/dev/null || fail "$f is not a complete EXR"
    count=$((count + 1))
done
[ "$count" -ge 1 ] && [ "$count" -lt 400 ] || fail "expected some but not all frames, got $count"
echo "interrupted ok ($count complete frames, the rest absent)"
