"""Plot of the FEM convergence CSV (tests/freecad/test_fem_convergence.py writes it to
$BISECTMESH_ARTIFACTS/fem_convergence.csv): the error of CalculiX's largest displacement against
the node count, log-log, BisectMesh and Gmsh, one panel per example.

    /usr/bin/python3 tests/bench/plot_fem_convergence.py build/test-artifacts/fem_convergence.csv out.png

(the system interpreter: it has matplotlib.) The test itself runs with the suite, or alone:
    ctest --test-dir build -R freecad.test_fem_convergence
"""
import csv
import sys

from plot_common import finish, plt

STYLE = {"bisectmesh": ("o-", "BisectMesh"), "gmsh": ("s--", "Gmsh (FreeCAD's mesher)")}


def main(src, dst):
    rows = list(csv.DictReader(open(src)))
    examples = sorted({r["example"] for r in rows})
    fig, axes = plt.subplots(1, len(examples), figsize=(6 * len(examples), 4.5), squeeze=False)
    for ax, name in zip(axes[0], examples):
        for mesher, (style, label) in STYLE.items():
            runs = sorted((int(r["nodes"]), 100 * float(r["error"])) for r in rows
                          if r["example"] == name and r["mesher"] == mesher)
            if runs:
                # an error of exactly 0 has no place on a log scale: drawn at 1e-4 %
                ax.loglog([n for n, _ in runs], [max(e, 1e-4) for _, e in runs], style, label=label)
        ref = [r for r in rows if r["example"] == name and r["mesher"] == "reference"]
        title = name
        if ref:
            title += "\n(reference: Gmsh, %s tetra10, %s nodes)" % (ref[0]["tetrahedra"], ref[0]["nodes"])
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("nodes")
        ax.set_ylabel("error of the largest displacement (%)")
    finish(fig, axes[0], dst)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
