"""Meshes written by bisectmesh._core.write_mesh and read back by FreeCAD's Fem.read: the .unv
that the workbench hands to FreeCAD, checked against the same mesh written as .inp."""

import os
import shutil
import tempfile
import unittest

import numpy as np

import FreeCAD
import Fem

import bisectmesh
from bisectmesh import femmesh_arrays

import fc_helpers


def element_corner_coordinates(femmesh):
    """Per volume, sorted by element id: the coordinates of its nodes in FreeCAD's order."""
    nodes = femmesh.Nodes
    return np.array([[tuple(nodes[n]) for n in femmesh.getElementNodes(vid)]
                     for vid in sorted(femmesh.Volumes)], dtype=np.float64)


EDGES = ((0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3))


def element_signatures(tets):
    """Per element: its corners as a set and, at order 2, which mid-node sits on which edge.
    Equal signatures mean the same element whichever corner a file format lists first."""
    signatures = []
    for t in np.asarray(tets).tolist():
        mids = tuple(sorted((min(t[a], t[b]), max(t[a], t[b]), t[4 + k]) for k, (a, b) in enumerate(EDGES))) \
            if len(t) == 10 else ()
        signatures.append((tuple(sorted(t[:4])), mids))
    return signatures


def sorted_rows(points):
    points = np.asarray(points)
    return points[np.lexsort(points.T[::-1])]


def match_rows(points, reference):
    """For each row of ``points``, the row of ``reference`` with the same coordinates."""
    order_p = np.lexsort(points.T[::-1])
    order_r = np.lexsort(reference.T[::-1])
    np.testing.assert_allclose(points[order_p], reference[order_r], rtol=0,
                               atol=1e-12 * float(np.abs(reference).max()))
    rows = np.empty(len(points), dtype=np.int64)
    rows[order_p] = order_r
    return rows


class MeshFileExchangeTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        cls.doc = FreeCAD.newDocument("BisectMeshFilesTest")
        part = fc_helpers.box_minus_cylinder(cls.doc)
        cls.arrays = {order: femmesh_arrays.femmesh_to_arrays(fc_helpers.gmsh_mesh(cls.doc, part, order))
                      for order in (1, 2)}
        cls.tmp = tempfile.mkdtemp(prefix="bisectmesh-files-")

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.doc.Name)
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def write_and_read(self, order, extension):
        arrays = self.arrays[order]
        path = os.path.join(self.tmp, "order%d.%s" % (order, extension))
        bisectmesh.core().write_mesh(path, arrays.nodes, arrays.tets)
        self.assertTrue(os.path.getsize(path) > 0)
        return Fem.read(path)

    def check_order(self, order):
        arrays = self.arrays[order]
        scale = float(np.abs(arrays.nodes).max())
        unv = self.write_and_read(order, "unv")
        inp = self.write_and_read(order, "inp")

        for name, femmesh in (("unv", unv), ("inp", inp)):
            self.assertEqual(femmesh.NodeCount, len(arrays.nodes), name)
            self.assertEqual(femmesh.VolumeCount, len(arrays.tets), name)
            self.assertEqual(femmesh.TetraCount, len(arrays.tets), name)
            read_nodes = np.array([tuple(v) for v in femmesh.Nodes.values()])
            np.testing.assert_allclose(sorted_rows(read_nodes), sorted_rows(arrays.nodes),
                                       rtol=0, atol=1e-12 * scale, err_msg=name)
            # Read back in FreeCAD's convention and converted again, every element is the
            # original one (FreeCAD's readers may start it at another corner), with its mid-nodes
            # on the same edges, positively oriented and valid.
            again = femmesh_arrays.femmesh_to_arrays(femmesh)
            self.assertEqual(again.tets.shape, arrays.tets.shape, name)
            row_of_node = match_rows(again.nodes, arrays.nodes)
            read_tets = row_of_node[again.tets[np.argsort(again.tet_ids)]]
            self.assertEqual(element_signatures(read_tets), element_signatures(arrays.tets), name)
            p = again.nodes[again.tets[:, :4]]
            volume = np.einsum("ij,ij->i", p[:, 1] - p[:, 0], np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 0]))
            self.assertTrue(np.all(volume > 0), name)
            report = bisectmesh.quality(femmesh)
            self.assertIs(report["valid"], True, "%s: %s" % (name, report["violations"][:5]))

        # The two files give FreeCAD the same elements, element by element.
        np.testing.assert_allclose(element_corner_coordinates(unv), element_corner_coordinates(inp),
                                   rtol=0, atol=1e-12 * scale)

    def test_first_order_unv_and_inp(self):
        self.check_order(1)

    def test_second_order_unv_and_inp(self):
        self.check_order(2)

    def test_read_mesh_round_trip(self):
        arrays = self.arrays[2]
        for extension in ("vtu", "msh", "inp"):
            path = os.path.join(self.tmp, "round_trip.%s" % extension)
            bisectmesh.core().write_mesh(path, arrays.nodes, arrays.tets)
            back = bisectmesh.core().read_mesh(path)
            self.assertEqual(back["order"], 2, extension)
            np.testing.assert_allclose(back["nodes"][back["tets"]], arrays.nodes[arrays.tets],
                                       rtol=0, atol=1e-12, err_msg=extension)


if __name__ == "__main__":
    unittest.main()
