"""FreeCAD solids to a tetrahedral FEM mesh, in-process.

1. The B-rep is tessellated once, on a copy, with the deflections of the resolution (a view's
   Deviation and AngularDeflection by FreeCAD's own rule, or given): edges shared by faces and
   solids are discretised once, so the pieces conform.
2. The polyhedral input of the C++ generator: a planar B-rep face is one polygon with its holes;
   a curved face is its facets grouped into planar patches (a cylinder's or cone's ruling strip
   is one quadrilateral, not two thin triangles); every solid a region, a face of two solids an
   interface, an inner shell a cavity.
3. Resolution hints (thesis 2.3): every node of a curved face asks for that face's chord length
   as its spacing, so the face grids keep a finer resolution's fine chords along the rulings too;
   planar faces grade from those edges, and the interior keeps the spacing Np.
4. ``bisectmesh._core.generate`` meshes it (GIL released, progress and cancel on this thread),
   then the nodes placed on curved faces' facets are projected onto the true surfaces unless
   that would invert a tetrahedron, and a ``Fem.FemMesh`` is built with a node and a face group
   per B-rep face and a volume group per solid.
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


def tessellation_parameters(shape, resolution=None):
    """(linear deflection in mm, angular deflection in degrees) for ``resolution`` (see
    :func:`mesh_shape`). A deviation becomes an absolute deflection by FreeCAD's own rule for
    its views: the mean of the bounding box's three sides times the deviation in percent."""
    angular = DEFAULT_ANGULAR_DEFLECTION
    if resolution is None:
        resolution = {"deviation": DEFAULT_DEVIATION}
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
    if not deflection > 0:
        raise ValueError("resolution: the linear deflection must be positive (got %g)" % deflection)
    if not 0 < angular < 180:
        raise ValueError("resolution: the angular deflection must lie between 0 and 180 degrees (got %g)" % angular)
    return deflection, angular


def _boundary_loops(tris):
    """The boundary loops of a set of triangles (edges used once), each a list of node ids in the
    triangles' direction."""
    count = {}
    for a, b, c in tris:
        for u, v in ((a, b), (b, c), (c, a)):
            key = (min(u, v), max(u, v))
            count[key] = count.get(key, 0) + 1
    nxt = {}
    for a, b, c in tris:
        for u, v in ((a, b), (b, c), (c, a)):
            if count[(min(u, v), max(u, v))] == 1:
                nxt.setdefault(u, []).append(v)
    loops, used = [], set()
    for start in list(nxt):
        for first in nxt[start]:
            if (start, first) in used:
                continue
            loop, u, v = [start], start, first
            while True:
                used.add((u, v))
                if v == start:
                    break
                loop.append(v)
                candidates = [w for w in nxt.get(v, []) if (v, w) not in used]
                if not candidates:
                    raise ValueError("a face's tessellation has an open boundary")
                u, v = v, candidates[0]
            loops.append(loop)
    return loops


def _loop_area(points, loop, normal):
    """Signed area of a planar loop seen along ``normal``."""
    s = np.zeros(3)
    for i in range(len(loop)):
        s += np.cross(points[loop[i]], points[loop[(i + 1) % len(loop)]])
    return 0.5 * float(np.dot(s, normal))


def _is_planar(face):
    return face.Surface.__class__.__name__ == "Plane"


def _planar_patches(points, tris):
    """Groups a curved face's facets into planar patches: neighbouring facets whose corners lie in
    the plane of the patch's first facet (a cylinder's or a cone's ruling strip is one patch, its
    two triangles coplanar up to round-off). Returns lists of triangle indices."""
    owner = {}
    for i, (a, b, c) in enumerate(tris):
        for u, v in ((a, b), (b, c), (c, a)):
            owner.setdefault((min(u, v), max(u, v)), []).append(i)
    patch_of = [-1] * len(tris)
    patches = []
    for seed in range(len(tris)):
        if patch_of[seed] >= 0:
            continue
        p0, p1, p2 = (points[v] for v in tris[seed])
        normal = np.cross(p1 - p0, p2 - p0)
        normal = normal / np.linalg.norm(normal)
        size = max(np.linalg.norm(p1 - p0), np.linalg.norm(p2 - p1), np.linalg.norm(p0 - p2))
        tol = 1e-11 * size  # far inside the generator's planarity tolerance (1e-9 of a face's diameter)
        patch_of[seed] = len(patches)
        members, stack = [seed], [seed]
        while stack:
            a, b, c = tris[stack.pop()]
            for u, v in ((a, b), (b, c), (c, a)):
                for n in owner[(min(u, v), max(u, v))]:
                    if patch_of[n] >= 0:
                        continue
                    q = [points[w] for w in tris[n]]
                    if np.dot(np.cross(q[1] - q[0], q[2] - q[0]), normal) <= 0:
                        continue
                    if any(abs(np.dot(x - p0, normal)) > tol for x in q):
                        continue
                    patch_of[n] = len(patches)
                    members.append(n)
                    stack.append(n)
        patches.append(members)
    return patches


class PolyhedralShape:
    """The polyhedral input made from a shape, and where each input face came from.

    nodes        #N by 3 float64
    faces        list of input faces for ``_core.generate`` (node lists or {"nodes", "hole_of"})
    regions      one list of input face indices per solid
    brep_face    per input face: the index into ``brep_faces`` of the B-rep face it lies on
    brep_faces   the distinct faces of the tessellated copy of the shape, in ``shape.Faces`` order
    solids       its solids, in order (region r is solids[r])
    deflection   the tessellation's linear deflection (mm); angular_deflection: in degrees
    """


def polyhedral_input(shape, resolution=None):
    """The polyhedral input of a shape's solids (see :class:`PolyhedralShape`); ``resolution`` as
    for :func:`mesh_shape`. Raises ValueError naming the face or solid that cannot be used."""
    import MeshPart

    if not shape.Solids:
        raise ValueError("the shape has no solid to mesh")
    deflection, angular = tessellation_parameters(shape, resolution)
    # A copy is tessellated, so that the caller's shape keeps the triangulation its view made.
    # The whole shape is meshed in one call: an edge shared by faces or solids gets one
    # discretisation, so the pieces conform. Each face then reads its stored triangulation.
    work = shape.copy()
    MeshPart.meshFromShape(Shape=work, LinearDeflection=deflection, AngularDeflection=float(np.radians(angular)),
                           Relative=False)
    solids = list(work.Solids)
    for r, solid in enumerate(solids):
        if not solid.isValid() or solid.Volume <= 0:
            raise ValueError("Solid%d is not a valid closed solid (check it with Part > Check geometry)" % (r + 1))
    brep_faces = list(work.Faces)
    index_of = {}  # rounded coordinates -> node id
    points = []

    def node(q):
        key = (round(q.x, 9), round(q.y, 9), round(q.z, 9))
        if key not in index_of:
            index_of[key] = len(points)
            points.append((q.x, q.y, q.z))
        return index_of[key]

    per_face = []
    for k, face in enumerate(brep_faces):
        pts, tris = face.tessellate(deflection)
        ids = [node(q) for q in pts]
        tris = [(ids[a], ids[b], ids[c]) for a, b, c in tris]
        tris = [t for t in tris if len(set(t)) == 3]
        if not tris:
            raise ValueError("Face%d has no triangles at deflection %g mm" % (k + 1, deflection))
        per_face.append(tris)
    p = np.array(points, float)
    faces, brep_face, faces_of = [], [], []

    def add(loops, k, mine):  # a polygon with holes: the largest loop the outer one
        outer = len(faces)
        for i, loop in enumerate(loops):
            faces.append(loop if i == 0 else {"nodes": loop, "hole_of": outer})
            brep_face.append(k)
            mine.append(len(faces) - 1)

    for k, face in enumerate(brep_faces):
        tris = per_face[k]
        mine = []
        patches = [list(range(len(tris)))] if _is_planar(face) else _planar_patches(p, tris)
        for patch in patches:
            ptris = [tris[i] for i in patch]
            try:
                loops = _boundary_loops(ptris)
            except ValueError:
                raise ValueError("Face%d: its tessellation has an open boundary" % (k + 1)) from None
            t0 = ptris[0]
            normal = np.cross(p[t0[1]] - p[t0[0]], p[t0[2]] - p[t0[0]])
            loops.sort(key=lambda l: -abs(_loop_area(p, l, normal)))
            if len(patches) > 1 and (len(loops) != 1 or len(set(loops[0])) != len(loops[0])):
                for t in ptris:  # a patch with a hole or a pinched boundary: its facets as they are
                    add([list(t)], k, mine)
            else:
                add(loops, k, mine)
        faces_of.append(mine)
    by_hash = {}
    for k, f in enumerate(brep_faces):
        by_hash.setdefault(f.hashCode(), []).append(k)
    regions = []
    for solid in solids:
        region = []
        for f in solid.Faces:
            k = next(i for i in by_hash.get(f.hashCode(), ()) if brep_faces[i].isSame(f))
            region.extend(faces_of[k])
        regions.append(region)
    out = PolyhedralShape()
    out.nodes = p
    out.faces, out.regions, out.brep_face = faces, regions, brep_face
    out.brep_faces, out.solids = brep_faces, solids
    out.deflection, out.angular_deflection = deflection, angular
    return out


def _node_hints(poly, spacing):
    """The spacing each input node asks for (0: none): a node of a curved face asks for that
    face's median facet width (the length of its tessellation's chords, which the resolution
    sets), at least spacing / 4 so that a very fine resolution cannot swamp the requested
    element count (the generator caps it by its spacing Np); the finest face wins at a node
    shared by faces."""
    p = poly.nodes
    widths = {}
    for f, k in zip(poly.faces, poly.brep_face):
        if _is_planar(poly.brep_faces[k]):
            continue
        loop = f if isinstance(f, list) else f["nodes"]
        widths.setdefault(k, []).append(min(np.linalg.norm(p[loop[i]] - p[loop[i - 1]]) for i in range(len(loop))))
    hint = np.zeros(len(p))
    for f, k in zip(poly.faces, poly.brep_face):
        if k not in widths:
            continue
        h = max(spacing / 4, float(np.median(widths[k])))
        for v in (f if isinstance(f, list) else f["nodes"]):
            hint[v] = h if hint[v] == 0 else min(hint[v], h)
    return hint


def _project_onto_faces(nodes, tets, tris, tri_face, brep_faces):
    """Moves the boundary nodes that lie on a curved B-rep face's facets onto the face itself
    (onto the edge where two faces meet), unless that inverts a tetrahedron; returns the number
    moved."""
    import FreeCAD

    faces_at = {}
    for t, k in zip(tris, tri_face):
        for v in t:
            faces_at.setdefault(int(v), set()).add(int(k))
    moved = 0
    corners = tets[:, :4]
    touching = {}
    for e, t in enumerate(corners):
        for v in t:
            touching.setdefault(int(v), []).append(e)

    def positive(e):
        a, b, c, d = (nodes[v] for v in corners[e])
        return np.dot(b - a, np.cross(c - a, d - a)) > 0

    for v, ks in faces_at.items():
        curved = [k for k in ks if not _is_planar(brep_faces[k])]
        if not curved:
            continue
        p = FreeCAD.Vector(*nodes[v])
        if len(ks) == 1:
            face = brep_faces[next(iter(ks))]
            u, w = face.Surface.parameter(p)
            q = face.Surface.value(u, w)
        else:  # on an edge (or a vertex) between faces: the nearest point of their common edges
            best = None
            for edge in brep_faces[curved[0]].Edges:
                if not all(any(edge.isSame(x) for x in brep_faces[k].Edges) for k in ks):
                    continue
                d = edge.distToShape(_vertex(p))
                if best is None or d[0] < best[0]:
                    best = (d[0], d[1][0][0])
            if best is None:
                continue
            q = best[1]
        old = nodes[v].copy()
        nodes[v] = (q.x, q.y, q.z)
        if not all(positive(e) for e in touching.get(v, [])):
            nodes[v] = old  # it would invert a tetrahedron: it stays on the facet
            continue
        moved += 1
    return moved


def _vertex(p):
    import Part

    return Part.Vertex(p)


def mesh_shape(shape, elements=None, size=None, order=2, resolution=None, hints=True, optimize=3, smooth=3,
               progress=None, threads=0, report=None):
    """A tetrahedral ``Fem.FemMesh`` of the solids of ``shape``.

    elements     the required number of tetrahedra (thesis R), or
    size         the element size (nodal spacing) instead
    order        1: tetra4, 2: tetra10 (mid-nodes of boundary edges on the B-rep surfaces)
    resolution   the tessellation's fineness: None (FreeCAD's defaults, Deviation 0.5 % and
                 AngularDeflection 28.5 degrees), a number (the absolute linear deflection), or a
                 dict {"deviation": percent, "angular_deflection": degrees} as
                 :func:`view_resolution` reads from a view object
    hints        grade the volume mesh from the tessellation's fine boundary spacing (thesis 2.3:
                 a finer resolution asks for finer elements there); False: spacing Np everywhere
    optimize     global optimisation passes (local transformations), smooth: smoothing passes
    progress     callable(fraction) -> bool|None, False cancels (raises bisectmesh.core().Cancelled)
    threads      threads for the generator (0: one per core)
    report       a dict to fill with "stats" (the generator's statistics, as ``bisect-mesh
                 --stats`` writes them: counts, stage seconds, quality), "deflection" (mm),
                 "angular_deflection" (degrees), "input_faces" and "projected" (nodes moved
                 from facets onto curved faces)

    Groups: "Face<k>_Nodes" and "Face<k>_Faces" for every B-rep face (k from 1, as FreeCAD names
    faces), "Solid<r>" volumes for every solid.
    Raises ValueError for unusable input (naming the face or solid), bisectmesh.core().Cancelled
    when cancelled, RuntimeError when a stage of the generator cannot finish.
    """
    import Fem

    if (elements is None) == (size is None):
        raise ValueError("give elements or size")
    if order not in (1, 2):
        raise ValueError("order %r: give 1 (tetra4) or 2 (tetra10)" % (order,))

    def go_on(fraction):
        # the stages before and after the generator answer a cancel too (tessellating a large
        # shape and building a large FemMesh take seconds)
        if progress is not None and progress(fraction) is False:
            raise core().Cancelled("meshing cancelled")

    go_on(0.0)
    poly = polyhedral_input(shape, resolution)
    go_on(0.0)
    hint = None
    if hints:
        # the spacing the generator will start from (thesis 6.11: Np = cbrt(8 V / R))
        spacing = float(size) if size else (8 * sum(s.Volume for s in poly.solids) / int(elements)) ** (1 / 3)
        hint = _node_hints(poly, spacing)
    out = core().generate(poly.nodes, poly.faces, poly.regions, elements=int(elements or 0), size=float(size or 0),
                          order=int(order), optimize=int(optimize), smooth=int(smooth), merge_coplanar=False,
                          node_spacing=hint, progress=progress, threads=int(threads), source="the shape")
    nodes = np.array(out["nodes"], float)
    tets, tris = np.array(out["tets"]), np.array(out["tris"])
    tri_face = np.array([poly.brep_face[t] for t in out["tri_tag"]], int)
    go_on(1.0)
    projected = _project_onto_faces(nodes, tets, tris, tri_face, poly.brep_faces)
    go_on(1.0)
    if report is not None:
        report.update(stats=out["stats"], deflection=poly.deflection, angular_deflection=poly.angular_deflection,
                      input_faces=len(poly.faces), hinted_nodes=0 if hint is None else int(np.count_nonzero(hint)), projected=projected)
    mesh = Fem.FemMesh()
    for i, p in enumerate(nodes):
        mesh.addNode(float(p[0]), float(p[1]), float(p[2]), i + 1)
        if i % 50000 == 49999:
            go_on(1.0)
    perm = TET10_PERMUTATION if tets.shape[1] == 10 else TET4_PERMUTATION
    region = np.array(out["region"])
    volumes = {}
    for e, t in enumerate(tets):
        mesh.addVolume([int(t[j]) + 1 for j in perm], e + 1)
        volumes.setdefault(int(region[e]), []).append(e + 1)
        if e % 50000 == 49999:
            go_on(1.0)
    face_ids, face_nodes = {}, {}  # per B-rep face: its triangles' element ids, its nodes' ids
    next_id = len(tets) + 1
    for t, k in zip(tris, tri_face):
        node_ids = [int(v) + 1 for v in t]
        mesh.addFace(node_ids, next_id)
        face_ids.setdefault(int(k), []).append(next_id)
        face_nodes.setdefault(int(k), set()).update(node_ids)
        next_id += 1
    for k in range(len(poly.brep_faces)):
        g = mesh.addGroup("Face%d_Nodes" % (k + 1), "Node")
        mesh.addGroupElements(g, sorted(face_nodes.get(k, ())))
        g = mesh.addGroup("Face%d_Faces" % (k + 1), "Face")
        mesh.addGroupElements(g, face_ids.get(k, []))
    for r in range(len(poly.solids)):
        g = mesh.addGroup("Solid%d" % (r + 1), "Volume")
        mesh.addGroupElements(g, volumes.get(r, []))
    return mesh
