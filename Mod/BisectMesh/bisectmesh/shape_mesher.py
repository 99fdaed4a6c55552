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

import gc
import numbers
import threading
import time

import numpy as np

from . import arguments, core
from .femmesh_arrays import TET4_PERMUTATION, TET10_PERMUTATION
from .femmesh_file import read_femmesh

# FreeCAD's defaults for a Part view object (Part preferences "MeshDeviation" and
# "MeshAngularDeflection"): the deviation in percent, the angular deflection in degrees
DEFAULT_DEVIATION = 0.5
DEFAULT_ANGULAR_DEFLECTION = 28.5
# The finest chord deviation taken: OpenCASCADE's confusion tolerance (mm), and a millionth of the
# shape's diagonal (finer, BRepMesh runs out of memory and aborts FreeCAD)
MIN_DEFLECTION = 1e-7
MIN_RELATIVE_DEFLECTION = 1e-6


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
    mm, "curvature_elements": elements per full turn}.

    TypeError for a resolution that is neither; ValueError, naming the key, for values FreeCAD's
    views do not take (angular deflection outside 1..180 degrees, deviation above 100 %) or a
    deflection finer than OpenCASCADE can tessellate the shape (it would abort FreeCAD)."""
    angular = DEFAULT_ANGULAR_DEFLECTION
    box = shape.BoundBox
    if isinstance(resolution, dict):
        unknown = set(resolution) - {"deviation", "angular_deflection", "deflection"}
        if unknown:
            raise ValueError("resolution: unknown key(s) %s (deviation, angular_deflection, deflection)"
                             % ", ".join(sorted(map(str, unknown))))
        if "angular_deflection" in resolution:
            angular = arguments.positive("resolution['angular_deflection']", resolution["angular_deflection"])
        if "deflection" in resolution:
            deflection = arguments.positive("resolution['deflection']", resolution["deflection"])
        else:
            deviation = arguments.positive("resolution['deviation']", resolution.get("deviation", DEFAULT_DEVIATION))
            if deviation > 100:
                raise ValueError("resolution['deviation'] is a percentage of the shape's size: at most 100 (got %r)"
                                 % deviation)
            deflection = (box.XLength + box.YLength + box.ZLength) / 300.0 * deviation
    elif isinstance(resolution, bool) or not isinstance(resolution, numbers.Real):
        raise TypeError("resolution must be a number (mm) or a dict, not %s" % type(resolution).__name__)
    else:
        deflection = arguments.positive("resolution", resolution)
    if not 1.0 <= angular <= 180.0:
        raise ValueError("resolution['angular_deflection'] must lie between 1 and 180 degrees (got %r)" % angular)
    _check_deflection("resolution", deflection, box)
    return {"chord_deviation": deflection, "curvature_elements": max(3.0, 360.0 / angular)}


def _check_deflection(name, deflection, box):
    finest = max(MIN_DEFLECTION, MIN_RELATIVE_DEFLECTION * box.DiagonalLength)
    if deflection < finest:
        raise ValueError("%s: a deflection of %.3g mm is finer than OpenCASCADE can tessellate this shape "
                         "(%.3g mm across): give at least %.3g mm" % (name, deflection, box.DiagonalLength, finest))


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
                 stage seconds, quality), "seconds" (core, femmesh) and "arrays" (the mesh's
                 MeshArrays, FemMesh ids beside them, for ``bisectmesh.quality``)
    options      min_size, max_size, curvature_elements (elements per full turn, default 12),
                 chord_deviation, size_grading, regions ([{"size": mm, "faces": [...], "edges":
                 [...], "vertices": [...], "solids": [...]}], FreeCAD's numbers from 1 or names
                 such as "Face3"), optimize, smooth, slivers, mean_shape, face_moves, insertion,
                 max_elements (the tetrahedra thin walls may make before the mesh is refused;
                 default what half of the memory holds): see
                 ``bisectmesh.core().default_options()`` and the README

    Raises TypeError for an argument of the wrong type or an unknown option; ValueError for an
    unusable value (naming the argument), a request that would need more than half of the
    memory, or unusable input (naming FreeCAD's Face<k>, Edge<k>, Solid<k>);
    bisectmesh.core().Cancelled when cancelled; RuntimeError when a stage of the generator cannot
    finish.
    """

    shape = arguments.part_shape_argument(shape)
    elements, size = arguments.count_or_size(elements, size)
    order = arguments.order(order)
    hints = arguments.flag("hints", hints)
    progress = arguments.optional_callable("progress", progress)
    threads = arguments.threads(threads)
    report = arguments.optional_dict("report", report)
    own = {"elements", "size", "order", "threads"}
    known = set(core().default_options()) - own
    for name in options:
        if name not in known:
            raise TypeError("mesh_shape() got an unexpected keyword argument %r (options: %s)" % (
                name, ", ".join(sorted(known))))
    for name in ("min_size", "max_size", "chord_deviation", "curvature_elements"):
        if options.get(name) is not None:  # 0: no bound
            options[name] = 0.0 if options[name] == 0 else arguments.positive(name, options[name])
    if options.get("chord_deviation"):
        _check_deflection("chord_deviation", options["chord_deviation"], shape.BoundBox)
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
    arguments.check_workload(elements, abs(shape.Volume), size, options.get("max_size") or None)
    if options.get("max_elements") is None:  # what thin walls make, checked by the core once its nodes are placed
        options["max_elements"] = arguments.element_limit()
    core_share = progress_shares(order)[0]

    def core_progress(fraction):
        return None if progress is None else progress(core_share * fraction)

    t0 = time.time()
    brep = shape.exportBrepToString()
    out = core().mesh_brep(brep, name="the shape", progress=core_progress, elements=elements, size=size, order=int(order),
                           threads=int(threads), **options)
    t1 = time.time()
    _warn_mesh_like(out["stats"])
    if progress is not None and progress(core_share) is False:
        raise core().Cancelled("meshing cancelled")

    def build_progress(fraction):
        if progress is not None and progress(core_share + (1 - core_share) * fraction) is False:
            raise core().Cancelled("meshing cancelled")

    mesh = femmesh_from_arrays(out, len(shape.Faces), int(out["stats"]["regions"]),
                               None if progress is None else build_progress)
    t2 = time.time()
    if progress is not None and progress(1.0) is False:
        raise core().Cancelled("meshing cancelled")
    if report is not None:
        report.update(stats=out["stats"], seconds={"core": t1 - t0, "femmesh": t2 - t1}, arrays=core_arrays(out))
    return mesh


def _warn_mesh_like(stats):
    """FreeCAD's report view is told when the shape is a mesh made into a shape (coplanar
    triangle faces, stats["coplanar_hint"]): its triangles' edges and sharp corners bound the
    elements, and Part's refine merges them. Only on the main thread (the task panel's worker
    shows it in its summary instead, mesh_object.summary)."""
    hint = stats.get("coplanar_hint")
    if not hint or threading.current_thread() is not threading.main_thread():
        return
    try:
        import FreeCAD
    except ImportError:  # outside FreeCAD: the report's stats carry it
        return
    FreeCAD.Console.PrintWarning("BisectMesh: %s\n" % hint)


def progress_shares(order, check=False):
    """The bar's shares of the time: (generator, FemMesh build, check of the result), summing to
    1 (the check's 0 unless ``check``). Issue 19 asks for a bar that moves with the time; measured
    on a filleted block at 2e5 tetrahedra (tests/freecad/gui_stall.py), FreeCAD's adding of the
    nodes and elements takes two fifths of the time at order 2 (ten nodes an element), a sixth at
    order 1, and the check of the core's own arrays (no reading of the FemMesh) 5-9%."""
    core, femmesh, checking = ((0.52, 0.42, 0.06) if order == 2 else (0.76, 0.15, 0.09))
    if not check:
        core, femmesh, checking = core / (core + femmesh), femmesh / (core + femmesh), 0.0
    return core, femmesh, checking


def core_arrays(out):
    """The :class:`MeshArrays` of the core's mesh dict, with the ids ``femmesh_from_arrays`` gives
    (1..N, 1..T): what ``bisectmesh.quality`` takes instead of reading the FemMesh back."""
    from .femmesh_arrays import MeshArrays

    tets = np.ascontiguousarray(out["tets"], dtype=np.int64)
    nodes = np.ascontiguousarray(out["nodes"], dtype=np.float64).reshape(-1, 3)
    return MeshArrays(nodes, tets, np.arange(1, len(nodes) + 1, dtype=np.int64),
                      np.arange(1, len(tets) + 1, dtype=np.int64), 2 if tets.shape[1] == 10 else 1, {})


def _slices(array, step):
    """(offset, rows as Python lists) of ``array``, ``step`` rows at a time."""
    for start in range(0, len(array), step):
        yield start, array[start:start + step].tolist()


def femmesh_from_arrays(out, faces, solids, progress=None):
    """A ``Fem.FemMesh`` of the core's mesh dict (nodes, tets, region, tris, tri_tag) with the
    groups ``Face<k>_Nodes``, ``Face<k>_Faces`` (k = 1..faces) and ``Solid<r>`` (r = 1..solids).
    ``progress(fraction)`` is called now and then.

    On the main thread the nodes and elements go in by FreeCAD's reading of a binary ``.vtu``
    (``femmesh_file``: lug at 10^5, 0.19 s against 0.33 s at order 1, 0.34 s against 0.72 s at
    order 2), one C++ call that holds the GIL throughout; nothing waits on the main thread but the
    caller. Off it (the mesh panel's worker), and wherever that reading fails, they are added one
    call each, in slices. A caller that gives ``progress`` can Stop, and Stop must come within
    0.5 s (issue 19): the read and the groups' one call each do not call back, so they are taken
    only while they stay short (:data:`READ_WITHOUT_CALLS`); above, the sliced calls.

    Off the main thread the build lets the window's thread in after each slice. Measured in a
    FreeCAD window at 2e5 tetra10 (tests/freecad/gui_stall.py) the window froze 0.2-0.57 s while
    this ran: the worker gave the GIL up between calls and took it back before
    the window's thread, waiting on a busy machine, was scheduled (Python's switch interval only
    helps a waiter that finds the GIL held all along). A 1 ms sleep per slice (5,000 items, 20-50
    ms of FreeCAD's adding) ends that: the longest freeze became 0.04-0.06 s. At 2e5 tetra10 it
    is about 160 sleeps, under 0.2 s of the 2 s build, and nothing on the main thread, where no
    window waits. Python's cycle collector is off meanwhile: each slice's row
    lists live long enough to be promoted, and the full collections that followed (20-35 ms each,
    one every 0.1 s, GIL held) walked all of FreeCAD's objects to find nothing (rows hold no
    cycles)."""
    worker = threading.current_thread() is not threading.main_thread()
    pause = 0.001 if worker else 0.0

    def tick(fraction):
        if pause:
            time.sleep(pause)
        if progress is not None:
            progress(fraction)

    read = not worker and (progress is None or _build_weight(out) <= READ_WITHOUT_CALLS)
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        return _femmesh_from_arrays(out, faces, solids, tick, read=read)
    finally:
        if was_enabled:
            gc.enable()


# The largest build (nodes and items weighed by _item_weights) read from a file when the caller
# can Stop. The read and the groups' one call each went 1.25 us a weight without a call back
# (filleted block at 2e5 tetrahedra, main thread: 0.19-0.48 s at order 1, 1.05 s at order 2;
# the checker's CI, two jobs at once, once passed 0.5 s at order 1), against 0.05-0.09 s
# between calls by slices; the slices cost the build 0.66-0.73 s against 0.42-0.74 s at order 1,
# 1.76-2.15 s against 1.35-1.42 s at order 2. 1.2e5 is about 0.15 s of reading: 7e4 tetra4 or
# 3e4 tetra10, where the two ways differ by hundredths of a second.
READ_WITHOUT_CALLS = 1.2e5


def _build_weight(out):
    """The build's weight (nodes, tetrahedra, triangles by :func:`_item_weights`) of a core mesh dict."""
    tets = np.asarray(out["tets"])
    weights = _item_weights(tets.shape[1] == 10)
    return len(out["nodes"]) * weights[0] + len(tets) * weights[1] + len(out["tris"]) * weights[2]


def _item_weights(quadratic):
    """The bar's weights of a node, a tetrahedron and a triangle: what FreeCAD's adding of each
    costs against a node's (measured in freecadcmd, 10^5 nodes and 4 * 10^4 elements: a node 1.6
    us, a tetra10 4.0, a tetra4 2.1, a 6-node triangle 3.1). Counted alike, the nodes ran the bar
    ahead of the time (at 2e5 tetra10 57% of the build's bar in 32% of its time; gui_stall.py's
    limit is 0.2)."""
    return (1.0, 2.5 if quadratic else 1.35, 2.0 if quadratic else 1.3)


def _femmesh_from_arrays(out, faces, solids, tick, read):
    nodes, tets, tris = np.asarray(out["nodes"], float), np.asarray(out["tets"]), np.asarray(out["tris"])
    region, tri_tag = np.asarray(out["region"]), np.asarray(out["tri_tag"])
    quadratic = tets.shape[1] == 10
    weights = _item_weights(quadratic)
    done = _build_weight(out)  # the items' share, once in
    total = max(1.0, done + faces + solids)
    # a progress call every 5,000 items: about 50 ms of FreeCAD's adding of tetra10 (Stop within
    # 0.5 s). The arrays become Python lists a slice at a time: one tolist() of 10^6 tetra10 holds
    # the GIL for a second and more, and the window with it.
    step = 5000
    perm = list(TET10_PERMUTATION if quadratic else TET4_PERMUTATION)
    first = len(tets) + 1  # the triangles' ids follow the tetrahedra's
    ordered = tets[:, perm]
    mesh = read_femmesh(nodes, [(ordered, 3), (tris, 2)]) if read else None
    if mesh is not None:
        tick(done / total)
    else:
        mesh = _femmesh_by_calls(nodes, ordered, tris, weights, step, lambda added: tick(added / total))
    # FreeCAD 0.20's addGroupElements walks every element of the group's kind at each call (lug at
    # 10^6: 221 calls of 5,000 ids took 3.5 s, 16 ms each; all 15 groups in one call each 1.5 s,
    # about 1 us an id besides the walks), so the main thread gives each group's ids in one call
    # and the worker slices of 50,000 (lug at 10^6 on a worker: the build 4.9 s against 7.0 s, a
    # thread waiting for the GIL 0.125 s at the longest)
    group_step = 50000 if not read else max(1, len(nodes), len(tets), len(tris))
    for k in range(faces):
        mine = np.nonzero(tri_tag == k)[0]
        for kind, ids in (("Nodes", np.unique(tris[mine]) + 1), ("Faces", mine + first)):
            g = mesh.addGroup("Face%d_%s" % (k + 1, kind), kind[:-1])
            for _, part in _slices(ids, group_step):
                mesh.addGroupElements(g, part)
                tick((done + k) / total)
    for r in range(solids):
        g = mesh.addGroup("Solid%d" % (r + 1), "Volume")
        ids = np.nonzero(region == r)[0] + 1
        for start, part in _slices(ids, group_step):
            mesh.addGroupElements(g, part)
            tick((done + faces + r + start / len(ids)) / total)
    tick(1.0)
    return mesh


def _femmesh_by_calls(nodes, tets, tris, weights, step, tick):
    """A ``Fem.FemMesh`` of nodes (ids 1..N), tetrahedra in FreeCAD's node order (1..T) and
    triangles (T+1..), one FreeCAD call per item; after each slice of ``step`` items,
    ``tick(added)``, the items added so far weighed by ``weights`` (:func:`_item_weights`)."""
    import Fem

    mesh = Fem.FemMesh()
    add_node, add_volume, add_face = mesh.addNode, mesh.addVolume, mesh.addFace
    done = 0.0
    for array, add, first_id, weight in ((nodes, lambda p, i: add_node(p[0], p[1], p[2], i), 1, weights[0]),
                                         (tets + 1, add_volume, 1, weights[1]),
                                         (tris + 1, add_face, len(tets) + 1, weights[2])):
        for start, rows in _slices(array, step):
            for i, row in enumerate(rows, first_id + start):
                add(row, i)
            done += len(rows) * weight
            tick(done)
    return mesh
