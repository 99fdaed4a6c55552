"""BisectMesh for FreeCAD: tetrahedral meshing by domain bisection, and mesh quality.

The macro API (the workbench's commands are thin wrappers over it)::

    import bisectmesh
    mesh = bisectmesh.mesh_shape(part_obj.Shape, elements=20000, order=2,
                                 resolution=bisectmesh.view_resolution(part_obj))   # a Fem.FemMesh
    obj = bisectmesh.make_mesh_object(doc, part_obj, elements=20000)   # a document object ...
    bisectmesh.remesh(obj)                                   # ... meshed (a recompute never does)
    report = bisectmesh.quality(mesh)   # of a Fem.FemMesh or a FEM mesh object
    report["valid"], report["gamma_mean"], report["measures"]["gamma"]["histogram"]

The measures are defined once in the C++ core (``libbisect/include/bisect/quality.hpp``) and
computed there; this package moves the mesh between FreeCAD and the core and keeps FreeCAD's
node and element ids in everything it reports.
"""

__version__ = "0.1.0"

MEASURES = ("dihedral_min", "dihedral_max", "solid_angle_min", "gamma", "alpha")

from .mesh_object import make_mesh_object, remesh  # noqa: E402,F401  (import FreeCAD only when called)


# What builds and installs the compiled module, as the messages name it.
SETUP_COMMAND = "./scripts/setup.sh"


def core():
    """The compiled module ``bisectmesh._core``, with a plain message when it is missing."""
    try:
        from . import _core
    except ImportError as err:
        raise ImportError(
            "bisectmesh._core, the compiled part of BisectMesh, cannot be loaded (%s): build and "
            "install it with %s in BisectMesh's source folder, then restart FreeCAD" % (err, SETUP_COMMAND)) from err
    return _core


_core_problem = []


def core_problem():
    """'' when the compiled module loads, else the one line of :func:`core`'s ImportError. A
    failure is remembered (the workbench's commands ask this often); a success costs nothing
    once the module is loaded."""
    if _core_problem:
        return _core_problem[0]
    try:
        core()
    except ImportError as err:
        _core_problem.append(str(err))
        return _core_problem[0]
    return ""


def mesh_shape(shape, elements=None, size=None, **options):
    """A tetrahedral ``Fem.FemMesh`` of the solids of a Part shape, meshed in-process; see
    :func:`bisectmesh.shape_mesher.mesh_shape` for the options (order, resolution, hints,
    optimize, smooth, progress, threads, report)."""
    from .shape_mesher import mesh_shape as run

    return run(shape, elements=elements, size=size, **options)


def view_resolution(obj):
    """{"deviation": percent, "angular_deflection": degrees} of a Part object's view (FreeCAD's
    defaults without a GUI); pass it as ``mesh_shape(..., resolution=...)``. TypeError unless
    ``obj`` is a document object with a Shape."""
    import FreeCAD

    from .shape_mesher import view_resolution as read

    if not isinstance(obj, FreeCAD.DocumentObject) or not hasattr(obj, "Shape"):
        raise TypeError("obj must be a document object with a Shape, not %s" % type(obj).__name__)

    return read(obj)


def _plain(value):
    """NumPy scalars and arrays to plain Python, so that a report survives json.dumps."""
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if hasattr(value, "tolist"):
        return value.tolist()
    return value


def mesh_arrays(femmesh):
    """The tetrahedra of a Fem.FemMesh (or FEM mesh object) as arrays in the core's convention;
    see :class:`bisectmesh.femmesh_arrays.MeshArrays`. A BisectMesh object meshed in this
    session hands over the generator's arrays it kept instead of reading its FemMesh (4 s at
    2e5 tetra10). MeshArrays come back as they are."""
    from .femmesh_arrays import MeshArrays, femmesh_to_arrays

    if isinstance(femmesh, MeshArrays):
        return femmesh
    kept = getattr(getattr(femmesh, "Proxy", None), "mesh_arrays", None)
    arrays = kept() if callable(kept) else None
    return arrays if arrays is not None else femmesh_to_arrays(femmesh)


def element_quality(femmesh, arrays=None):
    """Per-tetrahedron measures: (tet_ids, {measure: array}) with NumPy arrays in the order of
    ``tet_ids`` (FreeCAD element ids). Measures: volume (of the positively oriented element;
    negative when FreeCAD's element is inverted), dihedral_min, dihedral_max (degrees),
    solid_angle_min (sr), gamma, alpha."""
    from .femmesh_arrays import MeshArrays

    if arrays is not None and not isinstance(arrays, MeshArrays):
        raise TypeError("arrays must be the MeshArrays of mesh_arrays(femmesh) or None, not %s" % type(arrays).__name__)
    arrays = mesh_arrays(femmesh) if arrays is None else arrays
    return arrays.tet_ids, dict(core().element_quality(arrays.nodes, arrays.tets))


def quality(femmesh, validate=True, per_element=False, progress=None):
    """Quality and validity of the tetrahedra of a FEM mesh, as a JSON-friendly dict.

    femmesh      a Fem.FemMesh, a document object with a FemMesh property, or the
                 :class:`bisectmesh.femmesh_arrays.MeshArrays` of one (what ``mesh_arrays``
                 returns, or ``mesh_shape``'s report["arrays"]: no reading of the FemMesh)
    validate     also run the mesh validator (orientation, conformity, closed boundary, ...)
    per_element  also return every element's measures under "per_element"
    progress     callable(fraction) -> bool|None, called on this thread now and then (at most
                 every 50 ms within the validator); False cancels (bisectmesh.core().Cancelled)

    The dict holds the core's quality summary: ``tets``, ``dihedral_min``, ``dihedral_max``,
    ``solid_angle_min``, ``solid_angle_mean``, ``gamma_mean``, ``gamma_min``, ``alpha_mean``,
    ``pct_dihedral_below_10`` and ``measures`` ({name: {min, mean, max, lo, hi, histogram}} for
    dihedral_min, dihedral_max, solid_angle_min, gamma, alpha); and besides:

    ``nodes``            node count of the FemMesh
    ``order``            1 or 2
    ``skipped_volumes``  {kind: count} of volume elements that are not tetrahedra
    ``valid``            True/False, or None when not validated
    ``violations``       [{kind, ids, message}], ids being FreeCAD node or element ids
    ``per_element``      {ids: [element ids], volume: [...], dihedral_min: [...], ...}

    Raises TypeError for arguments of the wrong type, ValueError when the mesh has no tetrahedra.
    """
    from . import arguments

    arguments.flag("validate", validate)
    arguments.flag("per_element", per_element)
    progress = arguments.optional_callable("progress", progress)
    c = core()

    def report_progress(fraction):
        if progress is not None and progress(fraction) is False:
            raise c.Cancelled("cancelled")

    arrays = mesh_arrays(femmesh)
    report_progress(0.0)
    if len(arrays.tets) == 0:
        other = ", ".join("%d %s" % (n, k) for k, n in sorted(arrays.skipped.items()))
        raise ValueError("the FEM mesh has no tetrahedra" + (" (it has %s)" % other if other else ""))
    report = _plain(dict(c.quality_summary(arrays.nodes, arrays.tets,
                                           progress=None if progress is None else lambda x: progress(0.2 * x))))
    # shares measured at 2e5 tetra10: the summary 0.2 s, the validator 0.7 s
    report_progress(0.2)
    report["nodes"] = int(len(arrays.nodes))
    report["order"] = int(arrays.order)
    report["skipped_volumes"] = dict(arrays.skipped)
    report["valid"] = None
    report["violations"] = []
    if validate:
        report["violations"] = _violations(c, arrays, None if progress is None else lambda x: progress(0.2 + 0.8 * x))
        report["valid"] = not report["violations"]
    report_progress(1.0)
    if per_element:
        ids, measures = element_quality(None, arrays)
        table = {"ids": _plain(ids)}
        table.update({name: _plain(values) for name, values in measures.items()})
        report["per_element"] = table
    return report


def _violations(c, arrays, progress=None):
    found = []
    for v in c.validate(arrays.nodes, arrays.tets, node_ids=arrays.node_ids, tet_ids=arrays.tet_ids, progress=progress):
        found.append(_plain(dict(v)))
    if arrays.skipped:
        # Other volume elements close the mesh where the tetrahedra stop and use nodes of their
        # own: judged on the tetrahedra alone, such faces and nodes are not defects.
        found = [v for v in found if v["kind"] not in ("open_boundary", "unused_node")]
    return found


def format_report(report):
    """A few lines of text for the report view or a console, of a report of :func:`quality`."""
    if not isinstance(report, dict) or "tets" not in report or "measures" not in report:
        raise TypeError("report must be a dict returned by bisectmesh.quality, not %s" % type(report).__name__)
    lines = ["%d tetrahedra (order %d), %d nodes" % (report["tets"], report["order"], report["nodes"])]
    if report.get("skipped_volumes"):
        lines.append("not tetrahedra, skipped: " + ", ".join(
            "%d %s" % (n, k) for k, n in sorted(report["skipped_volumes"].items())))
    if report.get("valid") is True:
        lines.append("valid: no inverted or degenerate elements, conforming, closed boundary")
    elif report.get("valid") is False:
        lines.append("NOT valid: %d problem(s)" % len(report["violations"]))
        lines.extend("  " + v["message"] for v in report["violations"][:20])
    lines.append("dihedral angles %.2f .. %.2f deg, %.2f%% of elements below 10 deg" % (
        report["dihedral_min"], report["dihedral_max"], report["pct_dihedral_below_10"]))
    lines.append("minimum solid angle %.4f sr (mean of element minima %.4f)" % (
        report["solid_angle_min"], report["solid_angle_mean"]))
    lines.append("gamma min %.4f mean %.4f, alpha mean %.4f" % (
        report["gamma_min"], report["gamma_mean"], report["alpha_mean"]))
    return "\n".join(lines)
