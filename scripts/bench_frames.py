"""The `frames` suite of scripts/bench: the cost of a sequence beyond its passes. A `hard`
sequence of an animated scene (scenes/walk.json's animation stretched over --frames frames) in
one process: wall time per frame against the sum of the passes per frame (readback excluded:
it is part of the overhead), their ratio, and the process's time to its first pass (timing
JSON `process.ms_to_first_pass`), with the EXR writer pipelined (the default) and
serial (PENUMBRA_SERIAL_WRITES=1), pipelined also with each of --exr-compression's methods
(render's flag of that name) and with each of --writer-threads' numbers of writer threads (1
too where the default is more), and --baseline's binary pipelined, and the time to first pass with a cold and a warm program
cache (a private cache folder under the bench's output folder). The `startup` suite: the
process's start-up alone (shared libraries, `--version`, time to the first pass), beside an
older binary (--baseline) when given.
"""
import json
import os
import resource
import shutil
import statistics
import subprocess
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WALK = os.path.join(ROOT, "scenes", "walk.json")


def stretched_walk(out, frames):
    """scenes/walk.json with its animation keys spread over frames 1..FRAMES, asset paths
    absolute, written into OUT."""
    with open(WALK, encoding="utf-8") as f:
        scene = json.load(f)
    first, last = (int(x) for x in scene["animation"]["frames"].split("-"))
    scale = (frames - 1) / max(last - first, 1)
    for track in scene["animation"]["tracks"]:
        for key in track["keys"]:
            key[0] = round(1 + (key[0] - first) * scale)
    scene["animation"]["frames"] = f"1-{frames}"
    for o in scene["objects"]:
        if "gltf" in o and not os.path.isabs(o["gltf"]):
            o["gltf"] = os.path.join(os.path.dirname(WALK), o["gltf"])
    path = os.path.join(out, "frames_walk.json")
    with open(path, "w", encoding="utf-8") as f:
        json.dump(scene, f)
    return path


def default_writer_threads():
    """The writer threads a render uses here (render_job_writer.h): PENUMBRA_WRITER_THREADS,
    else one for every 4 cores, 2 to 4."""
    if os.environ.get("PENUMBRA_WRITER_THREADS"):
        return int(os.environ["PENUMBRA_WRITER_THREADS"])
    return min(4, max(2, (os.cpu_count() or 1) // 4))


def cpu_seconds():
    """User and system CPU time of the finished children so far."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


class Run:
    """What one render process measured: wall and CPU s, per-frame pass sums and readbacks
    (ms), ms to its first pass, and the mean EXR size (bytes)."""

    def __init__(self, wall, cpu, passes, readbacks, first, exr_bytes):
        self.wall, self.cpu, self.passes, self.readbacks = wall, cpu, passes, readbacks
        self.first, self.exr_bytes = first, exr_bytes


def sequence(b, scene, frames, env, tag, binary=None, options=()):
    """One process (BINARY, else this build's) rendering FRAMES frames of SCENE with render
    OPTIONS: a Run."""
    folder = os.path.join(b.out, f"frames_{tag}")
    shutil.rmtree(folder, ignore_errors=True)
    cmd = [binary or b.binary, "render", scene, "-t", "hard", "--size", b.size, "-f",
           f"1-{frames}", "-o", os.path.join(folder, "f.####.exr"), "--quiet", *options]
    start, cpu = time.monotonic(), cpu_seconds()
    subprocess.run(cmd, check=True, env=env)
    wall, cpu = time.monotonic() - start, cpu_seconds() - cpu
    passes, readbacks, first, exr_bytes = [], [], None, 0
    for i in range(1, frames + 1):
        with open(os.path.join(folder, f"f.{i:04d}.json"), encoding="utf-8") as f:
            t = json.load(f)
        passes.append(sum(p["ms"] for p in t["passes"] if p["name"] != "readback"))
        readbacks.append(sum(p["ms"] for p in t["passes"] if p["name"] == "readback"))
        first = t.get("process", {}).get("ms_to_first_pass", first)
        exr_bytes += os.path.getsize(os.path.join(folder, f"f.{i:04d}.exr"))
    shutil.rmtree(folder, ignore_errors=True)  # 240 frames at 1024x768 are about 1.1 GB
    return Run(wall, cpu, passes, readbacks, first, exr_bytes / frames)


def frames(b):
    n = b.frames
    scene = stretched_walk(b.out, n)
    cache = os.path.join(b.out, "frames_cache")
    base = dict(os.environ, XDG_CACHE_HOME=cache)
    cores = os.cpu_count() or 1
    print(f"\nframes: {n} frames of `hard` on scenes/walk.json's animation, one process, "
          f"median of {b.repeat} (goal: wall per frame <= 1.3x the sum of the passes)")
    print("(ratio: wall per frame / its own passes; vs serial: / the serial runs' passes, since "
          "on few cores the writer's work slows the passes it overlaps; cpu: the process's CPU "
          f"time per frame; / floor: wall per frame over that CPU spread on the {cores} cores, "
          "the least wall it allows; MB: EXR size per frame)")
    print(f"{'run':<30}{'wall/frame ms':>14}{'passes ms':>11}{'ratio':>7}{'vs serial':>11}"
          f"{'readback ms':>13}{'cpu/frame ms':>14}{'/ floor':>9}{'to 1st pass ms':>16}{'MB':>7}")
    serial_env = {"PENUMBRA_SERIAL_WRITES": "1"}
    default_writers = default_writer_threads()
    modes = [("serial writes", serial_env, ()),
             (f"pipelined writes ({default_writers} writer{'s' * (default_writers > 1)})", {},
              ())]
    writers = [int(w) for w in b.args.writer_threads.split(",")] if b.args.writer_threads else (
        [1] if default_writers > 1 else [])
    for w in writers:
        modes.append((f"pipelined, {w} writer{'s' * (w > 1)}",
                      {"PENUMBRA_WRITER_THREADS": str(w)}, ()))
    for c in b.args.exr_compression.split(",") if b.args.exr_compression else ():
        modes.append((f"pipelined writes {c}", {}, ("--exr-compression", c)))
    binary = {}  # label -> another binary than this build's
    if b.args.baseline:
        modes.append(("baseline, pipelined", {}, ()))
        binary["baseline, pipelined"] = os.path.abspath(b.args.baseline)
    rows = {label: [] for label, _, _ in modes}
    for r in range(b.repeat):  # alternated, so all see the same machine
        for label, extra, options in modes:
            run = sequence(b, scene, n, dict(base, **extra), "run", binary.get(label), options)
            rows[label].append((run.wall * 1e3 / n, statistics.mean(run.passes),
                                statistics.mean(run.readbacks), run.cpu * 1e3 / n,
                                run.first if run.first is not None else float("nan"),
                                run.exr_bytes / 1e6))
    serial_passes = statistics.median(row[1] for row in rows["serial writes"])
    for label, _, _ in modes:
        per_frame, passes, readback, cpu, first, mb = (statistics.median(c)
                                                       for c in zip(*rows[label]))
        print(f"{label:<30}{per_frame:>14.1f}{passes:>11.1f}{per_frame / passes:>7.2f}"
              f"{per_frame / serial_passes:>11.2f}{readback:>13.1f}{cpu:>14.1f}"
              f"{per_frame / (cpu / cores):>9.2f}{first:>16.1f}{mb:>7.2f}")
    # Time to first pass: a one-frame render, cold cache (emptied first) and warm, and with the
    # cache off.
    for label, extra, empty in (("cold program cache", {}, True), ("warm program cache", {}, False),
                                ("program cache off", {"PENUMBRA_PROGRAM_CACHE": "0"}, False)):
        firsts = []
        for r in range(b.repeat):
            if empty:
                shutil.rmtree(cache, ignore_errors=True)
            firsts.append(sequence(b, scene, 1, dict(base, **extra), "first").first)
        print(f"{label:<30}{'':>14}{'':>11}{'':>7}{'':>11}{'':>13}{'':>14}{'':>9}"
              f"{statistics.median(firsts):>16.1f}")


def shared_libraries(binary):
    """How many shared libraries the dynamic loader maps for BINARY (`ldd` lines)."""
    r = subprocess.run(["ldd", binary], capture_output=True, text=True, check=True)
    return len(r.stdout.splitlines())


def startup(b):
    """The process's start-up (`startup` suite): shared libraries, wall time of `--version`,
    and `process.ms_to_first_pass` and wall time of a one-frame render with warm caches, for
    this build and for --baseline BINARY when given, alternated in one run."""
    scene = stretched_walk(b.out, 24)  # frame 1 of it
    base = dict(os.environ, XDG_CACHE_HOME=os.path.join(b.out, "startup_cache"))
    binaries = [("this build", b.binary)]
    if b.args.baseline:
        binaries.insert(0, ("baseline", os.path.abspath(b.args.baseline)))
    rows = {label: [] for label, _ in binaries}
    for label, binary in binaries:  # warm the program and Mesa caches, untimed
        sequence(b, scene, 1, base, "startup", binary)
    for _ in range(b.repeat):
        for label, binary in binaries:
            start = time.monotonic()
            subprocess.run([binary, "--version"], check=True, stdout=subprocess.DEVNULL)
            version_ms = (time.monotonic() - start) * 1e3
            run = sequence(b, scene, 1, base, "startup", binary)
            rows[label].append((version_ms, run.first, run.wall * 1e3))
    print(f"\nstartup: {b.size}, one `hard` frame of scenes/walk.json's animation, warm program "
          f"and Mesa caches, median of {b.repeat} (binaries alternated)")
    print(f"{'binary':<14}{'libraries':>10}{'--version ms':>14}{'to 1st pass ms':>16}"
          f"{'render wall ms':>16}  path")
    for label, binary in binaries:
        version_ms, first, wall = (statistics.median(c) for c in zip(*rows[label]))
        print(f"{label:<14}{shared_libraries(binary):>10}{version_ms:>14.1f}{first:>16.1f}"
              f"{wall:>16.1f}  {binary}")
