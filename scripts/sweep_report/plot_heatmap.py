"""A heatmap of the Pareto metric over the first two varied parameters (technique.name aside,
which splits panels instead): one panel per scene group, technique and value of the remaining
keys, every cell written out, one colour bar for all panels."""
import math

import numpy as np

from .fronts import metric_value
from .plot_common import figure, save
from .values import MISSING, fmt_num

MAX_PANELS = 12


def axes_keys(report):
    keys = []
    for k in report.keys:
        if k != "technique.name" and len({r.value_text(k) for r in report.runs} - {MISSING}) > 1:
            keys.append(k)
    return keys[:2] if len(keys) >= 2 else None


def ordered(texts):
    out = []
    for t in texts:
        if t not in out:
            out.append(t)
    return out


def panels(report, keys, metric):
    """{(group, technique, rest): {(row text, column text): value}} and the row/column texts."""
    rest_keys = [k for k in report.keys if k not in keys and k != "technique.name"]
    cells = {}
    for r in report.runs:
        v = metric_value(r, metric)
        a, b = r.value_text(keys[0]), r.value_text(keys[1])
        if v is None or MISSING in (a, b):
            continue
        rest = ", ".join(f"{k}={r.value_text(k)}" for k in rest_keys)
        cells.setdefault((r.sweep.group, r.technique, rest), {})[(a, b)] = v
    rows = ordered(r.value_text(keys[0]) for r in report.runs if r.value_text(keys[0]) != MISSING)
    cols = ordered(r.value_text(keys[1]) for r in report.runs if r.value_text(keys[1]) != MISSING)
    return cells, rows, cols


def plot(report, metric, plots_dir):
    """Draws plots/heatmap.{png,svg,pdf}; returns (name, keys) or None where fewer than two
    parameters vary."""
    keys = axes_keys(report)
    if not keys:
        return None
    cells, rows, cols = panels(report, keys, metric)
    if not cells:
        return None
    items = sorted(cells.items())[:MAX_PANELS]
    values = [v for _, c in items for v in c.values()]
    lo, hi = min(values), max(values)
    n = len(items)
    ncol = min(n, 3)
    nrow = math.ceil(n / ncol)
    cw, ch = max(3.2, 0.9 * len(cols) + 1.6), max(2.4, 0.45 * len(rows) + 1.4)
    fig, axs = figure(cw * ncol + 1.2, ch * nrow + 0.6, nrow, ncol)
    axs = list(np.atleast_1d(axs).ravel())
    for ax in axs[n:]:
        fig.delaxes(ax)  # the last row's empty places
    image = None
    for ax, ((group, tech, rest), c) in zip(axs, items):
        grid = np.full((len(rows), len(cols)), np.nan)
        for (a, b), v in c.items():
            grid[rows.index(a), cols.index(b)] = v
        image = ax.imshow(grid, cmap="magma_r", vmin=lo, vmax=hi if hi > lo else lo + 1e-9,
                          aspect="auto")
        for i in range(len(rows)):
            for j in range(len(cols)):
                if not np.isnan(grid[i, j]):
                    dark = (grid[i, j] - lo) / ((hi - lo) or 1) > 0.55
                    ax.text(j, i, fmt_num(grid[i, j], 3), ha="center", va="center", fontsize=7,
                            color="white" if dark else "black")
        ax.set_xticks(range(len(cols)), cols, fontsize=7, rotation=30 if len(cols) > 4 else 0)
        ax.set_yticks(range(len(rows)), rows, fontsize=7)
        ax.set_xlabel(keys[1], fontsize=8)
        ax.set_ylabel(keys[0], fontsize=8)
        title = tech + (f" · group {group + 1}" if len(report.groups) > 1 else "")
        ax.set_title(title + (f"\n{rest}" if rest else ""), fontsize=8)
    bar = fig.colorbar(image, ax=list(axs[:n]), shrink=0.9)
    bar.set_label(metric + " (lower is better)", fontsize=8)
    fig.suptitle(f"{metric} over {keys[0]} and {keys[1]}"
                 + (f" (first {MAX_PANELS} of {len(cells)} panels)" if len(cells) > n else ""),
                 fontsize=10)
    return save(fig, plots_dir, "heatmap"), keys
