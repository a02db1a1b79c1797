# A sweep's cached files are reused only when they read back: a truncated reference gave
# "internal error" on every rerun, and a truncated run EXR was reused silently; and only while
# the assets they were rendered from are unchanged.
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

# An asset edited in place under the same name (a .gltf's external buffer): the run and the
# reference are rendered again, as the bytes they were rendered from changed.
write_triangle_gltf tri.gltf tri.bin tri.bin
write_scene_with_gltf tri.json tri.gltf
tri=("$PENUMBRA" sweep tri.json -t hard --vary technique.pcf=1 --size 32x24
     --reference-technique reference --reference-set technique.samples=2 --warmup 0 --repeat 1
     --no-report -o tri_out)
"${tri[@]}" 2>log.txt || { cat log.txt; fail "sweep of the glTF scene"; }
"${tri[@]}" 2>log.txt || { cat log.txt; fail "second sweep of the glTF scene"; }
grep -q "1 runs (0 rendered, 1 reused, 0 failed), 1 references (0 rendered)" log.txt ||
    { cat log.txt; fail "an unchanged asset rendered again"; }
python3 -c 'import struct; open("tri.bin", "wb").write(struct.pack("<9f", 0, 0, 0, 2, 0, 0, 0, 2,
                                                                    0))'
"${tri[@]}" 2>log.txt || { cat log.txt; fail "sweep after the edit"; }
grep -q "1 runs (1 rendered, 0 reused, 0 failed), 1 references (1 rendered)" log.txt ||
    { cat log.txt; fail "an asset edited in place reused the cached renders"; }
echo "hostile_sweep_cache ok"
