"""Shared figure style and output for slamkit's evaluation plots.

Figures are made with matplotlib's Figure class and written by its Agg (PNG), SVG and PDF
backends directly: pyplot, its backend selection and its figure manager are never imported,
since they cost start-up time and nothing here is shown on screen."""
import os

import matplotlib
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

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
    "svg.hashsalt": "slamkit",  # the same SVG element ids at every run
}
matplotlib.rcParams.update(STYLE)
# The same input gives the same files: no creation date in SVG or PDF.
NO_DATE = {"png": None, "svg": {"Date": None}, "pdf": {"CreationDate": None}}


class InputMismatch(Exception):
    """Inputs that cannot be drawn in one figure; plot.py prints the message as one line."""


def new_figure(figsize, rows=1, sharex=False):
    """A figure and its axes (one, or a column of `rows`)."""
    fig = Figure(figsize=figsize)
    return fig, fig.subplots(rows, 1, sharex=sharex)


def save(fig, out_dir, name, request):
    """Writes NAME.EXT into out_dir for each of request's "formats" (png, svg, pdf; default png
    and svg), the PNG at request's "dpi" (default the style's).

    Each file is cropped to the figure's content with a small pad, as bbox_inches="tight" does;
    the bounding box is computed once for all formats: savefig's bbox_inches="tight" lays the
    figure out again for each file, a third of the drawing time."""
    os.makedirs(out_dir, exist_ok=True)
    renderer = FigureCanvasAgg(fig).get_renderer()
    bbox = fig.get_tightbbox(renderer).padded(matplotlib.rcParams["savefig.pad_inches"])
    for ext in request.get("formats", ["png", "svg"]):
        path = os.path.join(out_dir, "%s.%s" % (name, ext))
        # Only the PNG is drawn in pixels; SVG and PDF keep the style's dpi for the few raster
        # parts (a colour bar), so a PNG for a slide does not change them.
        dpi = request.get("dpi") if ext == "png" else None
        try:
            fig.savefig(path, bbox_inches=bbox, metadata=NO_DATE[ext], dpi=dpi)
        except OSError as error:  # a full disk fails in a writer that does not name the file
            raise OSError(error.errno, "cannot write %s: %s" % (path, error.strerror)) from None
