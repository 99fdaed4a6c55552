"""FreeCAD solids to a tetrahedral FEM mesh, in-process, on the true surfaces.

The shape crosses to the C++ core as a BREP string (``Part.Shape.exportBrepToString()``): no
geometry is done in Python. The core (``bisectmesh._core.mesh_brep``) reads it with
OpenCASCADE, meshes every face on its true surface, fills the solids (thesis ch. 5, then the 3D
pipeline) and, for order 2, puts the boundary mid-nodes on the surfaces with every element's
Jacobian positive. The mesh comes back as NumPy arrays and becomes a ``Fem.FemMesh`` with its
groups (:func:`femmesh_from_arrays`).

Groups: ``Face<k>_Nodes`` (the nodes on B-rep face k, its edges and vertices included) and
``Face<k>_Faces`` (its boundary triangles) for every face, ``Solid<r>`` (the tetrahedra of solid
r) for every solid; k and r count from 1, as FreeCAD names sub-shapes.
"""

import numpy as np

from . import core
from .femmesh_arrays import TET4_PERMUTATION, TET10_PERMUTATION

# FreeCAD's defaults for a Part view object (Part preferences "MeshDeviation" and
# "MeshAngularDeflection"): the deviation in percent, the angular deflection in degrees
DEFAULT_DEVIATION = 0.5
DEFAULT_ANGULAR_DEFLECTION = 28.5


def view_resolution(obj):
    """The tessellation settings of a Part object as its view shows it: {"deviation": percent,
    "angular_deflection": degrees} from ``obj.ViewObject`` when the GUI is up, else from the
    Part preferences (FreeCAD's defaults when unset)."""
    view = getattr(obj, "ViewObject", None)
    if view is not None and hasattr(view, "Deviation"):
        return {"deviation": float(view.Deviation), "angular_deflection": float(view.AngularDeflection)}
    import FreeCAD

    prefs = FreeCAD.ParamGet("User parameter:BaseApp/Preferences/Mod/Part")
    return {"deviation": prefs.GetFloat("MeshDeviation", DEFAULT_DEVIATION),
            "angular_deflection": prefs.GetFloat("MeshAngularDeflection", DEFAULT_ANGULAR_DEFLECTION)}


def resolution_options(shape, resolution):
    """The resolution hints of thesis 2.3 as curvature bounds: a CSG modeller's resolution says
    how finely the designer wants a curved surface drawn, so the mesh is at least that fine there.
    ``resolution`` is a number (the chord deviation in mm) or a dict {"deviation": percent (turned
    into mm by FreeCAD's own rule for its views: the mean of the bounding box's sides times the
    percentage), "angular_deflection": degrees, "deflection": mm}. Returns {"chord_deviation":
    mm, "curvature_elements": elements per full turn}."""
    angular = DEFAULT_ANGULAR_DEFLECTION
    if isinstance(resolution, dict):
        unknown = set(resolution) - {"deviation", "angular_deflection", "deflection"}
        if unknown:
            raise ValueError("resolution: unknown key(s) %s" % ", ".join(sorted(unknown)))
        angular = float(resolution.get("angular_deflection", angular))
        if "deflection" in resolution:
            deflection = float(resolution["deflection"])
        else:
            box = shape.BoundBox
            deflection = (box.XLength + box.YLength + box.ZLength) / 300.0 * float(resolution.get("deviation", DEFAULT_DEVIATION))
    else:
        deflection = float(resolution)
    if not deflection > 0 or deflection != deflection or deflection == float("inf"):
        raise ValueError("resolution: the deflection must be a positive number (got %r)" % deflection)
    if not 0 < angular < 180:
        raise ValueError("resolution: the angular deflection must lie between 0 and 180 degrees (got %r)" % angular)
    return {"chord_deviation": deflection, "curvature_elements": max(3.0, 360.0 / angular)}


def _number_of_elements(elements):
    if elements is None:
        return None
    if isinstance(elements, bool) or not isinstance(elements, int):
        raise ValueError("elements must be a whole number (got %r)" % (elements,))
    if elements <= 0:
        raise ValueError("elements must be positive (got %d)" % elements)
    return elements


def _size(size):
    if size is None:
        return None
    if isinstance(size, bool) or not isinstance(size, (int, float)):
        raise ValueError("size must be a number (got %r)" % (size,))
    if not (size > 0 and size != float("inf")):
        raise ValueError("size must be a positive number (got %r)" % (size,))
    return float(size)


def mesh_shape(shape, elements=None, size=None, order=2, resolution=None, hints=False, progress=None, threads=0,
               report=None, **options):
    """A tetrahedral ``Fem.FemMesh`` of the solids of ``shape`` (a Part.Shape: solids, CompSolids,
    BooleanFragments, compounds of solids, closed shells).

    elements     the required number of tetrahedra (thesis R), or
    size         the element size instead
    order        1: tetra4, 2: tetra10 (mid-nodes of boundary edges on the B-rep surfaces)
    resolution   the resolution hints (thesis 2.3), see :func:`resolution_options`: the shape's
                 chords at most that far from its curved faces; hints=True takes FreeCAD's
                 default view resolution when resolution is None
    progress     callable(fraction) -> bool|None, called on this thread; False cancels (raises
                 bisectmesh.core().Cancelled)
    threads      threads for the generator (0: one per core)
    report       a dict to fill with "stats" (as ``bisect-mesh --stats`` writes them: counts,
                 stage seconds, quality) and "seconds" (core, femmesh)
    options      min_size, max_size, curvature_elements (elements per full turn, default 12),
                 chord_deviation, size_grading, regions ([{"size": mm, "faces": [...], "edges":
                 [...], "vertices": [...], "solids": [...]}], FreeCAD's numbers from 1 or names
                 such as "Face3"), optimize, smooth, slivers, insertion: see
                 ``bisectmesh.core().default_options()`` and the README

    Raises ValueError for unusable input or options (naming the argument, or FreeCAD's Face<k>,
    Edge<k>, Solid<k>), bisectmesh.core().Cancelled when cancelled, RuntimeError when a stage of
    the generator cannot finish.
    """
    import time

    elements, size = _number_of_elements(elements), _size(size)
    if (elements is None) == (size is None):
        raise ValueError("give elements or size")
    if order not in (1, 2) or isinstance(order, bool):
        raise ValueError("order %r: give 1 (tetra4) or 2 (tetra10)" % (order,))
    if hints and resolution is None:
        resolution = {"deviation": DEFAULT_DEVIATION}
    if resolution is not None:
        bounds = resolution_options(shape, resolution)
        if options.get("chord_deviation"):
            bounds["chord_deviation"] = min(bounds["chord_deviation"], float(options["chord_deviation"]))
        if options.get("curvature_elements"):
            bounds["curvature_elements"] = max(bounds["curvature_elements"], float(options["curvature_elements"]))
        options.update(bounds)
    if not getattr(shape, "Solids", None) and not getattr(shape, "Shells", None):
        raise ValueError("the shape has no solid to mesh (%d faces, no closed shell)" % len(getattr(shape, "Faces", [])))
    # the core's share of the time is most of it; reading the file into FreeCAD takes the rest
    core_share = 0.85

    def core_progress(fraction):
        return None if progress is None else progress(core_share * fraction)

    t0 = time.time()
    brep = shape.exportBrepToString()
    out = core().mesh_brep(brep, name="the shape", progress=core_progress, elements=elements, size=size, order=int(order),
                           threads=int(threads), **options)
    t1 = time.time()
    if progress is not None and progress(core_share) is False:
        raise core().Cancelled("meshing cancelled")

    def build_progress(fraction):
        if progress is not None and progress(core_share + (1 - core_share) * fraction) is False:
            raise core().Cancelled("meshing cancelled")

    mesh = femmesh_from_arrays(out, len(shape.Faces), int(out["stats"]["regions"]), build_progress)
    t2 = time.time()
    if progress is not None and progress(1.0) is False:
        raise core().Cancelled("meshing cancelled")
    if report is not None:
        report.update(stats=out["stats"], seconds={"core": t1 - t0, "femmesh": t2 - t1})
    return mesh


def femmesh_from_arrays(out, faces, solids, progress=None):
    """A ``Fem.FemMesh`` of the core's mesh dict (nodes, tets, region, tris, tri_tag) with the
    groups ``Face<k>_Nodes``, ``Face<k>_Faces`` (k = 1..faces) and ``Solid<r>`` (r = 1..solids).
    ``progress(fraction)`` is called now and then."""
    import Fem

    nodes, tets, tris = np.asarray(out["nodes"], float), np.asarray(out["tets"]), np.asarray(out["tris"])
    region, tri_tag = np.asarray(out["region"]), np.asarray(out["tri_tag"])
    total = max(1, len(nodes) + len(tets) + len(tris))
    step = 50000
    mesh = Fem.FemMesh()
    add_node = mesh.addNode
    for i, p in enumerate(nodes.tolist()):
        add_node(p[0], p[1], p[2], i + 1)
        if progress is not None and i % step == step - 1:
            progress(i / total)
    perm = list(TET10_PERMUTATION if tets.shape[1] == 10 else TET4_PERMUTATION)
    add_volume = mesh.addVolume
    for e, t in enumerate((tets[:, perm] + 1).tolist()):
        add_volume(t, e + 1)
        if progress is not None and e % step == step - 1:
            progress((len(nodes) + e) / total)
    add_face = mesh.addFace
    first = len(tets) + 1
    for i, t in enumerate((tris + 1).tolist()):
        add_face(t, first + i)
    for k in range(faces):
        mine = np.nonzero(tri_tag == k)[0]
        g = mesh.addGroup("Face%d_Nodes" % (k + 1), "Node")
        mesh.addGroupElements(g, (np.unique(tris[mine]) + 1).tolist() if len(mine) else [])
        g = mesh.addGroup("Face%d_Faces" % (k + 1), "Face")
        mesh.addGroupElements(g, (mine + first).tolist())
    for r in range(solids):
        g = mesh.addGroup("Solid%d" % (r + 1), "Volume")
        mesh.addGroupElements(g, (np.nonzero(region == r)[0] + 1).tolist())
    if progress is not None:
        progress(1.0)
    return mesh
