"""Colouring a FEM mesh in the 3D view by element quality.

FreeCAD 0.20.2's ``ViewProviderFemMesh`` offers two colourings: per node (``NodeColor``,
``setNodeColorByScalars``, reset by ``resetNodeColor``) and per element (``ElementColor``). Tried
on Gmsh-made tetrahedral meshes, the per-element one left about a third of the boundary
triangles unassigned (drawn in its fallback colour, bright green, whatever colours are given):
its triangle-to-element table has empty slots. The per-node colouring covers every triangle,
so we colour nodes, each with the worst quality among the tetrahedra that use it; a poor
element then shows as a red patch around its nodes.

Setting ``NodeColor`` takes time quadratic in the nodes in FreeCAD 0.20 (PyCXX's dict iteration
rebuilds the key list at every step: 58,000 nodes took 33 s, 2e5 tetra10 never finished), so we
colour through ``setNodeColorByScalars``, which reads two lists. It scales its colours to the
data's maximum: we pass a "badness" 1 - q on a fixed scale and pin the maximum at 1 with node id 0,
which FreeCAD never draws (its node ids start at 1). Its colours run green (0) through yellow
(0.5) to red (1); :func:`ramp` gives the same for the legend and the histograms. Only the nodes
of the boundary surface are passed: the view draws no other.

The colour computation is plain NumPy and runs headless (or in a worker thread: see
:func:`colour_values`); only :func:`apply_colours`, :func:`colour_by_quality` and
:func:`reset_colours` touch a view provider.
"""

import math

import numpy as np

# Each measure on a fixed 0..1 scale where 1 is the regular tetrahedron's value and 0 is
# degenerate: (label, value of the regular tetrahedron, larger is better).
_REGULAR_DIHEDRAL = math.degrees(math.acos(1.0 / 3.0))
_REGULAR_SOLID_ANGLE = math.acos(23.0 / 27.0)
SCALES = {
    "gamma": ("goodness \u03b3", 1.0, True),
    "dihedral_min": ("minimum dihedral angle", _REGULAR_DIHEDRAL, True),
    "alpha": ("radius ratio \u03b1", 1.0 / 3.0, True),
    "solid_angle_min": ("minimum solid angle", _REGULAR_SOLID_ANGLE, True),
    "dihedral_max": ("maximum dihedral angle", _REGULAR_DIHEDRAL, False),
}


def normalized(measure, values):
    """Quality on 0 (degenerate) .. 1 (regular), clipped."""
    if measure not in SCALES:
        raise ValueError("unknown measure %r; one of %s" % (measure, ", ".join(sorted(SCALES))))
    _, regular, larger_is_better = SCALES[measure]
    values = np.asarray(values, dtype=np.float64)
    if larger_is_better:
        q = values / regular
    else:
        q = (180.0 - values) / (180.0 - regular)
    return np.clip(np.nan_to_num(q, nan=0.0), 0.0, 1.0)


def ramp(q):
    """Colours for qualities 0..1: red (poor) through yellow to green (good); #q by 3 floats.
    The colours FreeCAD's setNodeColorByScalars gives a badness 1 - q on a 0..1 scale."""
    q = np.clip(np.asarray(q, dtype=np.float64), 0.0, 1.0)
    red = np.where(q < 0.5, 1.0, 2.0 * (1.0 - q))
    green = np.where(q < 0.5, 2.0 * q, 1.0)
    blue = np.zeros_like(q)
    return np.stack([red, green, blue], axis=-1)


def legend_rgb(width, height):
    """The colour bar, poor (left) to good (right), as a height x width x 3 uint8 array."""
    row = np.round(255 * ramp(np.linspace(0.0, 1.0, width))).astype(np.uint8)
    return np.ascontiguousarray(np.broadcast_to(row, (height, width, 3)))


def node_quality(arrays, element_values, measure, surface_only=False):
    """(FreeCAD node ids, quality 0..1): each node takes the worst quality of the tetrahedra that
    use it (mid-edge nodes included). surface_only: the nodes of the boundary surface alone."""
    from ..femmesh_arrays import boundary_nodes, node_minimum

    q = normalized(measure, element_values)
    node_ids, worst = node_minimum(arrays, q)
    if surface_only:
        keep = np.isin(node_ids, arrays.node_ids[boundary_nodes(arrays)], assume_unique=True)
        node_ids, worst = node_ids[keep], worst[keep]
    return node_ids, worst


def node_colours(arrays, element_values, measure, surface_only=False):
    """{FreeCAD node id: (r, g, b)} of :func:`node_quality` through :func:`ramp`."""
    node_ids, worst = node_quality(arrays, element_values, measure, surface_only)
    colours = ramp(worst)
    return {int(i): tuple(float(c) for c in rgb) for i, rgb in zip(node_ids, colours)}


def colour_values(mesh, measure="gamma"):
    """What :func:`apply_colours` draws for ``mesh`` (a FEM mesh object or its MeshArrays):
    (node ids, badness) as lists, boundary nodes only. No view provider is touched: this may run
    in a worker thread."""
    import bisectmesh

    arrays = bisectmesh.mesh_arrays(mesh)
    if len(arrays.tets) == 0:
        raise ValueError("%s has no tetrahedra to colour" % getattr(mesh, "Label", "the mesh"))
    _, measures = bisectmesh.element_quality(None, arrays)
    node_ids, worst = node_quality(arrays, measures[measure], measure, surface_only=True)
    return node_ids.tolist(), (1.0 - worst).tolist()


def apply_colours(obj, node_ids, badness):
    """Colours ``obj``'s nodes in the 3D view (see the module's docstring); returns the count."""
    obj.ViewObject.setNodeColorByScalars(list(node_ids) + [0], list(badness) + [1.0])
    return len(node_ids)


def worst_element_nodes(arrays, element_values, measure, threshold):
    """FreeCAD ids of the nodes of elements whose ``measure`` is worse than ``threshold``
    (in the measure's own unit), for HighlightedNodes."""
    _, _, larger_is_better = SCALES[measure]
    values = np.asarray(element_values, dtype=np.float64)
    bad = values < threshold if larger_is_better else values > threshold
    rows = np.unique(arrays.tets[bad].ravel())
    return [int(i) for i in arrays.node_ids[rows]]


def poor_element_nodes(mesh, measure="dihedral_min", threshold=10.0):
    """:func:`worst_element_nodes` of ``mesh`` (a FEM mesh object, FemMesh or MeshArrays); touches
    no view provider (may run in a worker thread)."""
    import bisectmesh

    arrays = bisectmesh.mesh_arrays(mesh)
    _, measures = bisectmesh.element_quality(None, arrays)
    return worst_element_nodes(arrays, measures[measure], measure, threshold)


def apply_marks(obj, nodes):
    """Shows ``nodes`` (FreeCAD ids) as highlighted points, or none; returns the count."""
    if nodes:
        obj.ViewObject.HighlightedNodes = nodes
    else:
        obj.ViewObject.resetHighlightedNodes()
    return len(nodes)


def colour_by_quality(obj, measure="gamma"):
    """Colours the FEM mesh object ``obj`` in the 3D view by ``measure`` (see SCALES), blocking.
    Returns the number of nodes coloured (those of the boundary surface)."""
    return apply_colours(obj, *colour_values(obj, measure))


def mark_poor_elements(obj, measure="dihedral_min", threshold=10.0):
    """Shows the nodes of the elements worse than ``threshold`` as highlighted points, so that
    poor elements inside the mesh can be seen too. Returns the number of nodes marked."""
    return apply_marks(obj, poor_element_nodes(obj, measure, threshold))


def reset_colours(obj):
    """Back to the mesh's own colour, without marked nodes."""
    obj.ViewObject.resetNodeColor()
    obj.ViewObject.resetHighlightedNodes()
