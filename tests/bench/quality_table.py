"""Issue 17's quality table on demand, beside Gmsh: the models FEM users mesh coarse at R in
{50, 100, 300, 1000, 3000}, meshed by the CLI (STL through the polyhedral route, B-rep through the
true-surface one) and, for the B-reps, by Gmsh at the count nearest R it reaches (its
characteristic length searched, as FreeCAD's mesher would be set). Writes quality_table.csv and
quality_table.png (smallest dihedral and mean alpha against R) into OUT_DIR.

    /usr/bin/python3 tests/bench/quality_table.py [CLI [SHARED_DIR [OUT_DIR]]]

defaults: build/bin/bisect-mesh, ../shared, build/bench. Both meshes are judged by the same
`bisect-mesh quality --json`. The pass/fail form of the table is tests/cpp/occ/test_quality_table.cpp.
"""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import time

from plot_common import finish, plt

MODELS = ("stl/cantilever.stl", "stl/slender-appendage.stl", "stl/lug.stl", "stl/plate-hole.stl", "cantilever.brep",
          "slender-appendage.brep", "lug.brep", "plate-hole.brep", "two-boxes-cavity.brep")
COUNTS = (50, 100, 300, 1000, 3000)
GMSH_TRIES = 5


def quality(cli, mesh):
    out = subprocess.run([cli, "quality", mesh, "--json"], capture_output=True, text=True, check=True).stdout
    return json.loads(out)


def bisect_run(cli, model, count, work):
    out = os.path.join(work, "b.vtu")
    start = time.perf_counter()
    subprocess.run([cli, model, "-n", str(count), "-o", out], capture_output=True, check=True)
    return quality(cli, out), time.perf_counter() - start


def gmsh_once(model, length, work):
    out = os.path.join(work, "g.msh")
    start = time.perf_counter()
    run = subprocess.run(["gmsh", model, "-3", "-clmax", "%.9g" % length, "-format", "msh2", "-o", out],
                         capture_output=True, text=True, timeout=600)
    seconds = time.perf_counter() - start
    if run.returncode != 0 or not os.path.exists(out):
        return None, seconds
    return out, seconds


def gmsh_run(cli, model, count, volume, work):
    """Gmsh at the count nearest `count` in a few lengths (cube-root steps; stops at its floor)."""
    length = (6.0 * math.sqrt(2.0) * volume / count) ** (1.0 / 3.0)
    best = None
    last = None
    for _ in range(GMSH_TRIES):
        out, seconds = gmsh_once(model, length, work)
        if out is None:
            length *= 0.9
            continue
        q = quality(cli, out)
        tets = q["tets"]
        if best is None or abs(math.log(tets / count)) < abs(math.log(best[0]["tets"] / count)):
            best = (q, seconds)
        if abs(tets - count) <= 0.2 * count or (last is not None and length > last[0] and tets >= last[1]):
            break  # near enough, or Gmsh's floor: a longer length gives no fewer
        last = (length, tets)
        length *= min(2.0, max(0.5, (tets / count) ** (1.0 / 3.0)))
    return best


def main(cli, shared, out_dir):
    os.makedirs(out_dir, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for rel in MODELS:
            model = os.path.join(shared, "models", rel)
            brep = not rel.endswith(".stl")
            volume = None
            for count in COUNTS:
                q, seconds = bisect_run(cli, model, count, work)
                if brep and volume is None:  # the model's volume, for Gmsh's first length
                    volume = mesh_volume(os.path.join(work, "b.vtu"))
                rows.append(dict(model=rel, mesher="bisectmesh", asked=count, tets=q["tets"],
                                 dihedral_min=q["quality"]["dihedral_min"], alpha_mean=q["quality"]["alpha_mean"],
                                 pct_below_10=q["quality"]["pct_dihedral_below_10"], seconds=seconds))
                print("%-28s %5d bisectmesh %6d tets %5.2f deg alpha %.3f" % (rel, count, q["tets"],
                      q["quality"]["dihedral_min"], q["quality"]["alpha_mean"]), flush=True)
                if not brep:
                    continue
                g = gmsh_run(cli, model, count, volume, work)
                if g is None:
                    print("%-28s %5d gmsh failed" % (rel, count), flush=True)
                    continue
                gq, gs = g
                rows.append(dict(model=rel, mesher="gmsh", asked=count, tets=gq["tets"],
                                 dihedral_min=gq["quality"]["dihedral_min"], alpha_mean=gq["quality"]["alpha_mean"],
                                 pct_below_10=gq["quality"]["pct_dihedral_below_10"], seconds=gs))
                print("%-28s %5d gmsh       %6d tets %5.2f deg alpha %.3f" % (rel, count, gq["tets"],
                      gq["quality"]["dihedral_min"], gq["quality"]["alpha_mean"]), flush=True)
    with open(os.path.join(out_dir, "quality_table.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    plot(rows, os.path.join(out_dir, "quality_table.png"))


def mesh_volume(vtu):
    """The volume of a .vtu of 4-node tetrahedra (ASCII, as the CLI writes it)."""
    import re
    text = open(vtu).read()
    arrays = dict(re.findall(r'<DataArray[^>]*Name="(\w+)"[^>]*>(.*?)</DataArray>', text, re.S))
    p = [float(x) for x in arrays["Points"].split()]
    c = [int(x) for x in arrays["connectivity"].split()]
    total = 0.0
    for t in range(0, len(c), 4):
        a, b, cc, d = (p[3 * c[t + k]:3 * c[t + k] + 3] for k in range(4))
        u = [b[i] - a[i] for i in range(3)]
        v = [cc[i] - a[i] for i in range(3)]
        w = [d[i] - a[i] for i in range(3)]
        total += (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
                  + u[2] * (v[0] * w[1] - v[1] * w[0])) / 6.0
    return abs(total)


def plot(rows, dst):
    fig, axes = plt.subplots(1, 2, figsize=(13, 5))
    models = sorted({r["model"] for r in rows})
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, model in enumerate(models):
        for mesher, style in (("bisectmesh", "o-"), ("gmsh", "s:")):
            sel = [r for r in rows if r["model"] == model and r["mesher"] == mesher]
            if not sel:
                continue
            label = "%s (%s)" % (os.path.basename(model), "BisectMesh" if mesher == "bisectmesh" else "Gmsh")
            colour = colours[i % len(colours)]
            axes[0].semilogx([r["asked"] for r in sel], [r["dihedral_min"] for r in sel], style, color=colour, label=label)
            axes[1].semilogx([r["asked"] for r in sel], [r["alpha_mean"] for r in sel], style, color=colour, label=label)
    axes[0].axhline(10, color="grey", lw=0.8)
    axes[1].axhline(0.20, color="grey", lw=0.8)
    axes[0].set_ylabel("smallest dihedral angle (degrees)")
    axes[1].set_ylabel("mean alpha")
    for ax in axes:
        ax.set_xlabel("R asked")
    finish(fig, axes, dst, legend_size=6)


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(os.path.dirname(here))
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build", "bin", "bisect-mesh"),
         sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "..", "shared"),
         sys.argv[3] if len(sys.argv) > 3 else os.path.join(root, "build", "bench"))
