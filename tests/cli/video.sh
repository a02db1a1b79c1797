# scripts/video: a --preview PNG sequence (a # pattern or a folder) to an H.264 MP4 and a GIF
# whose frame counts ffprobe confirms, hostile names never reaching a shell or ffmpeg's
# options, bad input refused (exit 2, nothing written) and the absent-ffmpeg message (exit 3).
source "$(dirname "$0")/lib.sh"
cd "$WORK"
video="$PENUMBRA_SOURCE_DIR/scripts/video"
command -v ffmpeg >/dev/null && command -v ffprobe >/dev/null ||
    fail "ffmpeg and ffprobe are needed (scripts/setup installs ffmpeg)"
frames() {  # frames FILE: the video frames ffprobe decodes
    ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames \
        -of csv=p=0 "file:$1"
}

dir='fr $(touch PWNED); x'
"$PENUMBRA" render "$PENUMBRA_SOURCE_DIR/scenes/walk.json" -f 1-4 --size 64x48 \
    -o "$dir/walk.####.exr" --preview "$dir/walk.####.png" 2>/dev/null || fail "render"
touch "$dir/walk.12.png" "$dir/walk.00005.png"  # not frames of the #### pattern: ignored

"$video" "$dir/walk.####.png" -o "-v'x.mp4" --fps 8 >log.txt || { cat log.txt; fail "mp4"; }
grep -q "4 frames at 8 fps" log.txt || fail "summary: $(cat log.txt)"
[ "$(frames "-v'x.mp4")" = 4 ] || fail "mp4 frames: $(frames "-v'x.mp4")"
ffprobe -v error -show_entries stream=codec_name -of csv=p=0 "file:-v'x.mp4" | grep -qx h264 ||
    fail "not H.264"
rm "$dir/walk.12.png" "$dir/walk.00005.png"
"$video" "$dir" -o "gifs/a b.gif" --fps 4 >/dev/null || fail "gif from a folder"
[ "$(frames "gifs/a b.gif")" = 4 ] || fail "gif frames: $(frames "gifs/a b.gif")"
[ ! -e PWNED ] || fail "a file name reached a shell"
[ -z "$(ls -A gifs | grep -v '^a b.gif$')" ] || fail "temporary files left: $(ls -A gifs)"

# Bad input: exit 2, nothing written.
mkdir folder.mp4
expect_exit 2 "no file matches" -- "$video" "$dir/none.####.png" -o bad.mp4
expect_exit 2 "must end in .mp4 or .gif" -- "$video" "$dir" -o bad.avi
expect_exit 2 "is a folder" -- "$video" "$dir" -o folder.mp4
expect_exit 2 "--fps" -- "$video" "$dir" -o bad.mp4 --fps 0
expect_exit 2 "missing FRAMES" -- "$video" -o bad.mp4
[ -z "$(ls -d bad* 2>/dev/null)" ] || fail "bad input wrote $(ls -d bad*)"

# Without ffmpeg on PATH: one line saying how to install it, exit 3.
mkdir nobin
for c in bash env mktemp ln realpath mv rm dirname basename mkdir sort awk; do
    ln -s "$(command -v "$c")" "nobin/$c"
done
expect_exit 3 "^video: ffmpeg is not installed: apt-get install ffmpeg" -- \
    env PATH="$WORK/nobin" "$video" "$dir" -o bad.mp4
[ "$(wc -l <"$WORK/stderr")" -eq 1 ] || fail "more than one line without ffmpeg"
[ ! -e bad.mp4 ] || fail "wrote bad.mp4 without ffmpeg"
echo "video ok"
