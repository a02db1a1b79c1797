"""The `css_profile` suite of scripts/bench: where `css`'s time goes with 30 environment lights
(scenes/bench/environment.json, 256 x 256 maps). The visibility shader is cut short after each
of its stages (copies of glsl/ loaded through PENUMBRA_GLSL_DIR), and each variant's frame is
measured as process CPU seconds (user + sys of all threads: llvmpipe's work, steadier than wall
time on a shared machine): (CPU of 1 + REPEAT frames - CPU of 1 frame) / REPEAT. A stage's cost
is its variant's frame less the previous one's. A second table does the same for one light at
the defaults (interpolation on; the conformance scene light_size_2): the fine pass's parts.
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
     [(GLSL, f"{NO_SHADOW}  // nearer than every caster",
       f"{NO_SHADOW}  // nearer than every caster\n    {NO_SHADOW}")], {}),
    ("+ coverage test (1 SAT box: 4 lookups)",
     [(GLSL, f"    if (z_coverage.y <= 1e-6) {NO_SHADOW}",
       "    return vec3(z_coverage.y <= 1e-6 ? 1.0 : 0.5, 0.0, 0.0);")], {}),
    ("+ first search (4 boxes: 16 lookups)",
     [(GLSL, f"    if (search.x < 1e-3) {NO_SHADOW}  // no blocker in the search area",
       "    return vec3(search.x < 1e-3 ? 1.0 : 0.5, 0.0, 0.0);")], {}),
    ("+ refined searches (2 x 5 boxes: 40)",
     [(GLSL, "    vec4 z_coverage1 = boxMean(k1, 2 * CSS_PAIRS);\n"
       "    float f = filteredTestWith(k1, w, empty, false, z_coverage1).x;\n"
       "    if (z_coverage1.y > 1e-6) f = plateauCorrected(f, ds1 - 1.0 - z_coverage1.x / "
       "z_coverage1.y);",
       "    float f = 0.25 + 0.01 * empty + 0.01 * w[0].x;")], {}),
    ("+ final test (3 boxes: 12), sharpening", [], {}),
    ("the same with interpolate 0.05 (the default)", [], {"technique.interpolate": 0.05}),
]


# One light at the defaults (`interpolate` 0.05): visibility_fine.frag's parts, cut the same way.
FINE = "visibility_fine.frag"
FINE_DECISION = "    else if (r.horizon > 0.0 && !interpolated(pix, r, step, s))\n        discard;"
FINE_PLANE = "    if (r.casts && u_self_exclude > 0.0 &&"
ONE_LIGHT = os.path.join(ROOT, "scenes", "conformance", "light_size_2.json")
ONE_LIGHT_VARIANTS = [
    ("other passes, coarse samples; fine: constants",
     [(FINE, "    ivec2 pix = ivec2(gl_FragCoord.xy);",
       "    o_visibility = vec4(1.0); o_z_avg = vec4(0.0); o_filter_width = vec4(0.0); return;\n"
       "    ivec2 pix = ivec2(gl_FragCoord.xy);")], {}),
    ("+ fine: G-buffer reads, horizon, map step",
     [(FINE, FINE_DECISION, "    else if (r.horizon < -1.0)\n        discard;")], {}),
    ("+ interpolation test (no plane test), rest",
     [(FINE, FINE_PLANE, "    if (false && r.casts && u_self_exclude > 0.0 &&")], {}),
    ("+ plane test (casting receivers only)", [], {}),
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


def cpu_seconds(b, glsl, overrides, frames, scene=ENVIRONMENT):
    """CPU seconds of one render of SCENE, FRAMES frames (no warm-up) with shaders from GLSL
    and OVERRIDES (-D KEY=VALUE)."""
    env = dict(os.environ)
    env.pop("PENUMBRA_GLSL_DIR", None)
    if glsl:
        env["PENUMBRA_GLSL_DIR"] = glsl
    cmd = [b.binary, "render", scene, "-t", "css", "--size", b.size, "-o",
           os.path.join(b.out, "css_profile.exr"), "--warmup", "0", "--repeat", str(frames),
           "--quiet"]
    for key, value in overrides.items():
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
    # Every pixel through visibility.frag (whose stages the variants cut), unless overridden.
    base = {"technique.map_size": 256, "technique.env_lights": 30, "technique.interpolate": 0}
    rows = [(label, per_frame(b, variant_dir(b.out, i, edits), {**base, **overrides}))
            for i, (label, edits, overrides) in enumerate(VARIANTS)]
    total = rows[-2][1]  # every pixel evaluated
    previous = 0.0
    for label, value in rows[:-1]:
        stage = value - previous
        print(f"{label:<42}{value:>12.3f}{stage:>9.3f}{100 * stage / total:>7.0f}%")
        previous = value
    label, value = rows[-1]
    print(f"{label:<42}{value:>12.3f}  ({total / value:.2f}x faster)")
    one_light_profile(b)


def per_frame(b, glsl, overrides, scene=ENVIRONMENT):
    """CPU seconds per frame: (1 + REPEAT frames less 1 frame) / REPEAT, after a render that
    fills the program and shader caches for both (a variant's first compiles its shaders)."""
    cpu_seconds(b, glsl, overrides, 1, scene)
    one = cpu_seconds(b, glsl, overrides, 1, scene)
    many = cpu_seconds(b, glsl, overrides, 1 + b.repeat, scene)
    return (many - one) / b.repeat


def one_light_profile(b):
    print(f"\ncss_profile: conformance light_size_2, one light, the defaults, {b.size}: CPU "
          "seconds per frame, visibility_fine.frag cut short after each part")
    print(f"{'variant':<46}{'CPU s/frame':>12}{'part':>9}")
    previous = 0.0
    for i, (label, edits, overrides) in enumerate(ONE_LIGHT_VARIANTS):
        glsl = variant_dir(b.out, len(VARIANTS) + i, edits)
        value = per_frame(b, glsl, overrides, ONE_LIGHT)
        print(f"{label:<46}{value:>12.4f}{value - previous:>9.4f}")
        previous = value
