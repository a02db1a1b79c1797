"""What every plot shares: matplotlib set up headless (Agg), saving one figure as PNG, SVG and
PDF with no timestamps (so a rerun writes the same files), and colour and marker choices."""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

DPI = 110
FORMATS = ("png", "svg", "pdf")
MARKERS = "osD^v<>PX*"
LINESTYLES = ("-", "--", ":", "-.")


def setup():
    plt.rcParams["svg.hashsalt"] = "penumbra-sweep"


def figure(width, height, nrows=1, ncols=1):
    return plt.subplots(nrows, ncols, figsize=(width, height), dpi=DPI, layout="constrained")


def save(fig, plots_dir, name):
    """Writes NAME.png, .svg and .pdf; returns NAME."""
    fig.savefig(os.path.join(plots_dir, name + ".png"), dpi=DPI)
    fig.set_layout_engine("none")  # laid out by the PNG's draw: the same layout, done once
    fig.savefig(os.path.join(plots_dir, name + ".svg"), metadata={"Date": None})
    fig.savefig(os.path.join(plots_dir, name + ".pdf"),
                metadata={"CreationDate": None, "ModDate": None})
    plt.close(fig)
    return name


def categorical_colours(n):
    cmap = plt.get_cmap("tab10" if n <= 10 else "tab20")
    return [cmap(i % cmap.N) for i in range(n)]


def freeze_layout(fig):
    """Draws once so the constrained layout settles, then keeps it: positions measured after
    this (labels, the page's image map) stay true in the saved files."""
    fig.canvas.draw()
    fig.set_layout_engine("none")
