"""The report's index.html: the sweeps' settings, the error-against-time plots (one per scene
group, each point a tooltip and a link to its row), the fronts, the per-parameter plots and the
runs table. Every link is relative, so the page works opened from disk."""
import os

from . import page_runs
from .fronts import metric_value
from .page_assets import CSS, JS
from .values import MISSING, e, fmt_num, fmt_value, href


def size_text(size):
    return f"{size[0]}×{size[1]}" if isinstance(size, list) and len(size) == 2 else fmt_value(size)


def technique_text(sweep, report):
    techs = []
    for r in report.runs:
        if r.sweep is sweep and r.technique not in techs:
            techs.append(r.technique)
    if "technique.name" in sweep.keys:
        return "varied (technique.name): " + ", ".join(techs)
    return ", ".join(techs) or str(sweep.doc.get("technique", "?"))


def sweep_rows(report, s):
    """(row name, HTML cell) pairs describing sweep S."""
    doc, ref = s.doc, s.doc.get("reference") or {}
    links = [f'<a href="{href(report.link(os.path.join(s.folder, n)))}">{e(n)}</a>'
             for n in ("sweep.json", "sweep.csv") if os.path.isfile(os.path.join(s.folder, n))]
    rows = [("folder", f"<code>{e(s.folder)}</code> " + " · ".join(links)),
            ("scene", f"<code>{e(doc.get('scene', '?'))}</code>"),
            ("technique", e(technique_text(s, report))),
            ("size", e(size_text(doc.get("size")))),
            ("frame", e(fmt_value(doc.get("frame", 0)))),
            ("runs", str(len(doc["runs"])))]
    for v in doc["varied"]:
        rows.append((f"varied: {v['key']}", e(", ".join(fmt_value(x) for x in v.get("values") or [])
                                               + f" ({v.get('scale', 'linear')})")))
    rows.append(("reference technique", e(ref.get("technique", "?"))))
    overrides = ref.get("overrides") or {}
    rows += [(f"reference: {k}", e(fmt_value(v))) for k, v in overrides.items()] or [
        ("reference overrides", "none")]
    refs = sorted({r.path("reference") for r in report.runs
                   if r.sweep is s and r.path("reference")})
    if refs:
        rows.append(("reference images", ", ".join(
            page_runs.file_link(report, p, os.path.relpath(p, s.folder)) for p in refs)))
    if len(report.groups) > 1:
        rows.append(("scene group", str(s.group + 1)))
    return rows


def settings(report):
    """One column per sweep; rows a sweep lacks (its own varied keys) are blank there."""
    per = [dict(sweep_rows(report, s)) for s in report.sweeps]
    names = []
    for s in report.sweeps:
        names += [n for n, _ in sweep_rows(report, s) if n not in names]
    many = len(report.sweeps) > 1
    out = ["<h2>Sweeps</h2>" if many else "<h2>Settings</h2>", "<table>"]
    if many:
        out.append("<tr><th></th>" + "".join(f"<th>{e(s.label)}</th>" for s in report.sweeps)
                   + "</tr>")
    for n in names:
        out.append(f"<tr><th>{e(n)}</th>" + "".join(f"<td>{p.get(n, MISSING)}</td>" for p in per)
                   + "</tr>")
    out.append("</table>")
    return "\n".join(out)


def group_text(report, g):
    (scene, size, frame, ref_tech, overrides), sweeps = report.groups[g]
    size = size_text(sweeps[0].doc.get("size"))
    text = f"{scene} · {size} · frame {frame} · reference {ref_tech}"
    return text + ("" if overrides == "{}" else f" {overrides}")


def plot_links(name, prefix="plots/"):
    return " ".join(f'<a href="{href(prefix + name + "." + x)}">{x.upper()}</a>'
                    for x in ("png", "svg", "pdf"))


def tooltip(run, metric):
    vals = ", ".join(f"{k}={run.value_text(k)}" for k in run.values)
    on = run.front and run in run.front.on_front
    return (f"{run.uid} · {run.technique}" + (f" · {vals}" if vals else "")
            + f" · {fmt_num(run.time())} ms · {metric} {fmt_num(metric_value(run, metric))}"
            + f" · front {run.front.label}{' (on it)' if on else ''}")


def error_section(report, plots, metric):
    by_uid = {r.uid: r for r in report.runs}
    many = len(report.groups) > 1
    out = ["<h2>Error against time</h2>",
           '<p class="note">One Pareto front (step line) per combination of the varied values '
           "that change the scene (keys not starting with <code>technique.</code>) and per "
           "technique: runs of different light sizes, say, are measured against different "
           "references and never share a front. Hover a point for its run; click it for its row. "
           "Labels that would overlap are left out.</p>"]
    if many:
        out.append(f'<p class="note"><b>{len(report.groups)} scene groups</b>: these sweeps '
                   "differ in scene, size, frame or reference, so their errors are not "
                   "comparable; each group has its own plot and fronts.</p>")
    for g, p in enumerate(plots):
        if many:
            out.append(f"<h3>Scene group {g + 1}: {e(group_text(report, g))}</h3>")
        name, w, h = p["name"], p["width"], p["height"]
        areas = "".join(
            f'<area shape="circle" coords="{pt["x"]:.0f},{pt["y"]:.0f},6" '
            f'href="#{by_uid[pt["run"]].row}" title="{e(tooltip(by_uid[pt["run"]], metric))}" '
            f'alt="{e(pt["run"])}">' for pt in p["points"])
        n_lab = len(p["labels"])
        shown = (f"{n_lab} of {len(p['points'])} points labelled" if p["labels"] or p["unlabelled"]
                 else "points unlabelled (nothing varies but the colour)")
        out.append(f'<div class="plots scroll"><figure>'
                   f'<img class="map" src="plots/{href(name)}.png" usemap="#map-{g}" '
                   f'width="{w}" height="{h}" alt="error against time">'
                   f'<map name="map-{g}">{areas}</map>'
                   f"<figcaption>{e(shown)}; colour: {e(p['colour_key'] or 'technique')} · "
                   f"{plot_links(name)}</figcaption></figure></div>")
    return "\n".join(out)


def fronts_table(report, fronts, metric):
    out = ["<h2>Pareto fronts</h2>", '<div class="scroll"><table><tr><th>front</th>'
           + ("<th>scene group</th>" if len(report.groups) > 1 else "")
           + "<th>technique</th><th>varied scene values</th><th>reference</th><th>runs</th>"
           f"<th>on the front, fastest first (ms, {e(metric)})</th></tr>"]
    for f in fronts:
        on = ", ".join(f'<a href="#{r.row}">{e(r.uid)}</a> ({e(fmt_num(r.time()))}, '
                       f"{e(fmt_num(metric_value(r, metric)))})" for r in f.on_front) or "–"
        out.append(f"<tr><td>{e(f.label)}</td>"
                   + (f"<td>{f.group + 1}</td>" if len(report.groups) > 1 else "")
                   + f"<td>{e(f.technique)}</td><td>{e(f.describe() or '(none varied)')}</td>"
                   f"<td>{e(f.reference or '–')}</td><td>{len(f.runs)}</td><td>{on}</td></tr>")
    out.append("</table></div>")
    return "\n".join(out)


def params_section(report, param_plots):
    if not param_plots:
        return ""
    out = ["<h2>Metrics against parameters</h2>"]
    for key in report.keys:
        out.append(f'<h3>{e(key)}</h3><div class="plots small">')
        for k, mlabel, name in param_plots:
            if k == key:
                png = f"plots/{href(name)}.png"
                out.append(f'<figure><a href="{png}"><img src="{png}" '
                           f'alt="{e(mlabel)} against {e(key)}"></a>'
                           f"<figcaption>{e(mlabel)} against {e(key)} · {plot_links(name)}"
                           "</figcaption></figure>")
        out.append("</div>")
    return "\n".join(out)


def title(report):
    if len(report.sweeps) == 1:
        doc = report.sweeps[0].doc
        return (f"Penumbra sweep: {doc.get('scene', '?')} · {', '.join(report.techniques())} · "
                f"{size_text(doc.get('size'))}")
    scenes = sorted({str(s.doc.get("scene", "?")) for s in report.sweeps})
    return f"Penumbra sweeps: {len(report.sweeps)} folders · {', '.join(scenes)}"


def heatmap_section(heatmap):
    if not heatmap:
        return ""
    name, keys = heatmap
    return (f'<h2>Heatmap</h2><div class="plots"><figure><a href="plots/{href(name)}.png">'
            f'<img src="plots/{href(name)}.png" alt="heatmap over {e(keys[0])} and {e(keys[1])}">'
            f"</a><figcaption>The Pareto metric over {e(keys[0])} and {e(keys[1])}, one panel per "
            f"technique and remaining values · {plot_links(name)}</figcaption></figure></div>")


def write(report, fronts, metric, error_plots, heatmap, param_plots):
    t = title(report)
    sub = [f"{len(report.runs)} runs", f"Pareto metric: {e(metric)}",
           '<a href="report.json">report.json</a>']
    parts = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
             f"<title>{e(t)}</title>", f"<style>{CSS}</style></head><body>", f"<h1>{e(t)}</h1>",
             f'<p class="sub">{" · ".join(sub)}</p>', settings(report),
             error_section(report, error_plots, metric), fronts_table(report, fronts, metric),
             heatmap_section(heatmap), params_section(report, param_plots),
             page_runs.runs_table(report),
             f"<script>{JS}</script>", "</body></html>"]
    path = os.path.join(report.out, "index.html")
    with open(path + ".tmp", "w", encoding="utf-8") as f:
        f.write("\n".join(parts) + "\n")
    os.replace(path + ".tmp", path)
    return path
