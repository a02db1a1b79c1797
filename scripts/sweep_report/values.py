"""How sweep values and numbers are written in the report, and the small checks on them that
every part shares (numbers, file-safe slugs, relative links)."""
import html
import math
import os
import re
import urllib.parse

MISSING = "-"  # a varied key that a run's sweep did not vary (reports over several folders)


def fmt_value(v):
    """A parameter value as people write it: arrays as "[0.5, 0.5]", booleans as true/false."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if v is None:
        return "null"
    if isinstance(v, float):
        if v.is_integer() and abs(v) < 1e15:
            return str(v)  # keep "1.0" distinct from an integer 1 only where it is written so
        return f"{v:.6g}"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(fmt_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k}: {fmt_value(x)}" for k, x in v.items()) + "}"
    return str(v)


def fmt_num(v, digits=4):
    if v is None:
        return "–"
    if isinstance(v, bool):
        return fmt_value(v)
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v) or math.isinf(v):
            return str(v)
        return f"{v:.{digits}g}"
    return str(v)


def is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def num_or_none(v):
    return float(v) if is_number(v) else None


def slug(s):
    return re.sub(r"[^A-Za-z0-9]+", "_", s).strip("_") or "param"


def href(path):
    """A relative link (a path with / separators), safe in an attribute."""
    return html.escape(urllib.parse.quote(path.replace(os.sep, "/")), quote=True)


def e(s):
    return html.escape(str(s), quote=True)
