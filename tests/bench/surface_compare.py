"""BisectMesh beside FreeCAD's own Gmsh mesher on a box with a hole and fillets at about 5,000
tetrahedra: the surface meshes drawn side by side (docs/images/box-hole-fillets.png), and the
figures a FEM user compares (tetrahedra, mean and smallest gamma, smallest dihedral angle, the
surface triangles' smallest angles) printed as JSON.

Run on demand (not a pass/fail test), with FreeCAD's interpreter:
    freecadcmd tests/bench/surface_compare.py
(freecadcmd opens its arguments as documents: BISECT_PICTURE=OUT.png picks another picture,
BISECT_SHAPE another shape: box-hole (the default), tube (FreeCAD's constraint_transform_torque,
radius 5, wall 1, length 50, at its shipped 2,869 tetrahedra asked: the wall caps the size) or
plate (50 x 20 x 1 at 500 asked) or frustum (Part.makeCone(10, 3, 30) at 3,000 asked: a full
conical side whose seam has proxy nodes along it) or spring (a circle of radius 3 swept along a
helix of radius 15, pitch 20 and height 60 by makePipeShell, at 30,000 asked: a B-spline face
whose proxy the linear deflection governed) or slot (a cylinder of radius 10 with a slot cut 0.05
from its wall, at 5,000 asked: the wall caps the size).)
Gmsh's CharacteristicLengthMax is searched until its count is within 10% of BisectMesh's.
"""

import json
import os
import shutil
import sys
import tempfile

import numpy as np

import FreeCAD
import Part

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
BUILD_MOD = os.environ.get("BISECTMESH_BUILD_MOD", os.path.join(ROOT, "build", "Mod", "BisectMesh"))
if os.path.isdir(BUILD_MOD):
    sys.path.insert(0, BUILD_MOD)

import bisectmesh  # noqa: E402
from bisectmesh import shape_mesher  # noqa: E402

sys.path.insert(0, os.path.join(ROOT, "tests", "freecad"))
from fc_helpers import helical_spring  # noqa: E402

ELEMENTS = 5000


def box_with_hole_and_fillets():
    """60 x 40 x 20, a through hole of radius 8, its four vertical edges filleted at radius 5."""
    box = Part.makeBox(60, 40, 20)
    vertical = [e for e in box.Edges if abs(e.Vertexes[0].Point.z - e.Vertexes[1].Point.z) > 1]
    box = box.makeFillet(5, vertical)
    return box.cut(Part.makeCylinder(8, 20, FreeCAD.Vector(30, 20, 0)))


def tube():
    return Part.makeCylinder(5, 50).cut(Part.makeCylinder(4, 50))


def slotted_cylinder():
    """Radius 10, height 5, a slot [8, 9.9] x [-1, 1] from z = 2 up: its end wall 0.05 to 0.1
    from the cylinder's, thinner than the facets of the cylinder's proxy stand off it."""
    return Part.makeCylinder(10, 5).cut(Part.makeBox(1.9, 2, 4, FreeCAD.Vector(8, -1, 2)))


# name -> (shape maker, elements asked, Gmsh's first length, picture)
SHAPES = {
    "box-hole": (box_with_hole_and_fillets, ELEMENTS, 4.0, "box-hole-fillets.png"),
    "tube": (tube, 2869, 1.5, "thin-tube.png"),
    "plate": (lambda: Part.makeBox(50, 20, 1), 500, 1.0, "thin-plate.png"),
    "frustum": (lambda: Part.makeCone(10, 3, 30), 3000, 2.4, "frustum.png"),
    "spring": (helical_spring, 30000, 1.5, "spring.png"),
    "slot": (slotted_cylinder, 5000, 1.0, "slotted-cylinder.png"),
}


def surface_triangles(arrays):
    """The boundary triangles of a tetrahedral mesh: the faces one tetrahedron has."""
    t = arrays.tets[:, :4]
    faces = np.concatenate([t[:, [1, 2, 3]], t[:, [0, 3, 2]], t[:, [0, 1, 3]], t[:, [0, 2, 1]]])
    key = np.sort(faces, axis=1)
    _, first, count = np.unique(key, axis=0, return_index=True, return_counts=True)
    return faces[first[count == 1]]


def smallest_angles(nodes, tris):
    p = nodes[tris]
    out = []
    for k in range(3):
        a, b, c = p[:, k], p[:, (k + 1) % 3], p[:, (k + 2) % 3]
        u, v = b - a, c - a
        cos = np.einsum("ij,ij->i", u, v) / (np.linalg.norm(u, axis=1) * np.linalg.norm(v, axis=1))
        out.append(np.degrees(np.arccos(np.clip(cos, -1, 1))))
    return np.min(out, axis=0)


def figures(mesh):
    q = bisectmesh.quality(mesh)
    arrays = bisectmesh.mesh_arrays(mesh)
    tris = surface_triangles(arrays)
    angles = smallest_angles(arrays.nodes, tris)
    return {"tets": q["tets"], "nodes": len(arrays.nodes), "gamma_mean": q["gamma_mean"], "gamma_min": q["gamma_min"],
            "alpha_mean": q["alpha_mean"], "dihedral_min": q["dihedral_min"],
            "pct_dihedral_below_10": q["pct_dihedral_below_10"], "surface_triangles": len(tris),
            "surface_angle_min": float(angles.min()), "surface_angle_mean": float(angles.mean()),
            "pct_surface_angle_below_20": float(100 * np.mean(angles < 20))}, arrays.nodes, tris


def gmsh_mesh(doc, part, length):
    import ObjectsFem
    from femmesh.gmshtools import GmshTools

    obj = ObjectsFem.makeMeshGmsh(doc, "Gmsh")
    obj.Part = part
    obj.ElementOrder = "1st"
    obj.CharacteristicLengthMax = length
    doc.recompute()
    tools = GmshTools(obj)
    try:
        error = tools.create_mesh()
    finally:
        folder = os.path.abspath(getattr(tools, "working_dir", "") or "")
        if os.path.dirname(folder) == os.path.abspath(tempfile.gettempdir()) and os.path.basename(folder).startswith("fcfem_"):
            shutil.rmtree(folder, ignore_errors=True)
    if error:
        raise RuntimeError("Gmsh failed: %s" % error)
    mesh = obj.FemMesh
    doc.removeObject(obj.Name)
    return mesh


def draw(panels, out):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    fig = plt.figure(figsize=(12, 5.2))
    for i, (title, nodes, tris) in enumerate(panels):
        ax = fig.add_subplot(1, len(panels), i + 1, projection="3d")
        poly = Poly3DCollection(nodes[tris], facecolor="#d9e3f0", edgecolor="#203040", linewidths=0.25)
        ax.add_collection3d(poly)
        lo, hi = nodes.min(axis=0), nodes.max(axis=0)
        ax.set_xlim(lo[0], hi[0]), ax.set_ylim(lo[1], hi[1]), ax.set_zlim(lo[2], hi[2])
        ax.set_box_aspect(hi - lo)
        ax.view_init(elev=32, azim=-58)
        ax.set_axis_off()
        ax.set_title(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=130)


def main():
    name = os.environ.get("BISECT_SHAPE", "box-hole")
    if name not in SHAPES:
        raise SystemExit("BISECT_SHAPE: one of %s (got %r)" % (", ".join(SHAPES), name))
    make, elements, length, picture = SHAPES[name]
    out = os.environ.get("BISECT_PICTURE") or os.path.join(ROOT, "docs", "images", picture)
    shape = make()
    doc = FreeCAD.newDocument("SurfaceCompare")
    try:
        part = doc.addObject("Part::Feature", "Part")
        part.Shape = shape
        doc.recompute()
        bisect, bn, bt = figures(shape_mesher.mesh_shape(shape, elements=elements, order=1))
        bisect["elements_asked"] = elements
        # Gmsh's size searched for the same count (its count goes as length^-3)
        for _ in range(8):
            gm, gn, gt = figures(gmsh_mesh(doc, part, length))
            ratio = gm["tets"] / bisect["tets"]
            if abs(ratio - 1) < 0.1:
                break
            length *= ratio ** (1 / 3)
        gm["characteristic_length_max"] = length
    finally:
        FreeCAD.closeDocument(doc.Name)
    draw([("BisectMesh: %d tetrahedra, mean gamma %.3f" % (bisect["tets"], bisect["gamma_mean"]), bn, bt),
          ("Gmsh (FreeCAD's mesher): %d tetrahedra, mean gamma %.3f" % (gm["tets"], gm["gamma_mean"]), gn, gt)], out)
    print(json.dumps({"bisectmesh": bisect, "gmsh": gm, "picture": out}, indent=1))


main()
