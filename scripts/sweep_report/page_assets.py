"""The page's style sheet and script: sortable runs table, and a check the test reads (every
image complete and non-empty, written to body data-images-ok)."""

CSS = """
body { font: 14px/1.4 system-ui, sans-serif; margin: 1.5em; color: #222; background: #fff; }
h1 { font-size: 1.5em; margin-bottom: 0.2em; } h2 { margin-top: 1.6em; border-bottom: 1px solid #ddd; }
.sub { color: #666; margin-top: 0; }
table { border-collapse: collapse; font-size: 12px; }
th, td { border: 1px solid #ddd; padding: 3px 6px; text-align: left; vertical-align: middle; }
th { background: #f3f3f3; position: sticky; top: 0; }
table.runs th { cursor: pointer; user-select: none; }
table.runs th.asc::after { content: " \\25B2"; } table.runs th.desc::after { content: " \\25BC"; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
tr.pareto td:first-child { font-weight: bold; }
.scroll { overflow-x: auto; }
table.runs td:first-child { white-space: nowrap; }
img.thumb { width: 96px; height: auto; display: block; background: #eee; }
.plots { display: flex; flex-wrap: wrap; gap: 12px; }
.plots figure { margin: 0; } .plots img { max-width: 100%; border: 1px solid #ddd; }
.plots.small img { width: 600px; }
.plots img.map { max-width: none; }
.note { color: #555; max-width: 60em; }
table.runs tr:target td { background: #fff6cc; }
figcaption { font-size: 12px; color: #555; }
.missing { color: #a00; font-size: 11px; }
code { background: #f5f5f5; padding: 0 3px; }
"""

# Sorting by clicking a header, and a check the test reads: every image complete and non-empty.
JS = """
(function () {
  function key(td) { var v = td.getAttribute('data-sort'); return v === null ? td.textContent : v; }
  document.querySelectorAll('table.runs th').forEach(function (th, col) {
    th.addEventListener('click', function () {
      var table = th.closest('table'), body = table.tBodies[0];
      var asc = !th.classList.contains('asc');
      table.querySelectorAll('th').forEach(function (h) { h.classList.remove('asc', 'desc'); });
      th.classList.add(asc ? 'asc' : 'desc');
      var rows = Array.prototype.slice.call(body.rows);
      rows.sort(function (a, b) {
        var x = key(a.cells[col]), y = key(b.cells[col]);
        var nx = x.trim() === '' ? NaN : Number(x), ny = y.trim() === '' ? NaN : Number(y), r;
        if (!isNaN(nx) && !isNaN(ny)) r = nx - ny;
        else if (!isNaN(nx) && isNaN(ny)) r = -1;
        else if (isNaN(nx) && !isNaN(ny)) r = 1;
        else r = x.localeCompare(y, undefined, {numeric: true});
        return asc ? r : -r;
      });
      rows.forEach(function (r) { body.appendChild(r); });
    });
  });
  window.addEventListener('load', function () {
    var imgs = document.images, ok = 0;
    for (var i = 0; i < imgs.length; i++) {
      if (imgs[i].complete && imgs[i].naturalWidth > 0) ok++;
      else console.error('image did not load: ' + imgs[i].getAttribute('src'));
    }
    document.body.dataset.imagesOk = ok + '/' + imgs.length;
  });
})();
"""
