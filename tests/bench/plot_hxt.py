"""Plot of bench_generate's table beside Gmsh HXT (generate_hxt.csv): for each model and count,
the whole process's seconds (ours on two threads and on one, HXT on two) and the peak memory,
with our time over HXT's written above each group."""
import csv
import sys

from plot_common import plt


def label(row):
    r = int(row["r"])
    return "%s\n%s" % (row["model"], "10^%d" % (len(str(r)) - 1) if str(r).strip("0") == "1" else "{:,}".format(r))


def main(src, dst):
    rows = [r for r in csv.DictReader(open(src)) if r["hxt_s"] not in ("", "0")]
    if not rows:
        sys.exit("no row with an HXT time in " + src)
    xs = list(range(len(rows)))
    fig, (time_ax, mem_ax) = plt.subplots(1, 2, figsize=(12, 5))
    width = 0.27
    series = (("s_2threads", "BisectMesh, 2 threads", -width, "C0"), ("s_1thread", "BisectMesh, 1 thread", 0.0, "C1"),
              ("hxt_s", "Gmsh HXT, 2 threads", width, "C2"))
    for key, name, shift, colour in series:
        time_ax.bar([x + shift for x in xs], [float(r[key]) for r in rows], width, label=name, color=colour)
    for x, r in zip(xs, rows):
        top = max(float(r["s_2threads"]), float(r["s_1thread"]), float(r["hxt_s"]))
        time_ax.annotate("%.2fx" % float(r["ratio"]), (x, top), textcoords="offset points", xytext=(0, 3), ha="center", fontsize=8)
    time_ax.set_yscale("log")
    time_ax.set_ylabel("seconds, whole process (log)")
    time_ax.set_title("Time end to end (label: ours on 2 threads / HXT)")
    for key, name, shift, colour in (("peak_mb", "BisectMesh", -width / 2, "C0"), ("hxt_peak_mb", "Gmsh HXT", width / 2, "C2")):
        mem_ax.bar([x + shift for x in xs], [float(r[key]) for r in rows], width, label=name, color=colour)
    mem_ax.set_ylabel("peak resident memory, MB")
    mem_ax.set_title("Peak memory")
    for ax in (time_ax, mem_ax):
        ax.set_xticks(xs)
        ax.set_xticklabels([label(r) for r in rows], fontsize=8)
        ax.grid(True, axis="y", which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(dst, dpi=100)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
