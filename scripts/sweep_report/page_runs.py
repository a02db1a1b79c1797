"""The page's runs table: one row per run with its sweep, technique, varied values ("-" where
its sweep did not vary a key), front, thumbnails, times and metrics; rows sort on a click."""
import os
import sys

from .values import e, fmt_num, fmt_value, href, is_number

TABLE_METRICS = ["mae", "rmse", "max", "p99", "shadow_mae", "shadow_pixels", "fail_fraction"]


def sort_attr(v):
    return "" if v is None else f' data-sort="{e(repr(float(v)) if is_number(v) else v)}"'


def num_td(v):
    """An opening <td>, right-aligned and sortable by value where v is a number."""
    return f'<td class="num"{sort_attr(v)}>' if is_number(v) else "<td>"


def img_cell(report, path, alt):
    if not path:
        return '<td><span class="missing">none</span></td>'
    rel = report.link(path)
    if not os.path.isfile(path):
        print(f"sweep-report: warning: {path} is missing", file=sys.stderr)
        return f'<td><span class="missing">missing: {e(rel)}</span></td>'
    return (f'<td><a href="{href(rel)}"><img class="thumb" src="{href(rel)}" alt="{e(alt)}" '
            f'title="{e(rel)}"></a></td>')


def file_link(report, path, text):
    if not path:
        return "–"
    cls = "" if os.path.isfile(path) else ' class="missing"'
    return f'<a{cls} href="{href(report.link(path))}">{e(text)}</a>'


def columns(report):
    passes, stats = [], []
    for r in report.runs:
        passes += [p for p in (r.rec["time_ms"].get("passes") or {}) if p not in passes]
        stats += [s for s in r.rec["stats"] if s not in stats]
    return passes, stats


def header(report, passes, stats):
    many = len(report.sweeps) > 1
    cells = ["run"] + (["sweep"] if many else []) + ["technique"] + report.keys
    cells += ["front", "preview", "error heatmap", "EXR", "total ms", "min–max ms"]
    cells += TABLE_METRICS + [f"{p} ms" for p in passes] + stats
    return "<thead><tr>" + "".join(f"<th>{e(c)}</th>" for c in cells) + "</tr></thead>"


def row(report, run, passes, stats):
    on = run.front is not None and run in run.front.on_front
    cls = ' class="pareto"' if on else ""
    cells = [f'<tr id="{run.row}"{cls}><td>{e(run.uid)}</td>']
    if len(report.sweeps) > 1:
        cells.append(f"<td>{e(run.sweep.label)}</td>")
    cells.append(f"<td>{e(run.technique)}</td>")
    for k in report.keys:
        v = run.values[k]
        cells.append(num_td(v) + f"{e(run.value_text(k))}</td>")
    front = run.front.label + (" ★" if on else "") if run.front else "–"
    cells.append(f'<td data-sort="{e(front)}">{e(front)}</td>')
    cells.append(img_cell(report, run.path("preview"), f"{run.uid} preview"))
    cells.append(img_cell(report, run.path("heatmap"), f"{run.uid} error heatmap"))
    cells.append(f"<td>{file_link(report, run.path('exr'), 'EXR')}</td>")
    tm = run.rec["time_ms"]
    t, rng = tm.get("total"), run.time_range()
    cells.append(f'<td class="num"{sort_attr(t)}>{e(fmt_num(t))}</td>')
    cells.append(f'<td class="num">{e(fmt_num(rng[0]) + "–" + fmt_num(rng[1]))}</td>'
                 if rng else "<td>–</td>")
    for m in TABLE_METRICS:
        v = run.rec["metrics"].get(m)
        cells.append(f'<td class="num"{sort_attr(v)}>{e(fmt_num(v))}</td>')
    for p in passes:
        v = (tm.get("passes") or {}).get(p)
        cells.append(f'<td class="num"{sort_attr(v)}>{e(fmt_num(v))}</td>')
    for s in stats:
        v = run.rec["stats"].get(s)
        text = fmt_num(v) if is_number(v) else fmt_value(v) if v is not None else "–"
        cells.append(num_td(v) + f"{e(text)}</td>")
    return "".join(cells) + "</tr>"


def runs_table(report):
    passes, stats = columns(report)
    out = ['<h2>Runs</h2><p class="sub">Click a header to sort. Bold ids (★ in the front column) '
           "are on their front's Pareto front.</p>",
           '<div class="scroll"><table class="runs">', header(report, passes, stats), "<tbody>"]
    out += [row(report, r, passes, stats) for r in report.runs]
    out.append("</tbody></table></div>")
    return "\n".join(out)
