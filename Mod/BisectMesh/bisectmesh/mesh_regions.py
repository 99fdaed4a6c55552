"""FreeCAD's FEM mesh regions (``Fem::FemMeshRegion``, made by ``ObjectsFem.makeMeshRegion(doc,
mesh_obj)`` or FEM's "FEM mesh region" command) as the ``regions`` argument of
:func:`bisectmesh.shape_mesher.mesh_shape`.

A region is linked to its mesh object through the mesh object's ``MeshRegionList`` (as for
FreeCAD's Gmsh object; the tree shows the regions under the mesh). It has a
``CharacteristicLength`` (the element size asked for) and ``References``, [(object, ("Face3",
"Edge2", ...))]. Each becomes {"size": mm, "faces": [3], "edges": [2], "vertices": [...],
"solids": [...]}, numbered from 1 as FreeCAD names the sub-shapes of the mesh's Part.

A reference must name sub-shapes of the Part's shape: the Part itself, or an object whose shape
is the same shape sub-shape for sub-shape and in the same place (a copy of it; a PartDesign
Body's Tip while the Body has no placement of its own), where the names mean the same
sub-shapes. A reference to any other object is refused with one line naming the region and the
object: its Face3 is not the Part's Face3, and guessing would put the size in the wrong place.
An empty sub-element name means the whole object: all of its solids.

A region with no size (0 mm) or no references asks for nothing and is left out, as FreeCAD's
Gmsh tools do.
"""

REGION_TYPE = "Fem::MeshRegion"
_KINDS = (("Face", "faces", "Faces"), ("Edge", "edges", "Edges"), ("Vertex", "vertices", "Vertexes"),
          ("Solid", "solids", "Solids"))


def is_mesh_region(obj):
    """True for a FEM mesh region (FreeCAD's ``Fem::FeaturePython`` of type Fem::MeshRegion)."""
    return getattr(getattr(obj, "Proxy", None), "Type", None) == REGION_TYPE


def region_objects(mesh_obj):
    """The mesh region objects linked to ``mesh_obj`` (its MeshRegionList), in order."""
    return list(getattr(mesh_obj, "MeshRegionList", None) or [])


def regions_of(mesh_obj, part=None):
    """The ``regions`` argument for meshing ``mesh_obj``'s Part (or ``part``): a list of dicts,
    sorted the same way for the same regions (the list enters the inputs' fingerprint).
    ValueError, one line naming the region, for a reference that cannot be mapped."""
    part = mesh_obj.Part if part is None else part
    regions = []
    for region in region_objects(mesh_obj):
        if not is_mesh_region(region):
            raise ValueError("%s: %s (%s) in MeshRegionList is not a FEM mesh region"
                             % (mesh_obj.Label, region.Label, region.Name))
        entry = region_entry(region, part)
        if entry is not None:
            regions.append(entry)
    return regions


def region_entry(region, part):
    """One region as a dict of mesh_shape's ``regions``, or None when it asks for nothing."""
    size = float(region.CharacteristicLength.Value)
    references = list(region.References or [])
    if size <= 0 or not references:
        return None
    shape = part.Shape
    entry = {"size": size}
    for obj, names in references:
        if obj is None:
            continue
        if obj != part and not _same_shape(obj, shape):
            raise ValueError(
                "mesh region %s refers to %s (%s), not to the meshed Part %s (%s): refer to the "
                "Part's own faces, edges or solids" % (region.Label, obj.Label, obj.Name, part.Label, part.Name))
        if isinstance(names, str):
            names = (names,)
        for name in names:
            if not name:  # the whole object
                _add(entry, "solids", range(1, len(shape.Solids) + 1))
                continue
            kind, key, number = _parse(region, name)
            count = len(getattr(shape, dict((k, a) for k, _, a in _KINDS)[kind]))
            if not 1 <= number <= count:
                raise ValueError("mesh region %s: %s is not in %s, which has %d %s" % (
                    region.Label, name, part.Label, count, key))
            _add(entry, key, (number,))
    if len(entry) == 1:
        return None
    return entry


def _same_shape(obj, shape):
    """True when ``obj``'s shape is ``shape``, or a copy of it sub-shape for sub-shape in the same
    order and place (a PartDesign Body's shape is such a copy of its Tip's), so that its Face3
    is the Part's Face3."""
    from .mesh_object import shape_fingerprint

    other = getattr(obj, "Shape", None)
    if other is None or other.isNull():
        return False
    return other.isSame(shape) or shape_fingerprint(other) == shape_fingerprint(shape)


def _parse(region, name):
    """("Face", "faces", 3) of "Face3"; ValueError naming the region for anything else."""
    for kind, key, _ in _KINDS:
        digits = name[len(kind):]
        if name.startswith(kind) and digits.isdigit():
            return kind, key, int(digits)
    raise ValueError("mesh region %s: %r is not a face, edge, vertex or solid (Face3, Edge2, Vertex1, Solid1)"
                     % (region.Label, name))


def _add(entry, key, numbers):
    entry[key] = sorted(set(entry.get(key, [])) | set(numbers))


def describe(regions):
    """One line per region for the panel and the report view: "0.5 mm on 1 face, 2 edges"."""
    lines = []
    for entry in regions:
        parts = []
        for _, key, _ in _KINDS:
            n = len(entry.get(key, []))
            if n:
                parts.append("%d %s" % (n, key if n > 1 else {"vertices": "vertex"}.get(key, key[:-1])))
        lines.append("%g mm on %s" % (entry["size"], ", ".join(parts)))
    return lines
