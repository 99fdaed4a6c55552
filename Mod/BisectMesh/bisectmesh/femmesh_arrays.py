"""Conversion between FreeCAD's ``Fem.FemMesh`` and the NumPy arrays of ``bisectmesh._core``.

The core takes ``nodes`` (#N by 3 float64) and ``tets`` (#T by 4 or #T by 10 int64, 0-based
node indices, corners first, mid-edge nodes in the edge order 01 12 02 03 13 23), with every
tetrahedron positively oriented: (p1-p0) . ((p2-p0) x (p3-p0)) > 0.

FreeCAD keeps its meshes in SMESH/SMDS, whose tetrahedra have the opposite orientation. Measured
on FreeCAD 0.20.2 with meshes made by FreeCAD's own Gmsh mesher (femmesh.gmshtools), first and
second order: every one of ~1,550 tetrahedra had (p1-p0) . ((p2-p0) x (p3-p0)) < 0, i.e. seen
from corner 3 the face 0-1-2 turns clockwise. The mid-edge nodes of a 10-node tetrahedron follow
the same edge order as ours (01 12 02 03 13 23) in FreeCAD's corner numbering. So a fixed
renumbering converts between the two conventions, and it must be fixed rather than chosen per
element: an element that is inverted in FreeCAD has to stay inverted for the validator to see it.

We swap corners 1 and 2. Our edges then are: 01 = FreeCAD's 02, 12 = FreeCAD's 12, 02 = FreeCAD's
01, 03 = 03, 13 = FreeCAD's 23, 23 = FreeCAD's 13. The permutation is its own inverse, so the
same tables convert in both directions.
"""

import numpy as np

TET4_PERMUTATION = (0, 2, 1, 3)
TET10_PERMUTATION = (0, 2, 1, 3, 6, 5, 4, 7, 9, 8)

# Volume elements that are not tetrahedra, told apart by their node count (SMDS polyhedra aside).
_OTHER_VOLUME_KINDS = {
    5: "pyramid",
    13: "pyramid",
    6: "prism",
    15: "prism",
    8: "hexahedron",
    20: "hexahedron",
    27: "hexahedron",
}


class MeshArrays:
    """The tetrahedra of a FemMesh as arrays, with FreeCAD's ids beside them.

    nodes     #N by 3 float64, every node of the FemMesh, sorted by FreeCAD node id
    tets      #T by 4 (order 1) or #T by 10 (order 2) int64, 0-based rows of ``nodes``,
              positively oriented (see the module docstring)
    node_ids  #N int64, FreeCAD's id of each row of ``nodes``
    tet_ids   #T int64, FreeCAD's element id of each row of ``tets``
    order     1 or 2 (0 when there are no tetrahedra)
    skipped   {kind: count} of volume elements that are not tetrahedra (pyramid, prism,
              hexahedron, other); a mesh mixing 4- and 10-node tetrahedra is reduced to its corners
              and says so under "tetra10 reduced to corners"
    """

    def __init__(self, nodes, tets, node_ids, tet_ids, order, skipped):
        self.nodes = nodes
        self.tets = tets
        self.node_ids = node_ids
        self.tet_ids = tet_ids
        self.order = order
        self.skipped = skipped

    def used_nodes(self):
        """Boolean mask over the rows of ``nodes``: used by at least one tetrahedron."""
        mask = np.zeros(len(self.nodes), dtype=bool)
        mask[self.tets.ravel()] = True
        return mask

    def __repr__(self):
        return "MeshArrays(nodes=%d, tets=%d, order=%d, skipped=%r)" % (
            len(self.nodes), len(self.tets), self.order, self.skipped)


def as_femmesh(mesh):
    """Accepts a Fem.FemMesh or a document object holding one (``obj.FemMesh``)."""
    inner = getattr(mesh, "FemMesh", None)
    if inner is not None:
        return inner
    if hasattr(mesh, "Nodes") and hasattr(mesh, "Volumes") and hasattr(mesh, "getElementNodes"):
        return mesh
    raise TypeError("expected a Fem.FemMesh or a FEM mesh object, got %s" % type(mesh).__name__)


def femmesh_to_arrays(mesh):
    """Reads the tetrahedra of a FemMesh (or FEM mesh object) into a :class:`MeshArrays`."""
    femmesh = as_femmesh(mesh)
    node_map = femmesh.Nodes  # {id: Vector}, with the mesh's placement applied
    node_ids = np.fromiter(node_map.keys(), dtype=np.int64, count=len(node_map))
    nodes = np.array([tuple(v) for v in node_map.values()], dtype=np.float64).reshape(-1, 3)
    order = np.argsort(node_ids, kind="stable")
    node_ids = node_ids[order]
    nodes = nodes[order]

    by_count = {4: ([], []), 10: ([], [])}
    skipped = {}
    for vid in femmesh.Volumes:
        element = femmesh.getElementNodes(vid)
        slot = by_count.get(len(element))
        if slot is None:
            kind = _OTHER_VOLUME_KINDS.get(len(element), "other")
            skipped[kind] = skipped.get(kind, 0) + 1
            continue
        slot[0].append(vid)
        slot[1].append(element)

    ids4, tets4 = by_count[4]
    ids10, tets10 = by_count[10]
    if ids10 and ids4:
        skipped["tetra10 reduced to corners"] = len(ids10)
        tet_ids = np.array(ids4 + ids10, dtype=np.int64)
        fc_tets = np.array(tets4 + [t[:4] for t in tets10], dtype=np.int64)
        perm = TET4_PERMUTATION
    elif ids10:
        tet_ids = np.array(ids10, dtype=np.int64)
        fc_tets = np.array(tets10, dtype=np.int64)
        perm = TET10_PERMUTATION
    else:
        tet_ids = np.array(ids4, dtype=np.int64)
        fc_tets = np.array(tets4, dtype=np.int64).reshape(-1, 4)
        perm = TET4_PERMUTATION

    if len(fc_tets):
        rows = np.searchsorted(node_ids, fc_tets)
        rows_clipped = np.minimum(rows, len(node_ids) - 1)
        missing = node_ids[rows_clipped] != fc_tets
        if missing.any():
            bad = np.argwhere(missing)[0]
            raise ValueError("element %d refers to node %d, which the mesh does not have"
                             % (tet_ids[bad[0]], fc_tets[bad[0], bad[1]]))
        tets = rows[:, list(perm)]
    else:
        tets = np.zeros((0, 4), dtype=np.int64)
    mesh_order = 0 if len(tets) == 0 else (2 if tets.shape[1] == 10 else 1)
    return MeshArrays(nodes, np.ascontiguousarray(tets, dtype=np.int64), node_ids, tet_ids,
                      mesh_order, skipped)


def arrays_to_femmesh(nodes, tets, node_ids=None, tet_ids=None):
    """Builds a Fem.FemMesh from arrays in the core's convention (the inverse of
    :func:`femmesh_to_arrays`). Ids default to 1..N and 1..T."""
    import Fem

    nodes = np.asarray(nodes, dtype=np.float64).reshape(-1, 3)
    tets = np.asarray(tets, dtype=np.int64)
    if tets.ndim != 2 or tets.shape[1] not in (4, 10):
        raise ValueError("tets must be an array of shape (M, 4) or (M, 10)")
    node_ids = np.arange(1, len(nodes) + 1) if node_ids is None else np.asarray(node_ids)
    tet_ids = np.arange(1, len(tets) + 1) if tet_ids is None else np.asarray(tet_ids)
    perm = list(TET10_PERMUTATION if tets.shape[1] == 10 else TET4_PERMUTATION)
    femmesh = Fem.FemMesh()
    for nid, (x, y, z) in zip(node_ids.tolist(), nodes.tolist()):
        femmesh.addNode(x, y, z, nid)
    fc_tets = node_ids[tets[:, perm]]
    for tid, element in zip(tet_ids.tolist(), fc_tets.tolist()):
        femmesh.addVolume(element, tid)
    return femmesh


# Per face of a tetrahedron (corners in the core's order): its corners, then the rows of its
# edges' mid-nodes in a tetra10 (edges 01 12 02 03 13 23 are rows 4..9).
_TET_FACES = ((1, 2, 3), (0, 2, 3), (0, 1, 3), (0, 1, 2))
_FACE_MIDS = ((5, 9, 8), (6, 9, 7), (4, 8, 7), (4, 5, 6))


def boundary_nodes(arrays):
    """Rows of ``arrays.nodes`` on the mesh's boundary surface (faces of one tetrahedron only),
    mid-edge nodes of those faces included: the nodes FreeCAD's 3D view draws."""
    tets = arrays.tets
    if len(tets) == 0:
        return np.zeros(0, dtype=np.int64)
    faces = np.concatenate([tets[:, list(f)] for f in _TET_FACES])
    keys = np.sort(faces, axis=1)
    if len(arrays.nodes) < 1 << 21:  # three 21-bit rows in one int64: a 1D unique, ten times faster
        keys = (keys[:, 0] << 42) | (keys[:, 1] << 21) | keys[:, 2]
        _, first, counts = np.unique(keys, return_index=True, return_counts=True)
    else:
        _, first, counts = np.unique(keys, axis=0, return_index=True, return_counts=True)
    once = first[counts == 1]
    rows = [faces[once].ravel()]
    if tets.shape[1] == 10:
        mids = np.concatenate([tets[:, list(m)] for m in _FACE_MIDS])
        rows.append(mids[once].ravel())
    return np.unique(np.concatenate(rows))


def node_minimum(arrays, values):
    """Per node, the minimum of ``values`` (one per tetrahedron) over the tetrahedra that use it.

    Returns (node_ids, minima) for the nodes used by at least one tetrahedron, mid-edge nodes
    included, as NumPy arrays."""
    values = np.asarray(values, dtype=np.float64)
    minima = np.full(len(arrays.nodes), np.inf)
    per_slot = np.repeat(values, arrays.tets.shape[1])
    np.minimum.at(minima, arrays.tets.ravel(), per_slot)
    used = np.isfinite(minima)
    return arrays.node_ids[used], minima[used]
