"""Plot of bench_decomposition's CSV: time against faces, log-log, with the fitted exponents."""
import csv
import sys

from plot_common import finish, fit, plt


def main(src, dst):
    rows = list(csv.DictReader(open(src)))
    fig, ax = plt.subplots(figsize=(7, 5))
    for family, marker in (("sphere", "o"), ("double_sphere_hole", "s")):
        sel = [r for r in rows if r["family"] == family]
        faces = [int(r["faces"]) for r in sel]
        for key, style in (("one_bisection_s", "-"), ("decomposition_s", "--")):
            t = [float(r[key]) for r in sel]
            label = "%s, %s (slope %.2f)" % (family, key.replace("_s", "").replace("_", " "), fit(faces, t))
            ax.loglog(faces, t, style, marker=marker, label=label)
    ax.set_xlabel("faces")
    ax.set_ylabel("seconds")
    ax.set_title("BisectMesh convex decomposition (thesis 6.10 families)")
    finish(fig, [ax], dst, legend_size=8)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
