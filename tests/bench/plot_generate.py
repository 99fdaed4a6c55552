"""Plot of bench_generate's scaling CSV: seconds against tetrahedra, log-log, with the fitted exponent."""
import csv
import sys

from plot_common import finish, fit, plt


def main(src, dst):
    rows = list(csv.DictReader(open(src)))
    tets = [int(r["tets"]) for r in rows]
    fig, ax = plt.subplots(figsize=(7, 5))
    for key, style in (("total_s", "o-"), ("gen_tets_s", "s--"), ("gen_nodes_s", "^:")):
        t = [float(r[key]) for r in rows]
        ax.loglog(tets, t, style, label="%s (slope %.2f)" % (key[:-2].replace("_", " "), fit(tets, t)))
    ax.set_xlabel("tetrahedra")
    ax.set_ylabel("seconds")
    ax.set_title("BisectMesh on %s" % rows[0]["model"])
    finish(fig, [ax], dst)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
