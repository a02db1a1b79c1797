"""Each metric against each varied parameter: one line per combination of the other varied
values (and technique, and scene group where the report merges several), log axes for log
ranges, min-max bars on the time plots where the sweeps recorded them."""
import matplotlib.pyplot as plt
import matplotlib.ticker

from .plot_common import LINESTYLES, MARKERS, figure, save
from .values import MISSING, fmt_value, is_number, num_or_none, slug

# (key in the run, label on an axis).
METRICS = [
    ("mae", "MAE"),
    ("rmse", "RMSE"),
    ("p99", "99th percentile error"),
    ("shadow_mae", "shadow MAE"),
    ("time_total", "total frame time (ms)"),
]


def metric(run, key):
    if key == "time_total":
        return run.time()
    return num_or_none(run.rec["metrics"].get(key))


def axis_values(report, key):
    """The swept values of KEY over every sweep, in order, and their scale."""
    values, log = [], True
    for s in report.sweeps:
        for v in s.doc["varied"]:
            if v["key"] == key:
                values += [x for x in (v.get("values") or []) if x not in values]
                log = log and v.get("scale") == "log"
    return values, log


def collect(report, key, mkey):
    values, log = axis_values(report, key)
    numeric = bool(values) and all(is_number(v) for v in values)
    log = numeric and log and all(v > 0 for v in values)
    order = {fmt_value(v): i for i, v in enumerate(values)}
    others = [k for k in report.keys if k != key]
    groups = len(report.groups) > 1
    series = {}
    for run in report.runs:
        v = run.values.get(key, MISSING)
        y = metric(run, mkey)
        if v is MISSING or y is None:
            continue
        x = float(v) if numeric and is_number(v) else order.setdefault(fmt_value(v), len(order))
        combo = ((f"group {run.sweep.group + 1}",) if groups else ()) + (run.technique,) + tuple(
            run.value_text(k) for k in others)
        series.setdefault(combo, []).append((x, y, run.time_range() if mkey == "time_total"
                                             else None))
    return values, numeric, log, order, others, series


def draw_series(ax, series, techs, groups):
    styles = {t: LINESTYLES[i % len(LINESTYLES)] for i, t in enumerate(sorted(techs))}
    marks = {t: MARKERS[i % len(MARKERS)] for i, t in enumerate(sorted(techs))}
    cmap = plt.get_cmap("tab10" if len(series) <= 10 else "tab20")
    tpos = 1 if groups else 0
    for i, (combo, pts) in enumerate(sorted(series.items())):
        pts.sort(key=lambda p: (p[0], p[1]))
        tech = combo[tpos]
        parts = list(combo)
        if len(techs) <= 1:
            del parts[tpos]
        colour = cmap(i % cmap.N)
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=marks[tech], markersize=4,
                linestyle=styles[tech], color=colour, label=" · ".join(parts) or None)
        for x, y, rng in pts:
            if rng:
                ax.errorbar([x], [y], yerr=[[y - rng[0]], [rng[1] - y]], fmt="none",
                            ecolor=colour, elinewidth=0.8, capsize=2, alpha=0.8)


def plot(report, key, mkey, mlabel, plots_dir):
    values, numeric, log, order, others, series = collect(report, key, mkey)
    techs = {c[1 if len(report.groups) > 1 else 0] for c in series}
    groups = len(report.groups) > 1
    legend = len(series) > 1 or len(techs) > 1
    fig, ax = figure(9 if legend else 7, 5)
    draw_series(ax, series, techs, groups)
    if log:
        ax.set_xscale("log")
    if numeric and len(values) <= 12:
        # Ticks at the swept values, written as they were given.
        ax.set_xticks([float(v) for v in values], [fmt_value(v) for v in values])
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    if not numeric:
        ticks = sorted(order.items(), key=lambda kv: kv[1])
        ax.set_xticks([i for _, i in ticks], [name for name, _ in ticks],
                      rotation=30 if max((len(n) for n in order), default=0) > 8 else 0)
    ax.set_xlabel(key + (" (log scale)" if log else ""))
    ax.set_ylabel(mlabel)
    ax.set_title(f"{mlabel} against {key}")
    ax.grid(True, alpha=0.3, which="both" if log else "major")
    if not series:
        ax.text(0.5, 0.5, "no data", transform=ax.transAxes, ha="center", va="center")
    elif legend:
        n = len(series)
        title = " · ".join((["group"] if groups else [])
                           + (["technique"] if len(techs) > 1 else []) + others)
        ax.legend(fontsize=8 if n <= 16 else 7, ncol=1 if n <= 20 else 2, title=title,
                  title_fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return save(fig, plots_dir, f"{slug(mkey)}-vs-{slug(key)}")
