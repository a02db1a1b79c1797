"""`scripts/bench pareto`: every technique's quality parameters swept on a conformance subset,
each run's shadow-region MAE against `exact` and its equal-error ratio: its time over the time
of the cheapest `reference` of at most its error (scripts/equal_error.py: interpolated between
the two N that bracket the error; '<' marks an upper bound where the run beats reference's
largest N). The headline figure of each technique (issue 19).

Each (scene, sweep) is one `penumbra sweep` folder, OUT/pareto/SCENE/SWEEP, against `exact`
N = 32 (the sweep's default reference, cached in OUT/pareto/references): the error is the
sweep's `shadow_mae` of visibility over the whole image (pixels where exact or the run is below
0.999), the time its median frame ms after one warm-up. The folders are resumable (a rerun
reuses unchanged runs). scripts/sweep-report merges them into OUT/pareto/report/ (one
error-against-time plot per scene with every technique's front); OUT/pareto/pareto.json and
pareto.csv hold every run. Scenes, and why each:

  light_size_0.25      one sphere under a 0.25 m light: a small penumbra (well under a
                       quarter of the image), where adaptive sampling should pay most
  light_size_2         the same sphere under a 2 m light: a large penumbra
  spheres_three_sizes  four casters at different heights under a 2 m light: several blocker
                       depths in one kernel (css's failure case), overlapping penumbrae
  bar_grid             nine thin bars: thin casters whose penumbrae overlap (adaptive's worst)
  engine               the 110k-triangle engine under a 3 m light: a heavy mesh, where every
                       shadow map costs most
"""
import argparse
import csv
import json
import os
import shutil
import statistics
import subprocess
import sys
import time

import equal_error as ee

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = ["light_size_0.25", "light_size_2", "spheres_three_sizes", "bar_grid", "engine"]
# (sweep label, technique, fixed overrides, --vary specs); reference's --vary comes from
# --pareto-samples.
SWEEPS = [
    ("adaptive", "adaptive", {}, ["technique.target_error=0.01,0.02,0.04",
                                  "technique.max_maps=81,289"]),
    ("adaptive_rss", "adaptive", {"technique.estimate": "rss"},
     ["technique.target_error=0.007,0.014,0.028"]),
    ("adaptive_global", "adaptive", {"technique.metric": "global"},
     ["technique.epsilon=0.001,0.003,0.01"]),
    # The defaults with every pixel tested against the maps: what skip_lit saves, side by side.
    ("adaptive_all_pixels", "adaptive", {"technique.skip_lit": False},
     ["technique.target_error=0.02"]),
    # The defaults with every map at map_size (max_texel 0): what the coarser maps of narrow
    # casters' windows save, side by side (with skip_lit a map's rendering is most of its cost).
    ("adaptive_full_maps", "adaptive", {"technique.max_texel": 0},
     ["technique.target_error=0.02"]),
    # The defaults with splits tested and weighted only in the screen tiles around their
    # disagreements (off by default: on llvmpipe it saved little), side by side.
    ("adaptive_tiles", "adaptive", {"technique.refine_tile": 32},
     ["technique.target_error=0.02"]),
    ("bitmask", "bitmask", {}, ["technique.budget=5,8,12,0",
                                "technique.occluders=micropatch,microquad,microrect",
                                "technique.layers=1,2"]),
    ("css", "css", {}, ["technique.order=2,4,8", "technique.map_size=256,512",
                        "technique.filter=sat,mipmap", "technique.blocker_depth=middle,nearest"]),
    # The defaults with every pixel evaluated: what `interpolate` saves, side by side.
    ("css_every_pixel", "css", {"technique.interpolate": 0}, ["technique.order=4"]),
    # No 512 map: its splat takes about 4x the 256's (47 s a frame at 320x240 on light_size_2,
    # llvmpipe under load) and its error was no lower (light_size_0.25: 0.027 against 0.024).
    ("ssm", "ssm", {}, ["technique.map_size=128,256", "technique.layers=1,4",
                        "technique.lod_depth=0.005,0.02"]),
]
TECHNIQUES = list(dict.fromkeys(t for _, t, _, _ in SWEEPS))
PENUMBRA_QUARTER = 0.25  # adaptive's goal: <= 0.5 where at most this share is in penumbra


def add_arguments(p):
    p.add_argument("--pareto-scenes", type=parse_scenes, default=SCENES,
                   help="pareto: conformance scenes by name or scene files (.json, e.g. "
                   "scripts/random-scenes' output), comma-separated; a file's rows are named "
                   f"by its stem (default: {','.join(SCENES)})")
    p.add_argument("--pareto-samples", type=parse_samples, default=list(range(1, 17)),
                   help="pareto: reference's N, A:B or a list (default 1:16, every N)")
    p.add_argument("--pareto-techniques", type=parse_techniques, default=TECHNIQUES,
                   help="pareto: the techniques swept besides reference, comma-separated "
                   f"(default: {','.join(TECHNIQUES)})")
    p.add_argument("--pareto-from", metavar="DIR",
                   help="pareto: render nothing; the tables from DIR/SCENE/SWEEP/sweep.csv (the "
                   "sweeps of an earlier run, e.g. device-bench's pareto-sweeps.tar.gz unpacked: "
                   "DIR is its pareto/ folder); a sweep missing there is left out")


def conformance_file(name):
    return os.path.join(ROOT, "scenes", "conformance", f"{name}.json")


# A scene's file by its row name: the conformance scenes', and those --pareto-scenes named by
# their path.
SCENE_FILES = {s: conformance_file(s) for s in SCENES}


def parse_scenes(text):
    """'a,b' -> ['a', 'b'], each a scene of scenes/conformance or a scene file (ending in
    .json; its row name is its stem, recorded in SCENE_FILES); argparse's error otherwise."""
    names = []
    for s in (s for s in text.split(",") if s):
        if s.endswith(".json"):
            name, path = os.path.splitext(os.path.basename(s))[0], os.path.abspath(s)
            if not os.path.isfile(path):
                raise argparse.ArgumentTypeError(f"no scene file '{s}'")
        else:
            name, path = s, conformance_file(s)
            if not os.path.isfile(path):
                raise argparse.ArgumentTypeError(f"no conformance scene '{s}'")
        if SCENE_FILES.get(name, path) != path or name in names:
            raise argparse.ArgumentTypeError(f"two scenes named '{name}' (rows and folders are "
                                             "named by the file's stem)")
        SCENE_FILES[name] = path
        names.append(name)
    if not names:
        raise argparse.ArgumentTypeError("no scene")
    return names


def parse_techniques(text):
    """'adaptive,css' -> ['adaptive', 'css'], each swept here; argparse's error otherwise."""
    techniques = [t for t in text.split(",") if t]
    for t in techniques:
        if t not in TECHNIQUES:
            raise argparse.ArgumentTypeError(f"no pareto sweep of '{t}' ({','.join(TECHNIQUES)})")
    if not techniques:
        raise argparse.ArgumentTypeError("no technique")
    return techniques


def parse_samples(text):
    """'1:16' -> 1..16, '1,2,4' -> [1, 2, 4]; argparse's error otherwise."""
    try:
        if ":" in text:
            a, b = (int(v) for v in text.split(":"))
            values = list(range(a, b + 1))
        else:
            values = [int(v) for v in text.split(",")]
    except ValueError:
        values = []
    if not values or min(values) < 1 or max(values) > 32:
        raise argparse.ArgumentTypeError(f"expected A:B or a list of N in 1..32, got '{text}'")
    return values


class Defaults:
    """Each technique's parameter defaults (`penumbra techniques NAME --json`)."""

    def __init__(self, binary):
        self.binary, self.cache = binary, {}

    def of(self, technique):
        if technique not in self.cache:
            out = subprocess.run([self.binary, "techniques", technique, "--json"],
                                 capture_output=True, text=True, check=True).stdout
            self.cache[technique] = {p["key"]: p["default"] for p in json.loads(out)["params"]}
        return self.cache[technique]

    def at_defaults(self, technique, fixed, values):
        d = self.of(technique)
        return not fixed and all(d.get(k.split(".", 1)[1]) == v for k, v in values.items())


def csv_value(text):
    """A sweep.csv cell as sweep.json has it: JSON where it parses (5, 0.02, false, null),
    else the word."""
    try:
        return json.loads(text)
    except ValueError:
        return text


def sweep_from_csv(b, scene, label):
    """The sweep.json document's fields this suite reads, from --pareto-from's sweep.csv; None
    where that sweep is missing."""
    path = os.path.join(b.args.pareto_from, scene, label, "sweep.csv")
    if not os.path.isfile(path):
        print(f"bench: pareto: no {path}; {label} on {scene} is left out", flush=True)
        b.failed.append(f"{scene} {label}")
        return None
    with open(path, encoding="utf-8", newline="") as f:
        rows = list(csv.DictReader(f))
    return {"runs": [{"values": {k: csv_value(v) for k, v in r.items()
                                 if k.startswith("technique.")},
                      "metrics": {k: csv_value(r.get(k, "null")) for k in ("shadow_mae", "mae")},
                      "time_ms": {"total": csv_value(r.get("total_ms", "null"))},
                      "reference": None} for r in rows]}


def sweep(b, scene, label, technique, fixed, varied, root):
    """Runs (or resumes) one sweep folder; its sweep.json document, or None where the sweep
    failed (a technique a driver refuses leaves the other techniques' figures standing)."""
    if b.args.pareto_from:
        return None, sweep_from_csv(b, scene, label)
    folder = os.path.join(root, scene, label)
    cmd = [b.binary, "sweep", SCENE_FILES[scene],
           "-t", technique, "--size", b.size, "--warmup", "1", "--repeat", str(b.repeat),
           "--cache", os.path.join(root, "references"), "--no-report", "--quiet", "-o", folder]
    for k, v in fixed.items():
        cmd += ["-D", f"{k}={json.dumps(v)}"]
    for v in varied:
        cmd += ["--vary", v]
    start = time.monotonic()
    if subprocess.run(cmd).returncode != 0:
        print(f"bench: pareto: the sweep of {label} on {scene} failed ({folder}); its runs are "
              "left out", flush=True)
        b.failed.append(f"{scene} {label}")
        return folder, None
    with open(os.path.join(folder, "sweep.json"), encoding="utf-8") as f:
        doc = json.load(f)
    print(f"pareto: {scene} {label}: {len(doc['runs'])} runs in {time.monotonic() - start:.0f} s",
          flush=True)
    return folder, doc


def error_of(run):
    """The run's shadow-region MAE (its MAE where no pixel is in shadow, as sweep-report)."""
    m = run["metrics"]
    return m.get("shadow_mae") if m.get("shadow_mae") is not None else m.get("mae")


def penumbra_share(exr):
    """Share of EXR's pixels whose visibility is strictly between 0 and 1 (oiiotool); None
    where oiiotool is missing (a GPU machine with only the renderer carried to it) or there is
    no image (--pareto-from)."""
    if exr is None or not shutil.which("oiiotool"):
        return None
    r = subprocess.run(["oiiotool", exr, "--ch", "visibility", "--rangecheck", "0.0001",
                        "0.9999"], capture_output=True, text=True, check=True)
    counts = [int(line.split()[0]) for line in r.stdout.splitlines()
              if line.strip() and line.split()[0].isdigit()]
    if len(counts) != 3 or not sum(counts):
        raise SystemExit(f"bench: pareto: cannot count the penumbra of {exr}")
    return counts[2] / sum(counts)


def params_text(values):
    return " ".join(f"{k.split('.', 1)[1]}={v}" for k, v in values.items())


def scene_rows(b, scene, root, samples, defaults, techniques):
    """Every sweep of SCENE: (rows, folders, reference front, penumbra share)."""
    folder, ref = sweep(b, scene, "reference", "reference", {},
                        ["technique.samples=" + ",".join(str(n) for n in samples)], root)
    if ref is None:
        raise SystemExit(f"bench: pareto: no reference on {scene}: no ratio can be computed")
    folders = [folder] if folder else []
    refs = [(r["values"]["technique.samples"], error_of(r), r["time_ms"].get("total"))
            for r in ref["runs"]]
    front = ee.reference_front(refs)
    share = penumbra_share(ref["runs"][0]["reference"])
    rows = [{"scene": scene, "sweep": "reference", "technique": "reference",
             "params": f"samples={n}", "error": e, "ms": t, "ratio": None, "n_equal": n,
             "kind": "front" if (n, e, t) in front else "", "defaults": n == 16}
            for n, e, t in refs]
    for label, technique, fixed, varied in SWEEPS:
        if technique not in techniques:
            continue
        folder, doc = sweep(b, scene, label, technique, fixed, varied, root)
        if doc is None:
            continue
        if folder:
            folders.append(folder)
        for r in doc["runs"]:
            err, ms = error_of(r), r["time_ms"].get("total")
            if err is None or ms is None:
                continue
            ratio, n, kind = ee.equal_error_ratio(ms, err, front)
            rows.append({"scene": scene, "sweep": label, "technique": technique,
                         "params": " ".join(filter(None, [params_text(fixed),
                                                          params_text(r["values"])])),
                         "error": err, "ms": ms, "ratio": ratio, "n_equal": n, "kind": kind,
                         "defaults": defaults.at_defaults(technique, fixed, r["values"])})
    return rows, folders, front, share


def print_rows(rows):
    print(f"\n{'scene':<20}{'sweep':<16}{'params':<40}{'error':>9}{'ms':>10}{'N equal':>9}"
          f"{'ratio':>8}")
    for r in rows:
        ratio = ee.fmt_ratio(r["ratio"], r["kind"]) if r["ratio"] is not None else "-"
        mark = " *" if r["defaults"] else ""
        print(f"{r['scene']:<20}{r['sweep']:<16}{r['params'][:39]:<40}{r['error']:>9.4f}"
              f"{r['ms']:>10.1f}{r['n_equal']:>9.2f}{ratio:>8}{mark}")
    print("(* the technique's defaults; reference's N = 16. N equal: reference's N at the run's "
          "error, interpolated; '<': the run beats reference's largest N, ratio an upper bound)")


def summary(rows, scenes):
    """{technique: {scene: (defaults ratio, kind, best row)}} over the non-reference runs."""
    out = {}
    for r in rows:
        if r["ratio"] is None:
            continue
        cell = out.setdefault(r["technique"], {}).setdefault(r["scene"], [None, None, None])
        if r["defaults"]:
            cell[0], cell[1] = r["ratio"], r["kind"]
        if cell[2] is None or r["ratio"] < cell[2]["ratio"]:
            cell[2] = r
    return {t: {s: by[s] for s in scenes if s in by} for t, by in out.items()}


def print_summary(table, scenes):
    """The README's table: per technique and scene, the ratio at its defaults / its best."""
    print("\nEqual-error ratio, at the technique's defaults / the best of its sweep "
          "(time / reference's time at equal error; lower is better):\n")
    print("| technique | " + " | ".join(scenes) + " | median (defaults) | median (best) | best |")
    print("|---" * (len(scenes) + 4) + "|")
    for technique, by in table.items():
        cells = []
        for s in scenes:
            d, kind, best = by.get(s, (None, None, None))
            dt = ee.fmt_ratio(d, kind) if d is not None else "-"
            cells.append(f"{dt} / {ee.fmt_ratio(best['ratio'], best['kind'])}" if best else "-")
        ds = [v[0] for v in by.values() if v[0] is not None]
        bs = [v[2]["ratio"] for v in by.values() if v[2]]
        top = min((v[2] for v in by.values() if v[2]), key=lambda r: r["ratio"])
        print(f"| `{technique}` | " + " | ".join(cells) +
              f" | {statistics.median(ds) if ds else float('nan'):.2f}"
              f" | {statistics.median(bs):.2f} | {ee.fmt_ratio(top['ratio'], top['kind'])} "
              f"({top['scene']}, {top['params']}) |")


def goal(name, bound, rows):
    """One line per goal: each scene's ratio, met where it (an upper bound or not) is <= bound;
    where some scenes meet it and others not, how many do."""
    if not rows:
        print(f"{name} (goal <= {bound}): no scene of this kind in the subset")
        return
    parts, met = [], 0
    for r in rows:
        parts.append(f"{r['scene']}{r.get('note', '')} {ee.fmt_ratio(r['ratio'], r['kind'])}")
        met += r["ratio"] <= bound
    verdict = ": met" if met == len(rows) else ": NOT met"
    if len(rows) > 1 and 0 < met < len(rows):
        verdict += f" (met on {met} of {len(rows)})"
    print(f"{name} (goal <= {bound}): " + ", ".join(parts) + verdict)


def pick(rows, sweep, params=None):
    """SWEEP's runs with PARAMS (key=value words, in any order), or at the technique's
    defaults."""
    return [r for r in rows if r["sweep"] == sweep and (
        set(r["params"].split()) == set(params.split()) if params else r["defaults"])]


def print_goals(rows, shares):
    print("\nGoals (issue 19), at the defaults unless named:")
    adaptive = pick(rows, "adaptive")
    if None in shares.values():
        goal("adaptive (penumbra share unknown: no oiiotool)", 0.5, adaptive)
    else:
        for r in adaptive:
            r["note"] = f" (penumbra {100 * shares[r['scene']]:.0f}%)"
        goal("adaptive, penumbra <= 1/4 of the image", 0.5,
             [r for r in adaptive if shares[r["scene"]] <= PENUMBRA_QUARTER])
        goal("adaptive, elsewhere", 1.1,
             [r for r in adaptive if shares[r["scene"]] > PENUMBRA_QUARTER])
    for budget in (5, 8, 12):
        goal(f"bitmask budget {budget} (microrects, two layers)", 0.5,
             pick(rows, "bitmask", f"budget={budget} occluders=microrect layers=2"))
    goal("css, one light", 0.2, pick(rows, "css"))
    goal("ssm", 0.1, pick(rows, "ssm"))


def write(root, rows, meta):
    with open(os.path.join(root, "pareto.json"), "w", encoding="utf-8") as f:
        json.dump(dict(meta, schema="penumbra-bench-pareto", rows=rows), f, indent=1)
    keys = ["scene", "sweep", "technique", "params", "error", "ms", "n_equal", "ratio", "kind",
            "defaults"]
    with open(os.path.join(root, "pareto.csv"), "w", encoding="utf-8", newline="") as f:
        w = csv.DictWriter(f, keys, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)


def pareto(b):
    """The suite: every sweep of every scene, the tables, pareto.json/.csv and the report."""
    scenes, samples = b.args.pareto_scenes, b.args.pareto_samples
    root = os.path.join(b.out, "pareto")
    os.makedirs(root, exist_ok=True)
    defaults, rows, folders, shares, fronts = Defaults(b.binary), [], [], {}, {}
    b.failed = []
    for scene in scenes:
        r, f, fronts[scene], shares[scene] = scene_rows(b, scene, root, samples, defaults,
                                                                b.args.pareto_techniques)
        rows += r
        folders += f
    print_rows(rows)
    print("\nPenumbra (share of the image, exact): " +
          ", ".join(f"{s} {100 * shares[s]:.0f}%" if shares[s] is not None else f"{s} ?"
                    for s in scenes))
    print_summary(summary(rows, scenes), scenes)
    print_goals(rows, shares)
    version = subprocess.run([b.binary, "--version"], capture_output=True, text=True).stdout
    write(root, rows, {"size": b.size, "repeat": b.repeat, "version": version.strip(),
                       "date": time.strftime("%Y-%m-%d"), "penumbra_share": shares,
                       "reference_fronts": fronts})
    if b.args.pareto_from:
        print(f"\n{root}/pareto.json, pareto.csv (from {b.args.pareto_from}; no report: "
              "sweep.csv holds no images)")
    else:
        report(root, folders)
    if b.failed:
        raise SystemExit("bench: pareto: these sweeps failed and are left out: " +
                         ", ".join(b.failed))


def report(root, folders):
    """scripts/sweep-report over the sweep folders: ROOT/report."""
    out = os.path.join(root, "report")
    # matplotlib warns about every crowded parameter plot: its output only where it fails.
    # This interpreter where it has matplotlib (a GPU machine's may be only in the Python that
    # runs the bench), else the script's own, Debian's /usr/bin/python3 (scripts/setup installs
    # python3-matplotlib there; a pyenv python3 first on PATH has none).
    script = os.path.join(ROOT, "scripts", "sweep-report")
    has = subprocess.run([sys.executable, "-c", "import matplotlib"], capture_output=True)
    command = [sys.executable, script] if has.returncode == 0 else [script]
    r = subprocess.run(command + [*folders, "-o", out], capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"bench: pareto: scripts/sweep-report failed: {r.stderr.strip()}")
    print(f"\n{root}/pareto.json, pareto.csv; error against time with every technique's front: "
          f"{out}/index.html (plots/error-vs-time-g*.png)")
