"""bisectmesh.quality on FEM meshes made in FreeCAD: agreement with an independent NumPy
computation, validity and FreeCAD ids, the corner convention, mixed and hand-made meshes."""

import json
import os
import unittest

import numpy as np

import FreeCAD
import Fem

import bisectmesh
from bisectmesh import femmesh_arrays

import fc_helpers

TOLERANCE = 1e-9


def close(a, b):
    return abs(a - b) <= TOLERANCE * max(1.0, abs(b))


class GmshMeshQualityTest(unittest.TestCase):
    """A box minus a cylinder, meshed by FreeCAD's Gmsh mesher at first and second order."""

    @classmethod
    def setUpClass(cls):
        cls.doc = FreeCAD.newDocument("BisectMeshQualityTest")
        cls.part = fc_helpers.box_minus_cylinder(cls.doc)
        cls.meshes = {order: fc_helpers.gmsh_mesh(cls.doc, cls.part, order) for order in (1, 2)}

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.doc.Name)

    def check_against_reference(self, order):
        obj = self.meshes[order]
        report = bisectmesh.quality(obj, per_element=True)
        ids, corners = fc_helpers.fc_elements(obj.FemMesh)
        reference = fc_helpers.reference_measures(corners)

        self.assertEqual(report["tets"], len(ids))
        self.assertEqual(report["order"], order)
        self.assertEqual(report["nodes"], obj.FemMesh.NodeCount)
        self.assertEqual(report["skipped_volumes"], {})

        # Element by element, matched by FreeCAD element id.
        per = report["per_element"]
        row_of = {eid: k for k, eid in enumerate(per["ids"])}
        self.assertEqual(sorted(row_of), sorted(ids.tolist()))
        rows = [row_of[eid] for eid in ids.tolist()]
        for name in bisectmesh.MEASURES:
            got = np.asarray(per[name])[rows]
            np.testing.assert_allclose(got, reference[name], rtol=TOLERANCE, atol=TOLERANCE, err_msg=name)
        # Our volumes are those of the positively oriented elements; FreeCAD's corners are
        # numbered the other way round (see femmesh_arrays), so the signs are opposite.
        np.testing.assert_allclose(np.asarray(per["volume"])[rows], -reference["volume"],
                                   rtol=TOLERANCE, atol=TOLERANCE)

        # Min, mean, max and histograms of the summary.
        for name in bisectmesh.MEASURES:
            stats = report["measures"][name]
            values = reference[name]
            for key, expected in (("min", values.min()), ("mean", values.mean()), ("max", values.max())):
                self.assertTrue(close(stats[key], expected),
                                "%s %s: %r, reference %r" % (name, key, stats[key], expected))
            lo, hi, bins = fc_helpers.HISTOGRAM_RANGES[name]
            self.assertTrue(close(stats["lo"], lo) and close(stats["hi"], hi), name)
            counts = np.asarray(stats["histogram"])
            self.assertEqual(len(counts), bins, name)
            self.assertEqual(int(counts.sum()), len(values), name)
            certain, possible = fc_helpers.histogram_bounds(values, lo, hi, bins)
            self.assertTrue(np.all(certain <= counts) and np.all(counts <= possible),
                            "%s histogram %s, reference %s" % (name, counts.tolist(), certain.tolist()))

        # The --stats keys of ARCHITECTURE.md §3.
        top = {
            "dihedral_min": reference["dihedral_min"].min(),
            "dihedral_max": reference["dihedral_max"].max(),
            "solid_angle_min": reference["solid_angle_min"].min(),
            "solid_angle_mean": reference["solid_angle_min"].mean(),
            "gamma_mean": reference["gamma"].mean(),
            "gamma_min": reference["gamma"].min(),
            "alpha_mean": reference["alpha"].mean(),
            "pct_dihedral_below_10": 100.0 * np.mean(reference["dihedral_min"] < 10.0),
        }
        for key, expected in top.items():
            self.assertTrue(close(report[key], expected), "%s: %r, reference %r" % (key, report[key], expected))
        return report

    def test_first_order_agrees_with_numpy_reference(self):
        report = self.check_against_reference(1)
        self.assertTrue(report["valid"], report["violations"][:5])

    def test_second_order_agrees_with_numpy_reference(self):
        report = self.check_against_reference(2)
        self.assertTrue(report["valid"], report["violations"][:5])

    def test_gmsh_meshes_are_valid(self):
        for order, obj in self.meshes.items():
            report = bisectmesh.quality(obj.FemMesh)
            self.assertIs(report["valid"], True, "order %d: %s" % (order, report["violations"][:5]))
            self.assertEqual(report["violations"], [])
            self.assertGreater(report["gamma_min"], 0.0)

    def test_freecad_corner_convention(self):
        """FreeCAD (SMDS) numbers tetrahedron corners with negative orientation; converted
        arrays are positive, and tetra10 mid-nodes sit on our edges 01 12 02 03 13 23."""
        for order, obj in self.meshes.items():
            _, corners = fc_helpers.fc_elements(obj.FemMesh)
            self.assertTrue(np.all(fc_helpers.reference_measures(corners)["volume"] < 0), order)
            arrays = femmesh_arrays.femmesh_to_arrays(obj)
            p = arrays.nodes[arrays.tets[:, :4]]
            volume = np.einsum("ij,ij->i", p[:, 1] - p[:, 0], np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 0]))
            self.assertTrue(np.all(volume > 0), order)
            if order == 2:
                edges = ((0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3))
                mids = arrays.nodes[arrays.tets[:, 4:]]
                # On the curved boundary mid-nodes leave the straight edge; each must still be
                # nearest to the midpoint of its own edge.
                for slot, _ in enumerate(edges):
                    distances = np.stack([np.linalg.norm(mids[:, slot] - 0.5 * (p[:, a] + p[:, b]), axis=1)
                                          for a, b in edges], axis=1)
                    self.assertTrue(np.all(np.argmin(distances, axis=1) == slot), "mid-node slot %d" % slot)

    def test_report_is_plain_json(self):
        report = bisectmesh.quality(self.meshes[2], per_element=True)
        text = json.dumps(report)
        self.assertEqual(json.loads(text)["tets"], report["tets"])
        for value in (report["gamma_mean"], report["measures"]["gamma"]["histogram"][0]):
            self.assertIn(type(value), (int, float))
        with open(os.path.join(fc_helpers.artifacts_dir(), "quality_gmsh_order2.json"), "w") as out:
            json.dump({k: v for k, v in report.items() if k != "per_element"}, out, indent=1)
        self.assertIn("valid", bisectmesh.format_report(report))

    def test_validate_false_skips_the_validator(self):
        report = bisectmesh.quality(self.meshes[1], validate=False)
        self.assertIsNone(report["valid"])
        self.assertEqual(report["violations"], [])
        self.assertNotIn("per_element", report)

    def test_arrays_round_trip_through_femmesh(self):
        arrays = femmesh_arrays.femmesh_to_arrays(self.meshes[2])
        rebuilt = femmesh_arrays.arrays_to_femmesh(arrays.nodes, arrays.tets, arrays.node_ids, arrays.tet_ids)
        original = self.meshes[2].FemMesh
        for eid in arrays.tet_ids[:50].tolist():
            self.assertEqual(rebuilt.getElementNodes(eid), original.getElementNodes(eid))
        again = femmesh_arrays.femmesh_to_arrays(rebuilt)
        np.testing.assert_array_equal(again.tets, arrays.tets)
        np.testing.assert_array_equal(again.nodes, arrays.nodes)


def copy_by_hand(source, node_offset=1000, element_offset=50000, swap_in=None):
    """A new Fem.FemMesh made with addNode/addVolume from ``source``'s volumes, with shifted
    ids; in element ``swap_in`` (an id of the copy) the first two nodes trade places."""
    femmesh = Fem.FemMesh()
    for nid, point in source.Nodes.items():
        femmesh.addNode(point.x, point.y, point.z, nid + node_offset)
    for vid in source.Volumes:
        element = [n + node_offset for n in source.getElementNodes(vid)]
        if vid + element_offset == swap_in:
            element[0], element[1] = element[1], element[0]
        femmesh.addVolume(element, vid + element_offset)
    return femmesh


class GeneratorArraysTest(unittest.TestCase):
    """The quality of a BisectMesh mesh computed from the generator's own arrays (the panel's
    check and the quality panel never read the FemMesh back): the same report as from the
    FemMesh, a progress that ends at 1 and can stop the check."""

    @classmethod
    def setUpClass(cls):
        from bisectmesh import shape_mesher

        cls.doc = FreeCAD.newDocument("BisectMeshArraysTest")
        cls.part = fc_helpers.box_minus_cylinder(cls.doc)
        cls.report = {}
        cls.mesh = shape_mesher.mesh_shape(cls.part.Shape, elements=6000, order=2, report=cls.report)

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.doc.Name)

    def test_arrays_give_the_femmesh_report(self):
        arrays = self.report["arrays"]
        read = bisectmesh.mesh_arrays(self.mesh)
        np.testing.assert_array_equal(arrays.tets, read.tets)
        np.testing.assert_array_equal(arrays.node_ids, read.node_ids)
        np.testing.assert_array_equal(arrays.tet_ids, read.tet_ids)
        np.testing.assert_allclose(arrays.nodes, read.nodes)
        self.assertEqual(bisectmesh.quality(arrays), bisectmesh.quality(self.mesh))

    def test_progress_ends_at_one_and_stops_the_check(self):
        seen = []
        report = bisectmesh.quality(self.report["arrays"], progress=seen.append)
        self.assertTrue(report["valid"])
        self.assertEqual(seen, sorted(seen))
        self.assertEqual((seen[0], seen[-1]), (0.0, 1.0))
        # Stop inside the validator: its first report past the summary says stop
        with self.assertRaises(bisectmesh.core().Cancelled):
            bisectmesh.quality(self.report["arrays"], progress=lambda x: x <= 0.2)

    def test_boundary_nodes_are_the_surface_triangles_nodes(self):
        arrays = self.report["arrays"]
        faces = [g for g in self.mesh.Groups if self.mesh.getGroupName(g).endswith("_Nodes")]
        on_faces = set()
        for g in faces:
            on_faces.update(self.mesh.getGroupElements(g))
        rows = femmesh_arrays.boundary_nodes(arrays)
        self.assertEqual(set(arrays.node_ids[rows].tolist()), on_faces)

    def test_mesh_part_checks_within_its_progress(self):
        from bisectmesh import mesh_object

        seen, kept = [], {}
        femmesh, result = mesh_object.mesh_part(self.part, elements=3000, order=1, check=True, report=kept,
                                                progress=seen.append)
        self.assertIs(result["quality"]["valid"], True)
        self.assertEqual(result["violations"], [])
        self.assertEqual(seen, sorted(seen))
        self.assertEqual(seen[-1], 1.0)
        self.assertEqual(len(kept["arrays"].tets), femmesh.VolumeCount)
        with self.assertRaises(bisectmesh.core().Cancelled):  # Stop during the check
            mesh_object.mesh_part(self.part, elements=3000, order=1, check=True, progress=lambda x: x < 0.97)


class HandMadeMeshTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        cls.doc = FreeCAD.newDocument("BisectMeshHandMadeTest")
        part = fc_helpers.box_minus_cylinder(cls.doc)
        cls.gmsh = fc_helpers.gmsh_mesh(cls.doc, part, 1, size=4.0).FemMesh

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.doc.Name)

    def test_copy_keeps_freecad_ids_and_is_valid(self):
        femmesh = copy_by_hand(self.gmsh)
        report = bisectmesh.quality(femmesh, per_element=True)
        self.assertIs(report["valid"], True, report["violations"][:5])
        self.assertEqual(sorted(report["per_element"]["ids"]), sorted(femmesh.Volumes))
        self.assertGreaterEqual(min(report["per_element"]["ids"]), 50000)

    def test_swapped_nodes_are_reported_with_the_element_id(self):
        victim = sorted(self.gmsh.Volumes)[len(self.gmsh.Volumes) // 3] + 50000
        femmesh = copy_by_hand(self.gmsh, swap_in=victim)
        report = bisectmesh.quality(femmesh)
        self.assertIs(report["valid"], False)
        inverted = [v for v in report["violations"] if v["kind"] == "inverted_tet"]
        self.assertEqual(len(inverted), 1, report["violations"])
        self.assertEqual(inverted[0]["ids"], [victim])
        self.assertIn(str(victim), inverted[0]["message"])
        self.assertEqual([v["kind"] for v in report["violations"]], ["inverted_tet"])
        # Measures grade the element as its mirror image: the swap changes no statistics.
        plain = bisectmesh.quality(copy_by_hand(self.gmsh), validate=False)
        self.assertTrue(close(report["gamma_mean"], plain["gamma_mean"]))

    def test_single_tetrahedron(self):
        femmesh = Fem.FemMesh()
        for nid, xyz in zip((7, 8, 9, 10), ((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1))):
            femmesh.addNode(float(xyz[0]), float(xyz[1]), float(xyz[2]), nid)
        # In FreeCAD's convention (negative orientation) this element is the right way round.
        femmesh.addVolume([7, 9, 8, 10], 3)
        report = bisectmesh.quality(femmesh, per_element=True)
        self.assertIs(report["valid"], True, report["violations"])
        self.assertTrue(close(report["per_element"]["volume"][0], 1.0 / 6.0))
        self.assertTrue(close(report["dihedral_min"], 54.735610317245346))  # atan(sqrt 2)
        self.assertTrue(close(report["dihedral_max"], 90.0))

        inverted = Fem.FemMesh()
        for nid, point in femmesh.Nodes.items():
            inverted.addNode(point.x, point.y, point.z, nid)
        inverted.addVolume([7, 8, 9, 10], 3)
        report = bisectmesh.quality(inverted)
        self.assertEqual([(v["kind"], v["ids"]) for v in report["violations"]], [("inverted_tet", [3])])

    def test_mixed_mesh_skips_other_volumes(self):
        femmesh = Fem.FemMesh()
        corners = [(x, y, z) for z in (0.0, 1.0) for y in (0.0, 1.0) for x in (0.0, 1.0)]
        for k, (x, y, z) in enumerate(corners):
            femmesh.addNode(x, y, z, k + 1)
        femmesh.addVolume([1, 2, 4, 3, 5, 6, 8, 7], 1)  # a hexahedron
        femmesh.addNode(3.0, 0.0, 0.0, 11)
        femmesh.addNode(4.0, 0.0, 0.0, 12)
        femmesh.addNode(3.0, 1.0, 0.0, 13)
        femmesh.addNode(3.0, 0.0, 1.0, 14)
        femmesh.addVolume([11, 13, 12, 14], 2)
        report = bisectmesh.quality(femmesh)
        self.assertEqual(report["tets"], 1)
        self.assertEqual(report["skipped_volumes"], {"hexahedron": 1})
        self.assertIs(report["valid"], True, report["violations"])

        only_hexa = Fem.FemMesh()
        for k, (x, y, z) in enumerate(corners):
            only_hexa.addNode(x, y, z, k + 1)
        only_hexa.addVolume([1, 2, 4, 3, 5, 6, 8, 7], 1)
        with self.assertRaises(ValueError) as caught:
            bisectmesh.quality(only_hexa)
        self.assertIn("no tetrahedra", str(caught.exception))
        self.assertIn("hexahedron", str(caught.exception))

    def test_not_a_mesh(self):
        with self.assertRaises(TypeError):
            bisectmesh.quality("mesh.unv")


if __name__ == "__main__":
    unittest.main()
