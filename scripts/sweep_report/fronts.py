"""Pareto fronts of error against time. Runs are only comparable when measured against the same
reference: one front per scene group, reference image, combination of the non-technique varied
values (keys not starting with "technique.") and technique."""
import math
import os

from .sweeps import ReportError
from .values import num_or_none

DEFAULT_METRIC = "shadow_mae"
KNOWN_METRICS = ["mae", "rmse", "max", "p99", "shadow_mae", "fail_fraction"]
NOT_ERRORS = {"shadow_pixels"}  # a count, not an error: never a Pareto metric
LABELS = {"mae": "MAE", "rmse": "RMSE", "max": "max error", "p99": "99th percentile error",
          "shadow_mae": "shadow MAE", "fail_fraction": "share of pixels off by > 0.05"}


def is_technique_key(key):
    return key == "technique" or key.startswith("technique.")


def metric_names(report):
    names = list(KNOWN_METRICS)
    for run in report.runs:
        for k, v in run.rec["metrics"].items():
            if k not in names and k not in NOT_ERRORS and num_or_none(v) is not None:
                names.append(k)
    return names


def check_metric(report, name):
    names = metric_names(report)
    if name not in names:
        raise ReportError(f"--pareto-metric: unknown metric '{name}' (one of: {', '.join(names)})")


def metric_value(run, name):
    """The run's metric NAME; shadow_mae falls back to MAE where a run has no shadow pixels."""
    v = num_or_none(run.rec["metrics"].get(name))
    if v is None and name == "shadow_mae":
        v = num_or_none(run.rec["metrics"].get("mae"))
    return v


def metric_label(name):
    if name == "shadow_mae":
        return "shadow MAE (MAE where a run has no shadow pixels)"
    return LABELS.get(name, name)


class Front:
    def __init__(self, index, group, reference, combo, technique):
        self.label = f"F{index}"
        self.group, self.reference, self.combo, self.technique = group, reference, combo, technique
        self.runs = []      # every run of the front's combination and technique
        self.on_front = []  # the runs no other run beats in both time and error, by time

    def describe(self):
        """The combination as "key=value, ..." (empty where no scene parameter varies)."""
        return ", ".join(f"{k}={v}" for k, v in self.combo)


def pareto(points):
    """points: [(time, error, run)]. The ones no other point beats in both time and error."""
    front, best = [], math.inf
    for t, err, run in sorted(points, key=lambda p: (p[0], p[1])):
        if err < best:
            front.append(run)
            best = err
    return front


def assign(report, metric):
    """The report's fronts, in the order of their first run; sets each run's .front."""
    scene_keys = [k for k in report.keys if not is_technique_key(k)]
    fronts = {}
    for run in report.runs:
        ref = run.path("reference")
        ref = os.path.basename(ref) if ref else ""
        combo = tuple((k, run.value_text(k)) for k in scene_keys)
        key = (run.sweep.group, ref, combo, run.technique)
        if key not in fronts:
            fronts[key] = Front(len(fronts) + 1, run.sweep.group, ref, combo, run.technique)
        run.front = fronts[key]
        run.front.runs.append(run)
    for front in fronts.values():
        pts = [(r.time(), metric_value(r, metric), r) for r in front.runs]
        front.on_front = pareto([p for p in pts if p[0] is not None and p[1] is not None])
    return list(fronts.values())
