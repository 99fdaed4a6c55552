"""A shape made from a mesh (Part's shape from mesh of a box's triangles, made into a solid):
``mesh_shape`` reports its coplanar triangle faces (stats coplanar_triangles, coplanar_hint naming
the first pair and Part's refine); the refined shape has none, and meets the quality bars that
its triangles' acute corners keep the unrefined one from (domain/mesh_like_faces.hpp)."""

import unittest

import Mesh
import Part

from bisectmesh import shape_mesher


def shape_from_mesh(mesh):
    shape = Part.Shape()
    shape.makeShapeFromMesh(mesh.Topology, 0.01)
    return Part.makeSolid(Part.makeShell(shape.Faces))


class MeshLikeShapeTest(unittest.TestCase):
    def setUp(self):
        # a 100 x 10 x 10 bar: 6 sides, 2 triangles each, the long sides' triangles with
        # corners of 5.7 degrees
        self.solid = shape_from_mesh(Mesh.createBox(100, 10, 10))

    def test_coplanar_triangles_are_named_with_the_remedy(self):
        self.assertEqual(len(self.solid.Faces), 12)
        report = {}
        mesh = shape_mesher.mesh_shape(self.solid, elements=300, order=2, report=report)
        stats = report["stats"]
        self.assertEqual(stats["coplanar_triangles"], 12)
        hint = stats["coplanar_hint"]
        self.assertRegex(hint, r"^Face\d+ and Face\d+ \(and 10 more triangles\) lie in one plane")
        self.assertIn("removeSplitter", hint)
        # the mesh object's summary (the task panel's text) carries it too
        from bisectmesh import mesh_object
        result = mesh_object.result_of(mesh, report, 1.0, 2)
        self.assertEqual(result["note"], hint)
        self.assertIn("note: " + hint, mesh_object.summary(result))

    def test_the_refined_shape_has_none_and_good_elements(self):
        refined = self.solid.removeSplitter()
        self.assertEqual(len(refined.Faces), 6)
        report = {}
        shape_mesher.mesh_shape(refined, elements=300, order=2, report=report)
        stats = report["stats"]
        self.assertEqual(stats["coplanar_triangles"], 0)
        self.assertEqual(stats["coplanar_hint"], "")
        self.assertGreaterEqual(stats["quality"]["dihedral_min"], 10.0)
        self.assertGreaterEqual(stats["quality"]["alpha_mean"], 0.20)

    def test_a_face_split_in_two_is_no_mesh(self):
        # a box whose top is two triangles in one plane, as a user splits a face for a load:
        # below the 4 reported
        box = Part.makeBox(20, 10, 10)
        top = [f for f in box.Faces if abs(f.CenterOfMass.z - 10) < 1e-9][0]
        a, b, c, d = (v.Point for v in top.OuterWire.OrderedVertexes)
        halves = [Part.Face(Part.makePolygon([a, b, c, a])), Part.Face(Part.makePolygon([a, c, d, a]))]
        solid = Part.makeSolid(Part.makeShell([f for f in box.Faces if not f.isSame(top)] + halves))
        self.assertTrue(solid.isValid())
        self.assertEqual(len(solid.Faces), 7)
        report = {}
        shape_mesher.mesh_shape(solid, elements=300, order=1, report=report)
        self.assertEqual(report["stats"]["coplanar_triangles"], 2)
        self.assertEqual(report["stats"]["coplanar_hint"], "")


if __name__ == "__main__":
    unittest.main()
