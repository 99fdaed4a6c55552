"""What the benchmark plots share: a headless matplotlib, the least-squares slope in log-log, and
the finish of a figure (grids, legends, the file)."""
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402,F401  (re-exported for the plot scripts)


def fit(xs, ys):
    """The exponent b of y = a x^b fitted by least squares on the logarithms."""
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    n = len(lx)
    mx, my = sum(lx) / n, sum(ly) / n
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)


def finish(fig, axes, dst, legend_size=None):
    """Log grids and legends (font size legend_size, or matplotlib's) on every axes, then the
    figure written to dst (PNG, 100 dpi)."""
    for ax in axes:
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=legend_size)
    fig.tight_layout()
    fig.savefig(dst, dpi=100)
