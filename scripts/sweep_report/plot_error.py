"""The error-against-time plot of one scene group: every run a point (coloured by the second
varied parameter, one marker per technique, min-max time bars where the sweep recorded them),
a step line per Pareto front, labels placed without overlaps, and each point's pixel position
for the page's tooltips."""
import matplotlib.colors
import matplotlib.cm
from matplotlib.lines import Line2D

from . import labels
from .fronts import metric_label, metric_value
from .plot_common import LINESTYLES, MARKERS, categorical_colours, figure, freeze_layout, save
from .values import MISSING, is_number

MARKER_AREA = 30  # scatter size in points²
MAX_CATEGORIES = 10  # more numeric colour values than this: a continuous map and a colour bar


class Colouring:
    """How points get their colour: by KEY's value (categories, or a colour bar for many numbers),
    or by technique where fewer than two keys vary."""

    def __init__(self, report, runs):
        self.key = report.keys[1] if len(report.keys) >= 2 else None
        texts, nums = [], []
        for r in runs:
            t = r.value_text(self.key) if self.key else r.technique
            if t not in texts:
                texts.append(t)
            v = r.values.get(self.key) if self.key else None
            nums.append(float(v) if is_number(v) else None)
        self.norm = None
        if self.key and len(texts) > MAX_CATEGORIES and all(n is not None for n in nums):
            lo, hi = min(nums), max(nums)
            log = lo > 0 and hi / lo > 20
            self.norm = (matplotlib.colors.LogNorm if log else matplotlib.colors.Normalize)(lo, hi)
            self.cmap = matplotlib.cm.get_cmap("viridis")
        self.texts = texts
        self.colours = dict(zip(texts, categorical_colours(len(texts))))
        self.colours[MISSING] = (0.5, 0.5, 0.5, 1.0)

    def of(self, run):
        if not self.key:
            return self.colours[run.technique]
        if self.norm is not None:
            return self.cmap(self.norm(float(run.values[self.key])))
        return self.colours[run.value_text(self.key)]

    def legend_handles(self):
        if self.norm is not None:
            return []
        return [Line2D([], [], marker="o", linestyle="", color=self.colours[t], label=t)
                for t in self.texts]


def label_keys(report, colouring, techniques):
    skip = {colouring.key} | ({"technique.name"} if len(techniques) > 1 else set())
    return [k for k in report.keys if k not in skip]


def draw_points(ax, pts, colouring, marker_of):
    for run, t, err in pts:
        c = colouring.of(run)
        rng = run.time_range()
        if rng:
            ax.errorbar([t], [err], xerr=[[t - rng[0]], [rng[1] - t]], fmt="none", ecolor=c,
                        elinewidth=0.9, capsize=2.5, alpha=0.8, zorder=2)
        ax.scatter([t], [err], color=[c], marker=marker_of[run.technique], s=MARKER_AREA,
                   edgecolors="black", linewidths=0.4, zorder=3)


def draw_fronts(ax, fronts, colouring, style_of, metric):
    for f in fronts:
        if not f.on_front:
            continue
        cs = {colouring.of(r) for r in f.on_front}
        colour = cs.pop() if len(cs) == 1 else "0.35"
        ax.step([r.time() for r in f.on_front], [metric_value(r, metric) for r in f.on_front],
                where="post", color=colour, linestyle=style_of[f.technique], linewidth=1.3,
                alpha=0.85, zorder=1)


def add_legend(fig, ax, colouring, techniques, marker_of, style_of):
    handles = colouring.legend_handles()
    if handles:
        leg = ax.legend(handles=handles, title=colouring.key or "technique", fontsize=8,
                        title_fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
        ax.add_artist(leg)
    elif colouring.norm is not None:
        sm = matplotlib.cm.ScalarMappable(norm=colouring.norm, cmap=colouring.cmap)
        fig.colorbar(sm, ax=ax, label=colouring.key, pad=0.01)
    kinds = [Line2D([], [], marker=marker_of[t], linestyle=style_of[t], color="0.25",
                    markerfacecolor="white", label=f"{t} (line: Pareto front)")
             for t in techniques]
    ax.legend(handles=kinds, title="technique", fontsize=8, title_fontsize=8,
              loc="lower left", bbox_to_anchor=(1.01, 0.0))


def plot(report, group, fronts, metric, plots_dir, name, subtitle):
    """Draws and saves the plot; returns its record for report.json and the page."""
    pts = [(r, r.time(), metric_value(r, metric)) for r in report.runs if r.sweep.group == group]
    pts = [p for p in pts if p[1] is not None and p[2] is not None]
    fronts = [f for f in fronts if f.group == group]
    techniques = sorted({r.technique for r, _, _ in pts})
    marker_of = {t: MARKERS[i % len(MARKERS)] for i, t in enumerate(techniques)}
    style_of = {f.technique: LINESTYLES[techniques.index(f.technique) % len(LINESTYLES)]
                if f.technique in techniques else "-" for f in fronts}
    colouring = Colouring(report, [p[0] for p in pts])
    fig, ax = figure(10, 6.2)
    draw_points(ax, pts, colouring, marker_of)
    draw_fronts(ax, fronts, colouring, style_of, metric)
    for values, set_scale in (([p[1] for p in pts], ax.set_xscale),
                              ([p[2] for p in pts], ax.set_yscale)):
        if values and min(values) > 0 and max(values) / min(values) > 20:
            set_scale("log")  # times or errors over more than a factor 20: log axis
    keys = label_keys(report, colouring, techniques)
    ax.set_xlabel("total frame time (ms)" + (", bars: min to max of the timed renders"
                                             if any(r.time_range() for r, _, _ in pts) else ""))
    ax.set_ylabel(metric_label(metric))
    ax.set_title(f"Error against time{subtitle}"
                 + (f"\nlabels: {', '.join(keys)}" if keys and pts else ""), fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.grid(True, which="minor", alpha=0.1)
    if pts:
        add_legend(fig, ax, colouring, techniques, marker_of, style_of)
    else:
        ax.text(0.5, 0.5, "no run has both a time and an error", transform=ax.transAxes,
                ha="center", va="center")
    freeze_layout(fig)
    return finish(fig, ax, pts, fronts, keys, colouring, metric, plots_dir, name)


def obstacles(pts, fronts, metric):
    """The error bars and the fronts' steps, as segments in data coordinates."""
    out = []
    for run, t, err in pts:
        rng = run.time_range()
        if rng:
            out.append((rng[0], err, rng[1], err))
    for f in fronts:
        steps = [(r.time(), metric_value(r, metric)) for r in f.on_front]
        for (t0, e0), (t1, e1) in zip(steps, steps[1:]):
            out += [(t0, e0, t1, e0), (t1, e0, t1, e1)]
    return out


def finish(fig, ax, pts, fronts, keys, colouring, metric, plots_dir, name):
    order = [r for f in fronts for r in f.on_front]
    order += sorted((r for r, _, _ in pts if r not in order), key=lambda r: r.time())
    by_run = {r: (t, err) for r, t, err in pts}
    items = [(*by_run[r], ", ".join(r.value_text(k) for k in keys), colouring.of(r), r.uid)
             for r in order if any(r.values[k] is not MISSING for k in keys)] if keys else []
    marker_px = MARKER_AREA ** 0.5 * fig.dpi / 72 + 2  # the marker's width, and a margin
    placed, left_out = labels.place(fig, ax, items, marker_px, obstacles(pts, fronts, metric))
    height = fig.bbox.height
    points = []
    for r, t, err in pts:
        px, py = ax.transData.transform((t, err))
        points.append({"run": r.uid, "x": round(float(px), 1), "y": round(float(height - py), 1)})
    record = {"name": save(fig, plots_dir, name), "colour_key": colouring.key, "points": points,
              "labels": [{"run": uid, "text": text,
                          "box": [round(b[0], 1), round(height - b[3], 1), round(b[2], 1),
                                  round(height - b[1], 1)]} for uid, text, b in placed],
              "unlabelled": left_out if keys else [],
              "width": int(round(fig.bbox.width)), "height": int(round(height))}
    return record
