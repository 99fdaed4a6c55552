"""Helpers of the FreeCAD tests: documents built in code, Gmsh meshes made by FreeCAD's own
mesher, and an independent NumPy computation of the quality measures.

The reference measures are written here from their definitions (ARCHITECTURE.md §3), not from
the C++ code: dihedral angles from the angle between face normals, solid angles by the Van
Oosterom-Strackee formula, gamma = 374.123 V^2/S^3, alpha = inradius / circumradius with the
circumcentre from its linear system.
"""

import os

import numpy as np

GAMMA_BETA = 374.123


def artifacts_dir():
    """Where tests leave pictures and reports for people to look at (created on demand)."""
    path = os.environ.get("BISECTMESH_ARTIFACTS") or os.path.join(os.getcwd(), "test-artifacts")
    os.makedirs(path, exist_ok=True)
    return path


def box_minus_cylinder(doc, name="BoxMinusCylinder"):
    """A 20 x 10 x 10 box with a cylinder of radius 3 taken out, right through it along y."""
    import FreeCAD
    import Part

    box = Part.makeBox(20, 10, 10)
    cylinder = Part.makeCylinder(3, 10, FreeCAD.Vector(10, 0, 5), FreeCAD.Vector(0, 1, 0))
    obj = doc.addObject("Part::Feature", name)
    obj.Shape = box.cut(cylinder)
    doc.recompute()
    return obj


def helical_spring(wire=3, radius=15, pitch=20, height=60):
    """A circle of radius `wire` swept by makePipeShell (Frenet) along a helix: one B-spline face
    and two end discs."""
    import Part

    helix = Part.makeHelix(pitch, height, radius)
    edge = helix.Edges[0]
    start = edge.FirstParameter
    sweep = Part.BRepOffsetAPI.MakePipeShell(helix)
    sweep.setFrenetMode(True)
    sweep.add(Part.Wire([Part.makeCircle(wire, edge.valueAt(start), edge.tangentAt(start))]))
    sweep.build()
    sweep.makeSolid()
    return sweep.shape()


def gmsh_mesh(doc, part, order=1, size=3.0, name=None):
    """Meshes ``part`` with FreeCAD's Gmsh mesher (femmesh.gmshtools), as a FEM user would."""
    import ObjectsFem
    from femmesh.gmshtools import GmshTools

    obj = ObjectsFem.makeMeshGmsh(doc, name or "GmshOrder%d" % order)
    obj.Part = part
    obj.ElementOrder = "1st" if order == 1 else "2nd"
    obj.CharacteristicLengthMax = size
    doc.recompute()
    error = GmshTools(obj).create_mesh()
    if error:
        raise RuntimeError("Gmsh failed: %s" % error)
    doc.recompute()
    return obj


def fc_elements(femmesh):
    """(element ids, #T by 3 by 4 corner coordinates) straight from FreeCAD, no conversion."""
    nodes = femmesh.Nodes
    ids, corners = [], []
    for vid in femmesh.Volumes:
        element = femmesh.getElementNodes(vid)
        if len(element) in (4, 10):
            ids.append(vid)
            corners.append([tuple(nodes[n]) for n in element[:4]])
    return np.array(ids, dtype=np.int64), np.array(corners, dtype=np.float64).reshape(-1, 4, 3)


def reference_measures(corners):
    """The measures of every tetrahedron of ``corners`` (#T by 4 by 3), any orientation.

    Returns {volume (signed, (p1-p0).((p2-p0)x(p3-p0))/6), dihedral_min, dihedral_max (degrees),
    solid_angle_min (sr), gamma, alpha} as arrays."""
    p = np.asarray(corners, dtype=np.float64)
    edge = lambda i, j: p[:, j] - p[:, i]  # noqa: E731
    volume = np.einsum("ij,ij->i", edge(0, 1), np.cross(edge(0, 2), edge(0, 3))) / 6.0

    # Face f is opposite corner f; its normal made to point away from corner f.
    faces = ((1, 2, 3), (0, 2, 3), (0, 1, 3), (0, 1, 2))
    normals, areas = [], []
    for f, (a, b, c) in enumerate(faces):
        n = np.cross(p[:, b] - p[:, a], p[:, c] - p[:, a])
        away = np.einsum("ij,ij->i", n, p[:, a] - p[:, f])
        n = n * np.sign(away)[:, None]
        length = np.linalg.norm(n, axis=1)
        normals.append(n / length[:, None])
        areas.append(0.5 * length)
    surface = np.sum(areas, axis=0)

    # The dihedral angle at an edge is between the two faces through it, i.e. the faces
    # opposite the other two corners: 180 degrees minus the angle between outward normals.
    dihedral = []
    for k in range(4):
        for m in range(k + 1, 4):
            nk, nm = normals[k], normals[m]
            between = np.arctan2(np.linalg.norm(np.cross(nk, nm), axis=1), np.einsum("ij,ij->i", nk, nm))
            dihedral.append(180.0 - np.degrees(between))
    dihedral = np.array(dihedral)

    # Van Oosterom-Strackee: tan(omega/2) = |a.(b x c)| / (abc + (a.b)c + (a.c)b + (b.c)a).
    solid = []
    for i in range(4):
        a, b, c = (p[:, j] - p[:, i] for j in range(4) if j != i)
        la, lb, lc = (np.linalg.norm(v, axis=1) for v in (a, b, c))
        dot = lambda u, v: np.einsum("ij,ij->i", u, v)  # noqa: E731
        numerator = np.abs(dot(a, np.cross(b, c)))
        denominator = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la
        solid.append(2.0 * np.arctan2(numerator, denominator))
    solid = np.array(solid)

    gamma = GAMMA_BETA * volume ** 2 / surface ** 3

    # Circumcentre x: |x - p0| = |x - pj| for j = 1..3, i.e. 2 (pj - p0).x = |pj|^2 - |p0|^2.
    matrix = 2.0 * np.stack([edge(0, j) for j in (1, 2, 3)], axis=1)
    rhs = np.stack([np.einsum("ij,ij->i", p[:, j], p[:, j]) - np.einsum("ij,ij->i", p[:, 0], p[:, 0])
                    for j in (1, 2, 3)], axis=1)
    centre = np.linalg.solve(matrix, rhs[:, :, None])[:, :, 0]
    circumradius = np.linalg.norm(centre - p[:, 0], axis=1)
    inradius = 3.0 * np.abs(volume) / surface
    return {
        "volume": volume,
        "dihedral_min": dihedral.min(axis=0),
        "dihedral_max": dihedral.max(axis=0),
        "solid_angle_min": solid.min(axis=0),
        "gamma": gamma,
        "alpha": inradius / circumradius,
    }


# (lo, hi, bins) of the summary's histograms, as documented for quality_summary
HISTOGRAM_RANGES = {
    "dihedral_min": (0.0, 90.0, 18),
    "dihedral_max": (0.0, 180.0, 18),
    "solid_angle_min": (0.0, 0.6, 12),
    "gamma": (0.0, 1.0, 10),
    "alpha": (0.0, 1.0 / 3.0, 10),
}


def histogram_bounds(values, lo, hi, bins, tolerance=1e-9):
    """Counts per bin of equal slices of [lo, hi] (values outside clamped into the end bins),
    as (certain, possible): a value within ``tolerance`` of a bin edge may fall on either side
    in another implementation, so it counts as possible in both neighbours and certain in none."""
    values = np.asarray(values, dtype=np.float64)
    width = (hi - lo) / bins
    position = (values - lo) / width
    lower = np.clip(np.floor(position - tolerance / width), 0, bins - 1).astype(int)
    upper = np.clip(np.floor(position + tolerance / width), 0, bins - 1).astype(int)
    certain = np.bincount(lower[lower == upper], minlength=bins)
    possible = certain + np.bincount(lower[lower != upper], minlength=bins) \
        + np.bincount(upper[lower != upper], minlength=bins)
    return certain, possible
