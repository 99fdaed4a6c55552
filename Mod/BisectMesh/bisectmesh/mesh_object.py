"""The BisectMesh FEM mesh document object: a ``Fem::FemMeshObjectPython`` that holds a mesh of
the solids of a Part object, made by :func:`bisectmesh.shape_mesher.mesh_shape`.

    obj = bisectmesh.make_mesh_object(doc, part_obj, elements=5000)   # or size=2.5
    bisectmesh.remesh(obj)                                            # meshes (blocking)

Like FreeCAD's Gmsh object, a document recompute never meshes: meshing is slow, and a recompute
cannot show progress or be stopped. A recompute checks the object's inputs instead (its
parameters, its mesh regions, the Part's geometry and, with UseResolutionHints, the Part's view
resolution): when they differ from those of the last meshing, the object is marked as needing a re-mesh
(NeedsRemesh, MeshStatus, and a greyed icon with a warning badge in the tree). Meshing happens in
the task panel, through the Re-mesh command (a worker thread with progress and Stop), or in a
macro through :func:`remesh`. A property that makes no sense (a Part without a solid, a negative
count) is reported in one line naming the object, and the mesh is marked, never a traceback.

Size control: TargetElements or ElementSize, MinSize and MaxSize, CurvatureElements (elements per
full circle) and ChordDeviation, and FreeCAD's mesh regions in MeshRegionList (mesh_regions.py).
UseResolutionHints (off for new objects) adds the Part's view Deviation as a curvature bound.
A view property changes no document object, so no recompute sees a new Deviation: the GUI
watches the Part's view instead (gui/view_watch.py) and runs :func:`check_inputs` within a second.

The parameters are properties (group "BisectMesh"), the results read-only properties (group
"Results"). FreeCAD stores the FemMesh in the document itself; the proxies below keep no state
of their own, so that a saved document reopens with ``bisectmesh.mesh_object`` importable and
nothing else. The view provider (gui/view_provider.py) only adds an icon and the edit panel: the
mesh is drawn by FEM's own C++ view provider of ``Fem::FemMeshObjectPython``. This module imports
nothing of the GUI at load time.

FreeCAD is imported inside the functions: ``import bisectmesh`` stays possible without it.
"""

import hashlib
import json
import time

from .preferences import DEFAULT_ELEMENTS  # noqa: F401  (the count when the preferences hold none)

TYPE = "Fem::BisectMesh"
ORDERS = ["1st", "2nd"]

_PARAMETERS = "BisectMesh"
_RESULTS = "Results"
# Results are outputs: setting them must not mark the object for another recompute.
_PROP_OUTPUT = 8

# (type, name, tooltip) of the parameters; the defaults are set by make_mesh_object.
_PARAMETER_PROPERTIES = (
    ("App::PropertyLink", "Part",
     "The Part object whose solids are meshed (it needs a Shape with at least one solid)"),
    ("App::PropertyEnumeration", "ElementOrder",
     "1st: linear tetrahedra (tetra4); 2nd: quadratic tetrahedra (tetra10), their boundary "
     "mid-edge nodes on the true surfaces"),
    ("App::PropertyInteger", "TargetElements",
     "The number of tetrahedra asked for (the thesis's R); 0: use ElementSize instead"),
    ("App::PropertyLength", "ElementSize",
     "The element size (nodal spacing), used when TargetElements is 0"),
    ("App::PropertyLength", "MinSize",
     "The smallest element size allowed anywhere (0: no bound); it wins over curvature and "
     "mesh regions"),
    ("App::PropertyLength", "MaxSize",
     "The largest element size allowed anywhere (0: no bound)"),
    ("App::PropertyInteger", "CurvatureElements",
     "Curved faces and edges get at least this many elements per full circle (0: no bound, "
     "else at least 3)"),
    ("App::PropertyLength", "ChordDeviation",
     "Element edges on curved faces stay within this distance of the surface (0: no bound)"),
    ("App::PropertyLinkList", "MeshRegionList",
     "FEM mesh regions (ObjectsFem.makeMeshRegion): a smaller element size on chosen faces, "
     "edges, vertices or solids of the Part"),
    ("App::PropertyBool", "UseResolutionHints",
     "Also take the Part's view resolution (Deviation, AngularDeflection) as a curvature bound, "
     "the thesis's resolution hints: a finer view Deviation gives a finer mesh on curved faces. "
     "A change of the view resolution marks the mesh as needing a re-mesh"),
    ("App::PropertyInteger", "OptimizePasses",
     "Passes of global optimisation by local transformations (0: none)"),
    ("App::PropertyInteger", "SmoothPasses",
     "Passes of guarded nodal smoothing (0: none)"),
)

# Values of the size-control properties that ask for nothing more than the version before them
# did: such a value is left out of the inputs' fingerprint, so that a mesh saved by that version
# is still current once the property has been added on restore.
_NEUTRAL = {"min_size": 0.0, "max_size": 0.0, "curvature_elements": 12, "chord_deviation": 0.0, "regions": []}
# what a property added on restore starts at (the same as the version before it meshed with)
_RESTORED = {"CurvatureElements": 12}

_RESULT_PROPERTIES = (
    ("App::PropertyInteger", "NodeCount", "Nodes of the last mesh"),
    ("App::PropertyInteger", "ElementCount", "Tetrahedra of the last mesh"),
    ("App::PropertyFloat", "MinDihedralAngle", "Smallest dihedral angle of the last mesh, in degrees"),
    ("App::PropertyFloat", "MeshingTime", "Seconds the last meshing took, from the shape to the FemMesh"),
    ("App::PropertyString", "Summary", "The last meshing in a few lines: counts, stage times, quality"),
    ("App::PropertyString", "ResultData", "The last meshing's counts, times and quality as JSON "
     "(what the panel shows)"),
    ("App::PropertyBool", "NeedsRemesh", "True when the mesh no longer matches the Part or the "
     "parameters (or there is none yet): re-mesh with the Re-mesh command, the panel, or "
     "bisectmesh.remesh(obj). A recompute never re-meshes"),
    ("App::PropertyString", "MeshStatus", "Why the mesh needs a re-mesh, or what is wrong with the "
     "parameters; empty when the mesh is up to date"),
    ("App::PropertyString", "MeshedInputs", "Fingerprint of the inputs of the last meshing"),
)
_HIDDEN_RESULTS = ("ResultData", "MeshedInputs")


class MeshObject:
    """Proxy of a BisectMesh FEM mesh object: on recompute, marks the mesh as needing a re-mesh
    when its inputs changed (it never meshes there)."""

    Type = TYPE

    def __init__(self, obj):
        obj.Proxy = self
        self.init_properties(obj)

    @staticmethod
    def init_properties(obj):
        """Adds the properties the object lacks; also run on restore, so that documents saved by
        an older version gain the new ones."""
        present = set(obj.PropertiesList)
        for kind, name, tooltip in _PARAMETER_PROPERTIES:
            if name not in present:
                obj.addProperty(kind, name, _PARAMETERS, tooltip)
                if name == "ElementOrder":
                    obj.ElementOrder = ORDERS
                    obj.ElementOrder = "2nd"
                elif name in _RESTORED:
                    setattr(obj, name, _RESTORED[name])
        for kind, name, tooltip in _RESULT_PROPERTIES:
            if name not in present:
                obj.addProperty(kind, name, _RESULTS, tooltip, _PROP_OUTPUT)
            # read-only; ResultData and MeshedInputs hidden too: for the code, not for people
            obj.setEditorMode(name, 2 if name in _HIDDEN_RESULTS else 1)

    def onDocumentRestored(self, obj):
        self.init_properties(obj)

    def execute(self, obj):
        """Checks the inputs; never meshes (see the module's docstring)."""
        check_inputs(obj)

    def adopt(self, obj, femmesh, result, key=None, arrays=None):
        """Takes a mesh made from the object's current inputs (by :func:`remesh`, or by the task
        panel in a worker thread); ``key``: their fingerprint, if already known; ``arrays``: the
        generator's MeshArrays of it, kept in memory (not in the document) so that quality and
        colouring need not read the FemMesh back (seconds at 10^6 elements)."""
        self.arrays = None
        obj.FemMesh = femmesh
        self.arrays = arrays
        set_results(obj, result)
        obj.MeshedInputs = key if key is not None else input_key(obj)
        mark_current(obj)
        obj.purgeTouched()

    def onChanged(self, obj, prop):
        if prop == "FemMesh":  # set by anything but adopt: the kept arrays are another mesh's
            self.arrays = None

    def mesh_arrays(self):
        """The MeshArrays of the object's FemMesh when this session made it, else None."""
        return getattr(self, "arrays", None)

    # FreeCAD pickles the proxy into the document: there is nothing to keep.
    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None


def check_inputs(obj, reason=None):
    """Compares ``obj``'s inputs with those of its last meshing and marks the mesh current or as
    needing a re-mesh (what a recompute does; also run when the Part's view resolution changes,
    which recomputes nothing). ``reason``: what MeshStatus says when they differ, if known.
    Returns True when the mesh is current."""
    try:
        key = input_key(obj)
    except ValueError as err:
        mark_stale(obj, str(err), error=True)
        return False
    if not obj.MeshedInputs and obj.FemMesh.VolumeCount > 0 and obj.ResultData:
        # saved by a version that kept no fingerprint: the mesh is taken as the inputs' own
        obj.MeshedInputs = key
    if key != obj.MeshedInputs:
        mark_stale(obj, "not meshed yet" if not obj.ResultData
                   else reason or "the Part, a mesh region or a parameter changed since the last meshing")
        return False
    mark_current(obj)
    return True


def input_key(obj):
    """A fingerprint of everything a meshing of ``obj`` depends on: its parameters and mesh
    regions, the Part's geometry (its BREP text, placement included) and, with
    UseResolutionHints, the Part's view resolution. ValueError (one line, naming the object)
    when the parameters make no sense."""
    from . import shape_mesher

    arguments = mesh_arguments(obj)
    part = obj.Part
    try:
        shape = part_shape(part)
    except ValueError as err:
        raise ValueError("%s: %s" % (obj.Label, err)) from None
    resolution = shape_mesher.view_resolution(part) if arguments["use_hints"] else None
    # size controls at their neutral values are left out: see _NEUTRAL
    keyed = {k: v for k, v in arguments.items() if k not in _NEUTRAL or v != _NEUTRAL[k]}
    digest = hashlib.sha1(shape_fingerprint(shape).encode())
    digest.update(json.dumps([part.Name, keyed, resolution], sort_keys=True).encode())
    return digest.hexdigest()


def shape_fingerprint(shape):
    """The geometry of ``shape`` as text that a geometric edit changes and a mere copy, a save
    and reload, or a tessellation for the view do not (its BREP text does: it carries the
    triangulation): the sub-shape counts, every vertex (placed), the type, area and centre of
    every face, the length of every edge, and the volume, to 10 significant digits."""
    def g(x):
        return "%.10g" % x

    parts = [shape.ShapeType, str(len(shape.Solids)), str(len(shape.Shells)), str(len(shape.Faces)),
             str(len(shape.Edges)), g(shape.Volume)]
    parts.extend("%s,%s,%s" % (g(v.X), g(v.Y), g(v.Z)) for v in shape.Vertexes)
    for face in shape.Faces:
        centre = face.CenterOfMass
        parts.append("%s:%s:%s,%s,%s" % (type(face.Surface).__name__, g(face.Area), g(centre.x), g(centre.y),
                                          g(centre.z)))
    parts.extend(g(edge.Length) for edge in shape.Edges)
    return ";".join(parts)


def mark_stale(obj, reason, error=False):
    """Marks the mesh as needing a re-mesh, says why once in the report view, and greys its icon."""
    import FreeCAD

    changed = not obj.NeedsRemesh or obj.MeshStatus != reason
    obj.NeedsRemesh = True
    obj.MeshStatus = reason
    if changed:
        if error:
            FreeCAD.Console.PrintError("BisectMesh: %s\n" % reason)
        else:
            FreeCAD.Console.PrintWarning("BisectMesh: %s needs a re-mesh: %s\n" % (obj.Label, reason))
        _refresh_icon(obj)


def mark_current(obj):
    if obj.NeedsRemesh or obj.MeshStatus:
        obj.NeedsRemesh = False
        obj.MeshStatus = ""
        _refresh_icon(obj)


def _refresh_icon(obj):
    view = getattr(obj, "ViewObject", None)
    if view is not None and hasattr(view, "signalChangeIcon"):
        view.signalChangeIcon()


def remesh(obj, progress=None):
    """Meshes the BisectMesh mesh object ``obj`` from its current Part and parameters, blocking
    (for macros; the GUI's Re-mesh command does the same in a worker thread). ``progress`` as for
    :func:`bisectmesh.mesh_shape`. Returns the result dict (see :func:`mesh_part`).

    TypeError unless ``obj`` is a BisectMesh mesh object; ValueError, naming the object, for
    parameters that make no sense; the exceptions of mesh_shape otherwise."""
    if not is_mesh_object(obj):
        raise TypeError("obj must be a BisectMesh mesh object (made by make_mesh_object), not %r" % (obj,))
    key = input_key(obj)
    part = obj.Part
    try:
        report = {}
        femmesh, result = mesh_part(part, shape=part_shape(part), progress=progress, report=report,
                                    **mesh_arguments(obj))
    except ValueError as err:
        raise ValueError("%s: %s" % (part.Label, err)) from err
    except RuntimeError as err:
        if type(err).__name__ == "Cancelled":
            raise
        raise RuntimeError("%s: %s" % (part.Label, err)) from err
    obj.Proxy.adopt(obj, femmesh, result, key, arrays=report.get("arrays"))
    return result


def mesh_arguments(obj):
    """The keyword arguments of :func:`mesh_part` that ``obj``'s properties and mesh regions ask
    for; ValueError, one line naming the object or the region, for values that make no sense."""
    from . import mesh_regions

    name = obj.Label
    if obj.TargetElements < 0:
        raise ValueError("%s: TargetElements must be 0 (use ElementSize) or more" % name)
    if obj.OptimizePasses < 0 or obj.SmoothPasses < 0:
        raise ValueError("%s: OptimizePasses and SmoothPasses cannot be negative" % name)
    size = float(obj.ElementSize.Value)
    if obj.TargetElements == 0 and size <= 0:
        raise ValueError("%s: set TargetElements, or ElementSize (with TargetElements 0)" % name)
    min_size, max_size = float(obj.MinSize.Value), float(obj.MaxSize.Value)
    if min_size < 0 or max_size < 0 or float(obj.ChordDeviation.Value) < 0:
        raise ValueError("%s: MinSize, MaxSize and ChordDeviation cannot be negative" % name)
    if max_size > 0 and min_size > max_size:
        raise ValueError("%s: MinSize (%g mm) is larger than MaxSize (%g mm)" % (name, min_size, max_size))
    curvature = int(obj.CurvatureElements)
    if curvature != 0 and not 3 <= curvature <= 10000:
        raise ValueError("%s: CurvatureElements must be 0 (no bound) or 3 to 10000 (got %d)" % (name, curvature))
    regions = []
    if obj.Part is not None and getattr(obj.Part, "Shape", None) is not None:
        try:
            regions = mesh_regions.regions_of(obj)
        except ValueError as err:
            raise ValueError("%s: %s" % (name, err)) from None
    return {
        "elements": obj.TargetElements if obj.TargetElements > 0 else None,
        "size": None if obj.TargetElements > 0 else size,
        "order": 1 if obj.ElementOrder == "1st" else 2,
        "use_hints": bool(obj.UseResolutionHints),
        "optimize": int(obj.OptimizePasses),
        "smooth": int(obj.SmoothPasses),
        "min_size": min_size,
        "max_size": max_size,
        "curvature_elements": curvature,
        "chord_deviation": float(obj.ChordDeviation.Value),
        "regions": regions,
    }


def part_shape(part):
    """The shape to mesh of ``part``, or ValueError saying why there is none."""
    if part is None:
        raise ValueError("no Part object to mesh: set the Part property")
    shape = getattr(part, "Shape", None)
    if shape is None or shape.isNull():
        raise ValueError("%s (%s) has no shape to mesh" % (part.Label, part.Name))
    if not shape.Solids:
        raise ValueError("%s (%s) has no solid to mesh (its shape is a %s)"
                         % (part.Label, part.Name, shape.ShapeType))
    return shape


def mesh_part(part, elements=None, size=None, order=2, use_hints=False, optimize=3, smooth=3,
              progress=None, shape=None, resolution=None, min_size=0.0, max_size=0.0,
              curvature_elements=12, chord_deviation=0.0, regions=None, threads=None, check=False,
              report=None):
    """Meshes the solids of ``part`` (a document object with a Shape) the way a BisectMesh object
    does; returns (Fem.FemMesh, result) with result a JSON-friendly dict of counts, stage times
    and the generator's quality summary.

    min_size, max_size, curvature_elements, chord_deviation, regions
                       the size controls of mesh_shape (0: no bound)
    threads            generator threads; None: the preferences' (0: one per core)
    shape, resolution  already read from ``part`` (the task panel reads them in the GUI thread and
                       meshes in another); by default read here.
    check              also validate the mesh (bisectmesh.quality on the generator's arrays, a
                       second or two at 10^6 elements): result["quality"] then holds the
                       report's summary and "valid", result["violations"] the first 20 messages;
                       ``progress`` covers the check too
    report             a dict that receives "arrays": the mesh's MeshArrays (for adopt)
    """
    from . import arguments, preferences, shape_mesher

    elements, size = arguments.count_or_size(elements, size)
    order = arguments.order(order)
    use_hints = arguments.flag("use_hints", use_hints)
    optimize = arguments.passes("optimize", optimize)
    smooth = arguments.passes("smooth", smooth)
    progress = arguments.optional_callable("progress", progress)
    threads = preferences.read("Threads") if threads is None else arguments.threads(threads)
    if shape is None:
        shape = part_shape(part)
    if use_hints and resolution is None:
        resolution = shape_mesher.view_resolution(part)
    if not use_hints:
        resolution = None
    check = arguments.flag("check", check)
    caller_report = arguments.optional_dict("report", report)
    report = {}
    start = time.perf_counter()
    meshing_share = 1.0 - shape_mesher.progress_shares(order, check)[2] if check else 1.0
    meshing_progress = progress
    if progress is not None and check:
        meshing_progress = lambda fraction: progress(meshing_share * fraction)  # noqa: E731
    femmesh = shape_mesher.mesh_shape(shape, elements=elements, size=size, order=order,
                                      resolution=resolution, hints=use_hints, optimize=optimize,
                                      smooth=smooth, progress=meshing_progress, report=report, threads=threads,
                                      min_size=min_size, max_size=max_size,
                                      curvature_elements=curvature_elements,
                                      chord_deviation=chord_deviation, regions=list(regions or []))
    seconds = time.perf_counter() - start
    result = result_of(femmesh, report, seconds, order)
    if check:
        import bisectmesh

        check_progress = None
        if progress is not None:
            check_progress = lambda fraction: progress(meshing_share + (1 - meshing_share) * fraction)  # noqa: E731
        found = bisectmesh.quality(report["arrays"], progress=check_progress)
        result["quality"] = {k: v for k, v in found.items()
                             if k not in ("measures", "violations", "per_element", "skipped_volumes")}
        result["violations"] = [v["message"] for v in found["violations"][:20]]
    if caller_report is not None:
        caller_report["arrays"] = report["arrays"]
    return femmesh, result


def result_of(femmesh, report, seconds, order):
    """What the object keeps of a meshing (see mesh_part)."""
    stats = report.get("stats") or {}
    quality = {k: v for k, v in (stats.get("quality") or {}).items() if k != "measures"}
    result = {
        "nodes": int(femmesh.NodeCount),
        "tets": int(femmesh.VolumeCount),
        "order": int(order),
        "seconds": float(seconds),
        "times": dict(stats.get("times") or {}),
        "quality": quality,
    }
    for key in ("regions", "convex_cells"):
        if key in stats:
            result[key] = stats[key]
    if stats.get("coplanar_hint"):  # a shape made from a mesh: the summary says what to do
        result["note"] = stats["coplanar_hint"]
    for key in ("deflection", "angular_deflection", "input_faces", "projected"):
        if key in report:
            result[key] = report[key]
    return json.loads(json.dumps(result, default=float))  # plain types only


# the generator's stages (the keys of its stats' "times"), named as the thesis's tables name them
STAGES = (("init_geom", "Init geom"), ("bisect", "Bisect"), ("gen_nodes", "Gen. nodes"),
          ("gen_tets", "Gen. tets"), ("optimize", "Optimize"), ("total", "Total"))


def summary(result):
    """A few lines of text for a result of :func:`mesh_part`."""
    lines = ["%d tetrahedra (order %d), %d nodes, in %.2f s" % (
        result["tets"], result["order"], result["nodes"], result["seconds"])]
    times = result.get("times") or {}
    if times:
        lines.append("stages (s): " + ", ".join(
            "%s %.3f" % (label.lower(), times[key]) for key, label in STAGES if key in times))
    q = result.get("quality") or {}
    if "dihedral_min" in q:
        lines.append("dihedral angles %.2f .. %.2f deg, %.2f%% of elements below 10 deg" % (
            q["dihedral_min"], q.get("dihedral_max", float("nan")), q.get("pct_dihedral_below_10", 0.0)))
    if "gamma_mean" in q:
        lines.append("gamma min %.4f mean %.4f, alpha mean %.4f" % (
            q.get("gamma_min", float("nan")), q["gamma_mean"], q.get("alpha_mean", float("nan"))))
    if result.get("note"):
        lines.append("note: " + result["note"])
    return "\n".join(lines)


def set_results(obj, result):
    obj.NodeCount = result["nodes"]
    obj.ElementCount = result["tets"]
    obj.MinDihedralAngle = float((result.get("quality") or {}).get("dihedral_min", 0.0))
    obj.MeshingTime = result["seconds"]
    obj.Summary = summary(result)
    obj.ResultData = json.dumps(result)


def stored_result(obj):
    """The result of the object's last meshing (a dict as mesh_part returns), or None."""
    try:
        return json.loads(obj.ResultData) if obj.ResultData else None
    except (AttributeError, ValueError):
        return None


def is_mesh_object(obj):
    """True for a BisectMesh FEM mesh object."""
    return getattr(getattr(obj, "Proxy", None), "Type", None) == TYPE


def make_mesh_object(doc, part_obj, elements=None, size=None, order=None, use_hints=False, optimize=None,
                     smooth=None, name="BisectMesh", analysis=None, min_size=0.0, max_size=0.0,
                     curvature_elements=None, chord_deviation=0.0):
    """A BisectMesh FEM mesh object of ``part_obj``'s solids in ``doc``, not yet meshed (marked
    NeedsRemesh): mesh it with :func:`remesh` (blocking), the Re-mesh command or the panel.

    elements | size   the target tetrahedron count, or the element size in mm (at most one;
                      neither: the preferences' default, 5000 elements when unset)
    order             1 (tetra4) or 2 (tetra10); None: the preferences' (2 when unset)
    min_size, max_size  bounds on the element size in mm (0: none)
    curvature_elements  elements per full circle on curved faces and edges (0: no bound);
                      None: the preferences' (12 when unset)
    chord_deviation   how far element edges may lie from curved surfaces, mm (0: no bound)
    use_hints         also bound the curvature by the Part's view resolution (UseResolutionHints)
    optimize, smooth  optimisation and smoothing passes; None: the preferences' (3 when unset)
    analysis          the FEM analysis to add it to; by default the active one in the GUI

    Mesh regions: ``ObjectsFem.makeMeshRegion(doc, obj, size)`` and its References.
    Returns the ``Fem::FemMeshObjectPython``. TypeError for an argument of the wrong type,
    ValueError (naming the argument) for a value that cannot be meshed.
    """
    import FreeCAD

    from . import arguments, preferences

    if not isinstance(doc, FreeCAD.Document):
        raise TypeError("doc must be a FreeCAD document, not %s" % type(doc).__name__)
    if not isinstance(part_obj, FreeCAD.DocumentObject) or not hasattr(part_obj, "Shape"):
        raise TypeError("part_obj must be a document object with a Shape, not %s" % type(part_obj).__name__)
    if part_obj.Document is not doc:
        raise ValueError("part_obj %s is in document %s, not in %s" % (part_obj.Label, part_obj.Document.Name, doc.Name))
    defaults = preferences.defaults()
    if elements is None and size is None:
        elements, size = preferences.count_or_size()
    elements, size = arguments.count_or_size(elements, size)
    order = arguments.order(defaults["DefaultOrder"] if order is None else order)
    use_hints = arguments.flag("use_hints", use_hints)
    optimize = arguments.passes("optimize", defaults["OptimizePasses"] if optimize is None else optimize)
    smooth = arguments.passes("smooth", defaults["SmoothPasses"] if smooth is None else smooth)
    curvature_elements = arguments.curvature_elements(
        defaults["CurvatureElements"] if curvature_elements is None else curvature_elements)
    min_size = arguments.bound("min_size", min_size)
    max_size = arguments.bound("max_size", max_size)
    chord_deviation = arguments.bound("chord_deviation", chord_deviation)
    if max_size and min_size > max_size:
        raise ValueError("min_size (%g) is larger than max_size (%g)" % (min_size, max_size))
    if not isinstance(name, str) or not name:
        raise TypeError("name must be a non-empty string, not %r" % (name,))
    if analysis is not None and not (isinstance(analysis, FreeCAD.DocumentObject)
                                     and analysis.isDerivedFrom("Fem::FemAnalysis")):
        raise TypeError("analysis must be a FEM analysis or None, not %s" % type(analysis).__name__)
    obj = doc.addObject("Fem::FemMeshObjectPython", name)
    MeshObject(obj)
    obj.Part = part_obj
    obj.ElementOrder = ORDERS[order - 1]
    obj.TargetElements = elements if elements is not None else 0
    if size is not None:
        obj.ElementSize = size
    obj.UseResolutionHints = use_hints
    obj.OptimizePasses = optimize
    obj.SmoothPasses = smooth
    obj.MinSize = min_size
    obj.MaxSize = max_size
    obj.CurvatureElements = curvature_elements
    obj.ChordDeviation = chord_deviation
    if FreeCAD.GuiUp:
        from .gui.view_provider import ViewProviderMeshObject

        ViewProviderMeshObject(obj.ViewObject)
        if analysis is None:
            analysis = _active_analysis(doc)
    if analysis is not None:
        analysis.addObject(obj)
    return obj


def _active_analysis(doc):
    try:
        import FemGui
    except ImportError:
        return None
    analysis = FemGui.getActiveAnalysis()
    if analysis is not None and analysis.Document is doc:
        return analysis
    return None


def __getattr__(name):
    # Documents saved before the view provider moved to gui/view_provider.py name it
    # bisectmesh.mesh_object.ViewProviderMeshObject: resolved here on first use, so that this
    # module imports nothing of the GUI.
    if name == "ViewProviderMeshObject":
        from .gui.view_provider import ViewProviderMeshObject

        return ViewProviderMeshObject
    raise AttributeError("module %r has no attribute %r" % (__name__, name))
