"""Histogram pictures of a quality report, drawn with matplotlib (which ships with FreeCAD).

Drawn off-screen by the Agg canvas into PNG bytes, which the panel shows in a QLabel: no pyplot,
so FreeCAD's own matplotlib backend and any open plot windows are left alone, and it runs
headless.
"""

import io

import numpy as np

from .colouring import normalized, ramp

# (measure, title, x label) of the panels drawn by default
DEFAULT_PANELS = (
    ("dihedral_min", "Minimum dihedral angle", "degrees"),
    ("gamma", "Goodness \u03b3 = 374.123 V\u00b2/S\u00b3", "\u03b3 (1 = regular)"),
)


def histogram_png(report, panels=DEFAULT_PANELS, width_px=380, height_px=170, dpi=100):
    """PNG bytes with one bar chart per entry of ``panels``, stacked vertically, from
    ``report["measures"]`` (bisectmesh.quality's dict). Bars are coloured like the 3D view."""
    from matplotlib.figure import Figure
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fig = Figure(figsize=(width_px / dpi, height_px * len(panels) / dpi), dpi=dpi)
    FigureCanvasAgg(fig)
    for k, (measure, title, xlabel) in enumerate(panels):
        ax = fig.add_subplot(len(panels), 1, k + 1)
        stats = report["measures"][measure]
        counts = np.asarray(stats["histogram"], dtype=float)
        edges = np.linspace(stats["lo"], stats["hi"], len(counts) + 1)
        centres = 0.5 * (edges[:-1] + edges[1:])
        ax.bar(edges[:-1], counts, width=np.diff(edges), align="edge",
               color=ramp(normalized(measure, centres)), edgecolor="#404040", linewidth=0.5)
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("%s    (min %.3g, mean %.3g)" % (xlabel, stats["min"], stats["mean"]), fontsize=8)
        ax.set_ylabel("elements", fontsize=8)
        ax.set_xlim(stats["lo"], stats["hi"])
        ax.tick_params(labelsize=7)
        ax.axvline(stats["mean"], color="#303080", linewidth=1.0, linestyle="--")
    fig.tight_layout(pad=0.4, h_pad=0.8)
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=dpi)
    return buffer.getvalue()
