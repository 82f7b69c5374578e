"""Shared figure style and output for slamkit's evaluation plots (matplotlib, Agg)."""
import os

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {
    "font.size": 10,
    "axes.titlesize": 11,
    "axes.labelsize": 10,
    "legend.fontsize": 8.5,
    "xtick.labelsize": 9,
    "ytick.labelsize": 9,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "savefig.dpi": 200,
    "svg.fonttype": "none",  # keep text as text in SVG
}


def save(fig, out_dir, name, pdf):
    """Writes NAME.png and NAME.svg (and NAME.pdf) into out_dir; returns the PNG path."""
    os.makedirs(out_dir, exist_ok=True)
    formats = ["png", "svg"] + (["pdf"] if pdf else [])
    for ext in formats:
        fig.savefig(os.path.join(out_dir, "%s.%s" % (name, ext)), bbox_inches="tight")
    plt.close(fig)
    return os.path.join(out_dir, name + ".png")
