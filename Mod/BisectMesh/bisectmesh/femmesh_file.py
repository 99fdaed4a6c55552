"""A ``Fem.FemMesh`` built by FreeCAD's own VTK reader from a binary ``.vtu`` file.

FreeCAD 0.20's ``FemMesh`` has no call that adds many nodes or elements at once: one
``addNode``/``addVolume``/``addFace`` call each cost lug at 10^5 tetra10 0.72 s (groups
included). ``FemMesh.read`` of an XML ``.vtu`` builds the mesh in C++ (VTK's reader, then one
SMESH call per item): with the arrays written in raw binary (NumPy's bytes, no text), writing and
reading took 0.34 s for the same mesh (0.19 s against 0.33 s at order 1). An ASCII ``.vtu`` read
slower than the calls (0.34 s for VTK's parsing alone at order 1), and so did a ``.unv``.

FreeCAD 0.20 hands the VTK cell's node ids to SMESH as they are, so the rows are written in
FreeCAD's own node order (``femmesh_arrays``' permutation applied), and item ids are the file's
order from 1 (nodes, then cells). A FreeCAD that reorders them (later versions map VTK's order to
SMESH's) is caught by :func:`as_written`, and :func:`read_femmesh` then returns None: the caller
adds the items one call each instead.

The read holds Python's GIL for its whole time (measured: a ticking thread waited 0.47 s
through a 0.47 s read), so it suits the main thread, where no window waits on it; the mesh
panel's worker keeps the sliced calls that let the window in (``shape_mesher``).
"""

import os
import tempfile

import numpy as np

# VTK cell types (vtkCellType.h)
VTK_TRIANGLE, VTK_TETRA, VTK_QUADRATIC_TRIANGLE, VTK_QUADRATIC_TETRA = 5, 10, 22, 24
_CELL_TYPES = {(3, 2): VTK_TRIANGLE, (4, 3): VTK_TETRA, (6, 2): VTK_QUADRATIC_TRIANGLE, (10, 3): VTK_QUADRATIC_TETRA}


def vtu_chunks(nodes, blocks):
    """The bytes of a binary (appended, raw) VTK XML unstructured grid, as a list of chunks.

    nodes    #N by 3 floats
    blocks   [(rows, dimension)]: #M by k int arrays of 0-based node rows, k in (3, 6) with
             dimension 2 (triangles) or k in (4, 10) with dimension 3 (tetrahedra); the cells
             follow in this order
    """
    rows = [np.ascontiguousarray(r, dtype="<i8") for r, _ in blocks]
    types = [np.full(len(r), _CELL_TYPES[(r.shape[1], dim)], dtype=np.uint8) for r, (_, dim) in zip(rows, blocks)]
    sizes = np.concatenate([np.full(len(r), r.shape[1], dtype="<i8") for r in rows]) if rows else np.zeros(0, "<i8")
    arrays = (np.ascontiguousarray(nodes, dtype="<f8").reshape(-1, 3),
              np.concatenate([r.ravel() for r in rows]) if rows else np.zeros(0, "<i8"),
              np.cumsum(sizes, dtype="<i8"),
              np.concatenate(types) if types else np.zeros(0, np.uint8))
    chunks, offsets, position = [], [], 0
    for array in arrays:
        data = array.tobytes()
        offsets.append(position)
        chunks += [np.uint64(len(data)).tobytes(), data]  # header_type UInt64: each array's byte count first
        position += 8 + len(data)
    head = ('<?xml version="1.0"?>\n'
            '<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian" header_type="UInt64">\n'
            '<UnstructuredGrid><Piece NumberOfPoints="%d" NumberOfCells="%d">\n'
            '<Points><DataArray type="Float64" NumberOfComponents="3" format="appended" offset="%d"/></Points>\n'
            '<Cells><DataArray type="Int64" Name="connectivity" format="appended" offset="%d"/>\n'
            '<DataArray type="Int64" Name="offsets" format="appended" offset="%d"/>\n'
            '<DataArray type="UInt8" Name="types" format="appended" offset="%d"/></Cells>\n'
            '</Piece></UnstructuredGrid>\n<AppendedData encoding="raw">\n_'
            % (len(arrays[0]), len(arrays[3]), *offsets))
    return [head.encode("ascii")] + chunks + [b"\n</AppendedData>\n</VTKFile>\n"]


def read_femmesh(nodes, blocks):
    """A ``Fem.FemMesh`` of ``nodes`` and the cells of ``blocks`` (as :func:`vtu_chunks` takes
    them, rows in FreeCAD's node order), node ids 1..N and element ids 1..M in the blocks' order;
    or None when the file cannot be written (a full or read-only temporary folder), FreeCAD
    cannot read it, or it read something else than was written (counts, or the first and last
    cells' nodes)."""
    import Fem

    try:
        handle, path = tempfile.mkstemp(prefix="bisectmesh-", suffix=".vtu")
    except OSError:
        return None
    try:
        try:
            with os.fdopen(handle, "wb") as stream:
                for chunk in vtu_chunks(nodes, blocks):
                    stream.write(chunk)
        except OSError:
            return None
        mesh = Fem.FemMesh()
        try:
            mesh.read(path)
        except Exception:  # FreeCAD's own error types (Base.FreeCADError) derive from Exception
            return None  # the caller adds the items one call each: a mesh either way
    finally:
        try:
            os.unlink(path)
        except OSError:
            pass
    return mesh if as_written(mesh, len(nodes), blocks) else None


def as_written(mesh, node_count, blocks):
    """Whether ``mesh`` holds what the blocks say: the node count, the counts of faces and
    volumes, and the node ids of each block's first and last cell."""
    if mesh.NodeCount != node_count:
        return False
    counts = {2: 0, 3: 0}
    for rows, dim in blocks:
        counts[dim] += len(rows)
    if mesh.FaceCount != counts[2] or mesh.VolumeCount != counts[3]:
        return False
    first = 1
    for rows, _ in blocks:
        for i in (0, len(rows) - 1) if len(rows) else ():
            if tuple(mesh.getElementNodes(first + i)) != tuple(int(n) + 1 for n in rows[i]):
                return False
        first += len(rows)
    return True
