"""Reading sweep folders (DIR/sweep.json, schema "penumbra-sweep" version 1) and merging one or
more of them into one report: runs with unique ids, the union of the varied keys, and scene
groups (same scene, size, frame and reference), since errors are only comparable within one."""
import json
import os

from .values import MISSING, fmt_value, num_or_none

SCHEMA = "penumbra-sweep"
SCHEMA_VERSION = 1


class ReportError(Exception):
    """Bad input: the message names the file or argument; the script exits 2."""


def load_doc(folder):
    path = os.path.join(folder, "sweep.json")
    try:
        with open(path, encoding="utf-8") as f:
            doc = json.load(f)
    except FileNotFoundError:
        raise ReportError(f"{path}: no such file (is {folder} a sweep folder?)")
    except (OSError, UnicodeDecodeError) as err:
        raise ReportError(f"{path}: cannot read: {getattr(err, 'strerror', None) or err}")
    except json.JSONDecodeError as err:
        raise ReportError(f"{path}: not valid JSON: {err}")
    if not isinstance(doc, dict) or doc.get("schema") != SCHEMA:
        raise ReportError(f"{path}: not a {SCHEMA} file")
    if doc.get("schema_version") != SCHEMA_VERSION:
        raise ReportError(f"{path}: schema_version {doc.get('schema_version')!r} unsupported "
                          f"(this script reads version {SCHEMA_VERSION})")
    if not isinstance(doc.get("runs"), list):
        raise ReportError(f"{path}: no runs list")
    if not isinstance(doc.setdefault("varied", []), list) or not all(
            isinstance(v, dict) and isinstance(v.get("key"), str) for v in doc["varied"]):
        raise ReportError(f"{path}: varied is not a list of {{key, values}} objects")
    for i, run in enumerate(doc["runs"]):
        if not isinstance(run, dict):
            raise ReportError(f"{path}: runs[{i}] is not an object")
        run.setdefault("id", f"run-{i + 1:04d}")
        run.setdefault("technique", doc.get("technique", "?"))
        for key in ("values", "metrics", "time_ms", "stats"):
            if not isinstance(run.get(key), dict):
                run[key] = {}
    return doc


class Sweep:
    """One folder: its document, a short label, and its scene group (index into Report.groups)."""

    def __init__(self, folder, doc, label):
        self.folder, self.doc, self.label = folder, doc, label
        self.keys = [v["key"] for v in doc["varied"]]
        self.group = None

    def group_key(self):
        ref = self.doc.get("reference") or {}
        return (str(self.doc.get("scene", "?")), fmt_value(self.doc.get("size")),
                fmt_value(self.doc.get("frame", 0)), str(ref.get("technique", "?")),
                json.dumps(ref.get("overrides") or {}, sort_keys=True))


class Run:
    """One run: its record in sweep.json, its sweep, an id unique in the report, and its value
    for every varied key of the report (MISSING where its sweep did not vary the key)."""

    def __init__(self, sweep, rec, uid, keys):
        self.sweep, self.rec, self.uid = sweep, rec, uid
        self.technique = str(rec.get("technique"))
        vals = rec["values"]
        self.values = {k: vals[k] if k in vals else MISSING for k in keys}
        self.front = None  # the Front this run belongs to (set by fronts.assign)
        self.row = None  # the id of its row on the page

    def value_text(self, key):
        v = self.values.get(key, MISSING)
        return MISSING if v is MISSING else fmt_value(v)

    def time(self):
        return num_or_none(self.rec["time_ms"].get("total"))

    def time_range(self):
        """(min, max) of the timed renders where the record has both, else None."""
        tm = self.rec["time_ms"]
        lo, hi, t = num_or_none(tm.get("total_min")), num_or_none(tm.get("total_max")), self.time()
        if lo is None or hi is None or t is None or not lo <= t <= hi:
            return None
        return lo, hi

    def path(self, key):
        """The run's file KEY (preview, heatmap, exr, reference) as a path, or None."""
        rel = self.rec.get(key)
        return os.path.join(self.sweep.folder, rel) if isinstance(rel, str) and rel else None


class Report:
    """The merged sweeps, written to folder OUT."""

    def __init__(self, sweeps, out):
        self.sweeps, self.out = sweeps, out
        self.keys = []
        for s in sweeps:
            self.keys += [k for k in s.keys if k not in self.keys]
        self.groups = []  # [(group key, [sweeps])]
        for s in sweeps:
            key = s.group_key()
            for i, (k, members) in enumerate(self.groups):
                if k == key:
                    s.group = i
                    members.append(s)
                    break
            else:
                s.group = len(self.groups)
                self.groups.append((key, [s]))
        many = len(sweeps) > 1
        self.runs = [Run(s, rec, f"{s.label}/{rec['id']}" if many else str(rec["id"]), self.keys)
                     for s in sweeps for rec in s.doc["runs"]]
        for i, run in enumerate(self.runs):
            run.row = f"r{i + 1}"

    def link(self, path):
        """PATH (a file of some sweep folder, or of OUT) relative to OUT, for the page."""
        return os.path.relpath(path, self.out)

    def techniques(self):
        return sorted({r.technique for r in self.runs})


def labels_for(folders):
    """Short, unique labels: the folder's name, with " (2)" etc. where two share one."""
    labels, seen = [], {}
    for f in folders:
        name = os.path.basename(os.path.normpath(os.path.abspath(f))) or "sweep"
        seen[name] = seen.get(name, 0) + 1
        labels.append(name if seen[name] == 1 else f"{name} ({seen[name]})")
    return labels


def read_report(folders, out):
    docs = [load_doc(f) for f in folders]
    return Report([Sweep(f, d, lab) for f, d, lab in zip(folders, docs, labels_for(folders))], out)
