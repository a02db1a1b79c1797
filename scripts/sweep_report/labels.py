"""Point labels that never overlap: a greedy placement. Labels are tried in priority order at a
few offsets around their point; a label is kept at the first offset where its box stays inside
the axes and clear of every marker and every label already placed, and left out otherwise (the
page's tooltips and the runs table still name that point)."""

# (dx, dy) in points from the point, with the text's alignment there: corners first, then sides,
# then the same farther out.
_NEAR = [(4, 4, "left", "bottom"), (4, -4, "left", "top"), (-4, 4, "right", "bottom"),
         (-4, -4, "right", "top"), (6, 0, "left", "center"), (-6, 0, "right", "center"),
         (0, 6, "center", "bottom"), (0, -6, "center", "top")]
CANDIDATES = _NEAR + [(dx * 3, dy * 3, ha, va) for dx, dy, ha, va in _NEAR]


def _overlaps(a, b, pad=1.0):
    return a[0] < b[2] + pad and b[0] < a[2] + pad and a[1] < b[3] + pad and b[1] < a[3] + pad


def _box(text, renderer):
    b = text.get_window_extent(renderer)
    return (b.x0, b.y0, b.x1, b.y1)


def place(fig, ax, items, marker_px, lines=(), fontsize=7):
    """items: [(x, y, text, colour, run uid)] in priority order; lines: [(x0, y0, x1, y1)] in
    data coordinates, horizontal or vertical (error bars, front steps), that labels keep off.
    The layout must be final (drawn and frozen). Returns ([(uid, text, box)], [uid left out]);
    boxes in display pixels."""
    renderer = fig.canvas.get_renderer()
    a = ax.get_window_extent(renderer)
    inside = (a.x0, a.y0, a.x1, a.y1)
    r = marker_px / 2
    markers = []
    for x, y, *_ in items:
        px, py = ax.transData.transform((x, y))
        markers.append((px - r, py - r, px + r, py + r))
    for x0, y0, x1, y1 in lines:
        (ax0, ay0), (ax1, ay1) = ax.transData.transform([(x0, y0), (x1, y1)])
        markers.append((min(ax0, ax1) - 2, min(ay0, ay1) - 2, max(ax0, ax1) + 2, max(ay0, ay1) + 2))
    placed, left_out = [], []
    for x, y, label, colour, uid in items:
        ann = ax.annotate(label, (x, y), xytext=(0, 0), textcoords="offset points",
                          fontsize=fontsize, color=colour, annotation_clip=False)
        for dx, dy, ha, va in CANDIDATES:
            ann.xyann = (dx, dy)
            ann.set_ha(ha)
            ann.set_va(va)
            box = _box(ann, renderer)
            if (box[0] >= inside[0] and box[1] >= inside[1] and box[2] <= inside[2]
                    and box[3] <= inside[3]
                    and not any(_overlaps(box, m, 0.0) for m in markers)
                    and not any(_overlaps(box, p[2]) for p in placed)):
                placed.append((uid, label, box))
                break
        else:
            ann.remove()
            left_out.append(uid)
    return placed, left_out
