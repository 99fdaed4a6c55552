"""Colouring a FEM mesh in the 3D view by element quality.

FreeCAD 0.20.2's ``ViewProviderFemMesh`` offers two colourings: per node (``NodeColor``,
``setNodeColorByScalars``, reset by ``resetNodeColor``) and per element (``ElementColor``). Tried
on Gmsh-made tetrahedral meshes, the per-element one left about a third of the boundary
triangles unassigned (drawn in its fallback colour, bright green, whatever colours are given):
its triangle-to-element table has empty slots. The per-node colouring covers every triangle,
so we colour nodes, each with the worst quality among the tetrahedra that use it; a poor
element then shows as a red patch around its nodes.

``setNodeColorByScalars`` scales its colours to the data's own maximum, so the same colour would
mean different qualities on different meshes; we map qualities to colours ourselves on a fixed
scale and pass them through ``NodeColor``.

The colour computation is plain NumPy and runs headless; only :func:`colour_by_quality` and
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
    """Colours for qualities 0..1: red (poor) through yellow to green (good); #q by 3 floats."""
    q = np.clip(np.asarray(q, dtype=np.float64), 0.0, 1.0)
    red = np.where(q < 0.5, 1.0, 2.0 * (1.0 - q))
    green = np.where(q < 0.5, 2.0 * q, 1.0)
    blue = np.zeros_like(q)
    # A touch of shading keeps the best elements from glaring.
    scale = 0.85 + 0.15 * (1.0 - q)
    return np.stack([red * scale, green * 0.8 * scale, blue], axis=-1)


def node_colours(arrays, element_values, measure):
    """{FreeCAD node id: (r, g, b)} from per-element values of ``measure``, each node taking
    the worst quality of the tetrahedra that use it (mid-edge nodes included)."""
    from ..femmesh_arrays import node_minimum

    q = normalized(measure, element_values)
    node_ids, worst = node_minimum(arrays, q)
    colours = ramp(worst)
    return {int(i): tuple(float(c) for c in rgb) for i, rgb in zip(node_ids, colours)}


def worst_element_nodes(arrays, element_values, measure, threshold):
    """FreeCAD ids of the nodes of elements whose ``measure`` is worse than ``threshold``
    (in the measure's own unit), for HighlightedNodes."""
    _, _, larger_is_better = SCALES[measure]
    values = np.asarray(element_values, dtype=np.float64)
    bad = values < threshold if larger_is_better else values > threshold
    rows = np.unique(arrays.tets[bad].ravel())
    return [int(i) for i in arrays.node_ids[rows]]


def colour_by_quality(obj, measure="gamma"):
    """Colours the FEM mesh object ``obj`` in the 3D view by ``measure`` (see SCALES).
    Returns the number of nodes coloured."""
    import bisectmesh

    arrays = bisectmesh.mesh_arrays(obj)
    if len(arrays.tets) == 0:
        raise ValueError("%s has no tetrahedra to colour" % obj.Label)
    _, measures = bisectmesh.element_quality(obj, arrays)
    colours = node_colours(arrays, measures[measure], measure)
    obj.ViewObject.NodeColor = colours
    return len(colours)


def mark_poor_elements(obj, measure="dihedral_min", threshold=10.0):
    """Shows the nodes of the elements worse than ``threshold`` as highlighted points, so that
    poor elements inside the mesh can be seen too. Returns the number of nodes marked."""
    import bisectmesh

    arrays = bisectmesh.mesh_arrays(obj)
    _, measures = bisectmesh.element_quality(obj, arrays)
    nodes = worst_element_nodes(arrays, measures[measure], measure, threshold)
    if nodes:
        obj.ViewObject.HighlightedNodes = nodes
    else:
        obj.ViewObject.resetHighlightedNodes()
    return len(nodes)


def reset_colours(obj):
    """Back to the mesh's own colour, without marked nodes."""
    obj.ViewObject.resetNodeColor()
    obj.ViewObject.resetHighlightedNodes()
