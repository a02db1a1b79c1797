"""The `bitmask_layers` suite of scripts/bench: what `bitmask`'s far layer costs. On the pareto
scenes (scripts/bench_pareto.py), at --size, `bitmask` at its defaults with `layers` 1 and 2,
and with --baseline BINARY also that binary's `layers` 2, the renders alternated in --repeat
rounds (one warm-up, one timed frame each): medians of the frame, the visibility pass and the
far layer's construction (its peel and microrects), and each run's ratio to `layers` 1.
"""
import json
import os
import statistics
import subprocess

import bench_pareto

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FAR_PASSES = ("bitmask_far_layer", "bitmask_far_microrects", "bitmask_far_neighbours")


def render(b, binary, scene, layers, label):
    """One warm-up and one timed frame; (frame ms, visibility pass ms, far construction ms)."""
    exr = os.path.join(b.out, f"layers_{label}.exr")
    subprocess.run([binary, "render", scene, "-t", "bitmask", "--size", b.size, "-o", exr,
                    "--warmup", "1", "--repeat", "1", "--quiet", "-D",
                    f"technique.layers={layers}"], check=True)
    with open(exr[:-4] + ".json", encoding="utf-8") as f:
        t = json.load(f)
    ms = {p["name"]: p["ms"] for p in t["passes"]}
    return (t["totals"]["frame_ms"], ms.get("bitmask_visibility", 0.0),
            sum(ms.get(p, 0.0) for p in FAR_PASSES))


def bitmask_layers(b):
    runs = [("layers 1", b.binary, 1), ("layers 2", b.binary, 2)]
    if b.args.baseline:
        runs.append(("baseline layers 2", os.path.abspath(b.args.baseline), 2))
    print(f"\nbitmask_layers: {b.size}, bitmask at its defaults, median of {b.repeat} rounds "
          f"(renders alternated; ratio: frame / layers 1)")
    print(f"{'scene':<22}{'run':<20}{'frame ms':>10}{'visibility':>12}{'far build':>11}"
          f"{'ratio':>8}")
    for name in bench_pareto.SCENES:
        scene = os.path.join(ROOT, "scenes", "conformance", f"{name}.json")
        rows = {label: [] for label, _, _ in runs}
        for _ in range(b.repeat):
            for label, binary, layers in runs:
                rows[label].append(render(b, binary, scene, layers, label.replace(" ", "_")))
        one = statistics.median(r[0] for r in rows["layers 1"])
        for label, _, _ in runs:
            frame, vis, far = (statistics.median(c) for c in zip(*rows[label]))
            print(f"{name:<22}{label:<20}{frame:>10.1f}{vis:>12.1f}{far:>11.1f}"
                  f"{frame / one:>8.2f}")
