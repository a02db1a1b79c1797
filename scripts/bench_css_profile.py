"""The `css_profile` suite of scripts/bench: where `css`'s time goes with 30 environment lights
(scenes/bench/environment.json, 256 x 256 maps). The visibility shader is cut short after each
of its stages (copies of glsl/ loaded through PENUMBRA_GLSL_DIR), and each variant's frame is
measured as process CPU seconds (user + sys of all threads: llvmpipe's work, steadier than wall
time on a shared machine): (CPU of 1 + REPEAT frames - CPU of 1 frame) / REPEAT. A stage's cost
is its variant's frame less the previous one's.
"""
import os
import resource
import shutil
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ENVIRONMENT = os.path.join(ROOT, "scenes", "bench", "environment.json")
SHADERS = os.path.join("techniques", "css")

# Each variant: (label, [(file, anchor, replacement)] applied to glsl/techniques/css/, -D
# overrides); an anchor that is not in its file stops the suite (the cut points must follow the
# shaders).
FRAG, GLSL = "visibility.frag", "visibility.glsl"
NO_SHADOW = "return vec3(1.0, 0.0, 0.0);"
VARIANTS = [
    ("other passes; empty visibility passes",
     [(FRAG, "    Receiver r;\n    if (!receiverAt(",
       "    o_visibility = vec4(1.0); o_z_avg = vec4(0.0); o_filter_width = vec4(0.0); return;\n"
       "    Receiver r;\n    if (!receiverAt(")], {}),
    ("+ G-buffer reads, horizon",
     [(GLSL, f"    if (zw <= u_near) {NO_SHADOW}", f"    {NO_SHADOW}")], {}),
    ("+ coverage test (1 SAT box: 4 lookups)",
     [(GLSL, f"    if (z_coverage.y <= 1e-6) {NO_SHADOW}",
       "    return vec3(z_coverage.y <= 1e-6 ? 1.0 : 0.5, 0.0, 0.0);")], {}),
    ("+ first search (4 boxes: 16 lookups)",
     [(GLSL, f"    if (search.x < 1e-3) {NO_SHADOW}  // no blocker in the search area",
       "    return vec3(search.x < 1e-3 ? 1.0 : 0.5, 0.0, 0.0);")], {}),
    ("+ refined searches (2 x 5 boxes: 40)",
     [(GLSL, "    float f = filteredTest(makeKernel(c, w1, MIP_TAPS, false), w, empty, false).x;",
       "    float f = 0.25 + 0.01 * empty + 0.01 * w[0].x;")], {}),
    ("+ final test (3 boxes: 12), sharpening", [], {}),
    ("the same with interpolate 0.05 (the default)", [], {"technique.interpolate": 0.05}),
]


def variant_dir(out, index, edits):
    """A copy of glsl/ under OUT with EDITS applied; None for no edits."""
    if not edits:
        return None
    path = os.path.join(out, f"css_profile_glsl{index}")
    shutil.rmtree(path, ignore_errors=True)
    shutil.copytree(os.path.join(ROOT, "glsl"), path)
    for name, anchor, replacement in edits:
        shader = os.path.join(path, SHADERS, name)
        with open(shader, encoding="utf-8") as f:
            text = f.read()
        if text.count(anchor) != 1:
            raise SystemExit(f"css_profile: the cut point is not in {name}: {anchor.strip()}")
        with open(shader, "w", encoding="utf-8") as f:
            f.write(text.replace(anchor, replacement))
    return path


def cpu_seconds(b, glsl, overrides, frames):
    """CPU seconds of one render of FRAMES frames (no warm-up) with shaders from GLSL."""
    env = dict(os.environ)
    env.pop("PENUMBRA_GLSL_DIR", None)
    if glsl:
        env["PENUMBRA_GLSL_DIR"] = glsl
    cmd = [b.binary, "render", ENVIRONMENT, "-t", "css", "--size", b.size, "-o",
           os.path.join(b.out, "css_profile.exr"), "--warmup", "0", "--repeat", str(frames),
           "--quiet", "-D", "technique.map_size=256", "-D", "technique.env_lights=30"]
    # Every pixel through visibility.frag (whose stages the variants cut), unless overridden.
    for key, value in {"technique.interpolate": 0, **overrides}.items():
        cmd += ["-D", f"{key}={value}"]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, check=True, env=env)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def css_profile(b):
    print(f"\ncss_profile: scenes/bench/environment.json, 30 lights, 256 x 256 maps, {b.size}: "
          f"CPU seconds per frame ({1 + b.repeat} frames less 1), the visibility shader cut short "
          "after each stage")
    print(f"{'variant':<42}{'CPU s/frame':>12}{'stage':>9}{'share':>8}")
    rows = []
    for i, (label, edits, overrides) in enumerate(VARIANTS):
        glsl = variant_dir(b.out, i, edits)
        one = cpu_seconds(b, glsl, overrides, 1)
        many = cpu_seconds(b, glsl, overrides, 1 + b.repeat)
        rows.append((label, (many - one) / b.repeat))
    total = rows[-2][1]  # every pixel evaluated
    previous = 0.0
    for label, per_frame in rows[:-1]:
        stage = per_frame - previous
        print(f"{label:<42}{per_frame:>12.3f}{stage:>9.3f}{100 * stage / total:>7.0f}%")
        previous = per_frame
    label, per_frame = rows[-1]
    print(f"{label:<42}{per_frame:>12.3f}  ({total / per_frame:.2f}x faster)")
