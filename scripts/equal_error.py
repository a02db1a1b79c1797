"""The equal-error ratio of `scripts/bench pareto`: a run's time over the time `reference` needs
to reach the run's error, read off reference's sweep over N (its samples per light axis) with
the time interpolated between the two N that bracket the error. Pure arithmetic, no rendering,
so that tests/unit/scripts/equal_error_test.py can check it."""
import math


def reference_front(points):
    """points: (n, error, ms) of reference runs. The ones no cheaper run beats in error, by time:
    ms rising, error strictly falling (a larger N whose jittered error came out no lower than a
    cheaper N's is never the cheapest reference of at most some error). Runs without an error or
    a time are left out."""
    usable = [p for p in points if p[1] is not None and p[2] is not None]
    front, best = [], math.inf
    for n, err, ms in sorted(usable, key=lambda p: (p[2], p[1])):
        if err < best:
            front.append((n, err, ms))
            best = err
    return front


def bracket(front, error):
    """(i0, i1, f, kind): the indices in FRONT of the two points around ERROR and its share f
    between them (the error's, linear), as reference_time() reads them: kind 'cheapest' (i0 =
    i1 = 0, f = 0), 'interpolated' or 'beyond' (i0 = i1 = the last, f = 0)."""
    if not front:
        raise ValueError("no reference run with an error and a time")
    if error >= front[0][1]:
        return 0, 0, 0.0, "cheapest"
    for i in range(len(front) - 1):
        e0, e1 = front[i][1], front[i + 1][1]
        if error >= e1:
            return i, i + 1, (e0 - error) / (e0 - e1), "interpolated"
    last = len(front) - 1
    return last, last, 0.0, "beyond"


def reference_time(front, error):
    """(ms, n, kind): the time reference needs for a shadow MAE of at most ERROR.

    kind 'cheapest': ERROR is at least the cheapest reference's error, which is then the answer.
    kind 'interpolated': between front points (n0, e0, t0) and (n1, e1, t1) with
    e0 > ERROR >= e1, time and N are linear in the error: t0 + (e0 - ERROR) / (e0 - e1) (t1 - t0).
    kind 'beyond': ERROR is below every reference's error; the answer is the lowest-error
    reference's time, which is less than reference would need."""
    i0, i1, f, kind = bracket(front, error)
    (n0, _, t0), (n1, _, t1) = front[i0], front[i1]
    return t0 + f * (t1 - t0), n0 + f * (n1 - n0), kind


def equal_error_ratio(ms, error, front):
    """(ratio, n, kind): MS over reference_time(front, ERROR). With kind 'beyond' the ratio is an
    upper bound (reference would need more time than its largest N took)."""
    t, n, kind = reference_time(front, error)
    return ms / t, n, kind


def fmt_ratio(ratio, kind):
    """'0.42', or '<0.42' for an upper bound (kind 'beyond')."""
    return ("<" if kind == "beyond" else "") + f"{ratio:.2f}"
