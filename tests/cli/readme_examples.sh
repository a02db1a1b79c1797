# Every ```sh block of README.md runs verbatim in a copy of the checkout, each block a script
# with `set -euo pipefail`, through a `penumbra` on PATH that appends --size 64x48 to render and
# sweep (the one change allowed); scripts/demo, test, setup and build are stubbed (they build).
source "$(dirname "$0")/lib.sh"
build=$(cd "$(dirname "$PENUMBRA")" && pwd)
clone="$WORK/clone"
mkdir -p "$clone" "$WORK/bin" "$WORK/home"
# A fresh clone: the files git tracks (and new ones it does not ignore), and the build folder.
git -C "$PENUMBRA_SOURCE_DIR" ls-files -co --exclude-standard -z |
    (cd "$PENUMBRA_SOURCE_DIR" && xargs -0 cp --parents -t "$clone" 2>/dev/null) || true
[ -f "$clone/scenes/walk.json" ] || fail "the copy of the checkout has no scenes/walk.json"
ln -s "$build" "$clone/build"
cat >"$WORK/bin/penumbra" <<WRAP
#!/usr/bin/env bash
case "\${1:-}" in
    render | sweep) exec "$PENUMBRA" "\$@" --size 64x48 ;;
    *) exec "$PENUMBRA" "\$@" ;;
esac
WRAP
chmod +x "$WORK/bin/penumbra"

python3 - "$PENUMBRA_SOURCE_DIR/README.md" "$WORK/blocks" <<'PY'
import os, re, sys
text = open(sys.argv[1]).read()
os.makedirs(sys.argv[2])
blocks = re.findall(r"^```sh\n(.*?)^```", text, re.S | re.M)
assert len(blocks) >= 5, f"only {len(blocks)} sh blocks in README.md"
for i, b in enumerate(blocks):
    open(os.path.join(sys.argv[2], f"{i:02d}.sh"), "w").write(b)
PY
prelude='set -euo pipefail
for s in demo test setup build; do eval "scripts/$s() { echo \"(readme test: scripts/$s skipped)\"; }"; done'
cd "$clone"
for block in "$WORK"/blocks/*.sh; do
    start=$(date +%s)
    HOME="$WORK/home" PATH="$WORK/bin:$PATH" PENUMBRA="$WORK/bin/penumbra" \
        bash -c "$prelude"$'\n'"$(cat "$block")" >"$block.out" 2>&1 ||
        { cat "$block" "$block.out" >&2; fail "README block $(basename "$block") failed"; }
    echo "block $(basename "$block"): $(($(date +%s) - start)) s"
done

# What the examples promised: files under out/ only, the install, the animated sequence.
[ -x "$WORK/home/.local/bin/penumbra" ] || fail "cmake --install put no bin/penumbra"
[ -f "$WORK/home/.local/share/man/man1/penumbra.1" ] || fail "no man page installed"
completion="$WORK/home/.local/share/bash-completion/completions/penumbra"
bash -n "$completion" || fail "the installed completion is not valid bash"
grep -q -- "--skip-existing" "$completion" || fail "the completion lacks render's flags"
# The installed binary finds its OpenImageIO module in <prefix>/lib/penumbra/.
[ -f "$WORK/home/.local/lib/penumbra/libpenumbra_oiio.so" ] || fail "no lib/penumbra module installed"
"$WORK/home/.local/bin/penumbra" contact-sheet "$PENUMBRA_SOURCE_DIR/tests/data/gl/budget_halves.png" \
    -o "$WORK/installed_sheet.png" --quiet || fail "the installed binary cannot draw a contact sheet"
[ -f out/walk/walk.0024.exr ] && [ -f out/walk/walk.0024.png ] || fail "no walk sequence in out/walk"
[ -f out/ref.exr ] && [ -f out/hard.exr ] || fail "no out/ref.exr, out/hard.exr"
stray=$(git -C "$PENUMBRA_SOURCE_DIR" ls-files -co --exclude-standard -z | tr '\0' '\n' |
    sed 's|^|./|' | sort >"$WORK/tracked"; find . -path ./out -prune -o -path ./build -prune \
    -o -type f -print | sort | comm -23 - "$WORK/tracked")
[ -z "$stray" ] || fail "README examples wrote outside out/: $stray"
