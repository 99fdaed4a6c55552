"""FreeCAD solids to a tetrahedral FEM mesh, in-process: the B-rep is tessellated once (edges
shared by neighbouring faces and solids are discretised once, so the pieces conform), turned into
the polyhedral input of the C++ generator (a planar B-rep face is one polygon face with its
holes, a curved face is its facets; every solid a region, a face of two solids an interface),
meshed by ``bisectmesh._core.generate``, and the nodes the generator placed on curved faces'
facets are projected back onto the true surfaces.

What is here: :func:`polyhedral_input` and :func:`mesh_shape` (a ``Fem.FemMesh`` with a node and
a face group per B-rep face and a volume group per solid). Not yet here: curved faces are meshed
on their tessellation's facets as they come, long and thin along a cylinder's rulings, which
caps the smallest dihedral angle (a box minus a cylinder: 0.3 degrees) and sets a floor on the
element count; resolution hints taken from a view object, the FEM mesh document object and the
GUI command.
"""

import numpy as np

from . import core
from .femmesh_arrays import TET4_PERMUTATION, TET10_PERMUTATION


def default_deflection(shape):
    """The tessellation's linear deflection when none is given: 0.5% of the bounding box's
    diagonal (FreeCAD's default view Deviation is 0.5%)."""
    return 0.005 * shape.BoundBox.DiagonalLength


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


class PolyhedralShape:
    """The polyhedral input made from a shape, and where each input face came from.

    nodes        #N by 3 float64
    faces        list of input faces for ``_core.generate`` (node lists or {"nodes", "hole_of"})
    regions      one list of input face indices per solid
    brep_face    per input face: the index into ``brep_faces`` of the B-rep face it lies on
    brep_faces   the shape's distinct faces (``shape.Faces``), in order
    solids       the shape's solids, in order (region r is solids[r])
    deflection   the tessellation's linear deflection
    """


def polyhedral_input(shape, deflection=None):
    """The polyhedral input of a shape's solids (see :class:`PolyhedralShape`). Raises ValueError
    naming the face whose tessellation cannot be used."""
    solids = list(shape.Solids)
    if not solids:
        raise ValueError("the shape has no solid to mesh")
    deflection = default_deflection(shape) if deflection is None else float(deflection)
    shape.tessellate(deflection)  # one triangulation for the whole shape: shared edges conform
    brep_faces = list(shape.Faces)
    index_of = {}  # rounded coordinates -> node id
    points = []

    def node(p):
        key = (round(p.x, 9), round(p.y, 9), round(p.z, 9))
        if key not in index_of:
            index_of[key] = len(points)
            points.append((p.x, p.y, p.z))
        return index_of[key]

    all_tris, tri_face = [], []
    for k, face in enumerate(brep_faces):
        pts, tris = face.tessellate(deflection)
        ids = [node(p) for p in pts]
        tris = [(ids[a], ids[b], ids[c]) for a, b, c in tris]
        tris = [t for t in tris if len(set(t)) == 3]
        if not tris:
            raise ValueError("face %d (Face%d) has no triangles at deflection %g" % (k, k + 1, deflection))
        all_tris.extend(tris)
        tri_face.extend([k] * len(tris))
    per_face = [[] for _ in brep_faces]
    for t, k in zip(all_tris, tri_face):
        per_face[k].append(t)
    faces, brep_face, faces_of = [], [], []
    for k, face in enumerate(brep_faces):
        tris = per_face[k]
        mine = []
        if _is_planar(face):
            # one polygon with holes: the tessellation's boundary loops, the largest the outer one
            p = np.array(points)
            normal = np.cross(p[tris[0][1]] - p[tris[0][0]], p[tris[0][2]] - p[tris[0][0]])
            loops = _boundary_loops(tris)
            loops.sort(key=lambda l: -abs(_loop_area(p, l, normal)))
            outer = len(faces)
            for i, loop in enumerate(loops):
                faces.append(loop if i == 0 else {"nodes": loop, "hole_of": outer})
                brep_face.append(k)
                mine.append(len(faces) - 1)
        else:
            for t in tris:
                faces.append(list(t))
                brep_face.append(k)
                mine.append(len(faces) - 1)
        faces_of.append(mine)
    regions = []
    for solid in solids:
        region = []
        for f in solid.Faces:
            k = next(i for i, g in enumerate(brep_faces) if g.isSame(f))
            region.extend(faces_of[k])
        regions.append(region)
    out = PolyhedralShape()
    out.nodes = np.array(points, float)
    out.faces, out.regions, out.brep_face = faces, regions, brep_face
    out.brep_faces, out.solids, out.deflection = brep_faces, solids, deflection
    return out


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


def mesh_shape(shape, elements=None, size=None, order=2, resolution=None, progress=None, threads=0):
    """A tetrahedral ``Fem.FemMesh`` of the solids of ``shape``.

    elements     the required number of tetrahedra (thesis R), or
    size         the element size (nodal spacing) instead
    order        1: tetra4, 2: tetra10 (mid-nodes of boundary edges on the B-rep surfaces)
    resolution   the tessellation's linear deflection (default: 0.5% of the bounding box's
                 diagonal); finer makes curved faces' elements smaller
    progress     callable(fraction) -> bool|None, False cancels (raises bisectmesh core().Cancelled)
    threads      threads for the generator (0: one per core)

    Groups: "Face<k>_Nodes" and "Face<k>_Faces" for every B-rep face (k from 1, as FreeCAD names
    faces), "Solid<r>" volumes for every solid.
    """
    import Fem

    if (elements is None) == (size is None):
        raise ValueError("give elements or size")
    poly = polyhedral_input(shape, resolution)
    out = core().generate(poly.nodes, poly.faces, poly.regions, elements=int(elements or 0), size=float(size or 0),
                          order=int(order), merge_coplanar=False, progress=progress, threads=int(threads))
    nodes = np.array(out["nodes"], float)
    tets, tris = np.array(out["tets"]), np.array(out["tris"])
    tri_face = np.array([poly.brep_face[t] for t in out["tri_tag"]], int)
    _project_onto_faces(nodes, tets, tris, tri_face, poly.brep_faces)
    mesh = Fem.FemMesh()
    for i, p in enumerate(nodes):
        mesh.addNode(float(p[0]), float(p[1]), float(p[2]), i + 1)
    perm = TET10_PERMUTATION if tets.shape[1] == 10 else TET4_PERMUTATION
    region = np.array(out["region"])
    volumes = {}
    for e, t in enumerate(tets):
        mesh.addVolume([int(t[j]) + 1 for j in perm], e + 1)
        volumes.setdefault(int(region[e]), []).append(e + 1)
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
