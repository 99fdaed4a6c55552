"""FreeCAD's FEM mesh regions on a BisectMesh mesh object (bisectmesh/mesh_regions.py), headless:
a region made by ObjectsFem.makeMeshRegion(doc, mesh_obj) on the hole of a box gives smaller
elements on that face than elsewhere (edge lengths measured on the FemMesh through FreeCAD's own
getFacesByFace); a change of a region, of its references or of the list marks the mesh as
needing a re-mesh; references are mapped by name on the Part, and a reference to another object
or to a sub-shape the Part lacks is refused in one line naming the region."""

import unittest

import numpy as np

import FreeCAD
import ObjectsFem
import Part

import bisectmesh
from bisectmesh import mesh_object, mesh_regions

import fc_helpers


def face_named(shape, surface):
    """(name, face) of the first face of ``shape`` whose surface is a ``surface`` (a class name)."""
    for k, face in enumerate(shape.Faces):
        if type(face.Surface).__name__ == surface:
            return "Face%d" % (k + 1), face
    raise AssertionError("no %s face" % surface)


def mean_edge_length(femmesh, face):
    """Mean length of the edges of the mesh's boundary triangles on the B-rep ``face`` (corner
    nodes only), found by FreeCAD's FemMesh.getFacesByFace."""
    nodes = femmesh.Nodes
    lengths = []
    for element in femmesh.getFacesByFace(face):
        corners = [np.array(tuple(nodes[n])) for n in femmesh.getElementNodes(element)[:3]]
        lengths.extend(np.linalg.norm(corners[i] - corners[(i + 1) % 3]) for i in range(3))
    if not lengths:
        raise AssertionError("no mesh triangles on the face")
    return float(np.mean(lengths)), len(lengths) // 3


class MeshRegionTest(unittest.TestCase):
    SIZE = 2.0    # the mesh's element size
    REGION = 0.5  # the region's, on the hole

    def setUp(self):
        self.doc = FreeCAD.newDocument("MeshRegionTest")
        self.part = fc_helpers.box_minus_cylinder(self.doc)
        self.hole_name, self.hole = face_named(self.part.Shape, "Cylinder")
        # explicit values, whatever the user's BisectMesh preferences hold
        self.obj = bisectmesh.make_mesh_object(self.doc, self.part, size=self.SIZE, order=1, curvature_elements=12,
                                               optimize=3, smooth=3)

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)

    def add_region(self, size, names, obj=None):
        region = ObjectsFem.makeMeshRegion(self.doc, self.obj, size, "Region")
        region.References = [(obj or self.part, tuple(names))]
        self.doc.recompute()
        return region

    def test_a_region_makes_smaller_elements_on_its_face(self):
        bisectmesh.remesh(self.obj)
        plain, _ = mean_edge_length(self.obj.FemMesh, self.hole)
        plain_tets = self.obj.ElementCount
        region = self.add_region(self.REGION, [self.hole_name])
        self.assertEqual(self.obj.MeshRegionList, [region])
        self.assertEqual(mesh_regions.regions_of(self.obj),
                         [{"size": self.REGION, "faces": [int(self.hole_name[4:])]}])
        self.assertTrue(self.obj.NeedsRemesh)  # a new region: the mesh is stale
        bisectmesh.remesh(self.obj)
        self.assertFalse(self.obj.NeedsRemesh)
        report = bisectmesh.quality(self.obj.FemMesh)
        self.assertTrue(report["valid"], report["violations"][:3])
        fine, triangles = mean_edge_length(self.obj.FemMesh, self.hole)
        # the faces away from the hole (not the two it pierces, graded towards it): the mesh's size
        others = [mean_edge_length(self.obj.FemMesh, f)[0] for f in self.part.Shape.Faces
                  if f.distToShape(self.hole)[0] > 1.0]
        self.assertEqual(len(others), 4)
        elsewhere = float(np.mean(others))
        print("hole face: mean edge %.3f mm without the region, %.3f mm with it (%d triangles); "
              "other faces %.3f mm; %d -> %d tetrahedra" % (plain, fine, triangles, elsewhere, plain_tets,
                                                            self.obj.ElementCount))
        self.assertLess(fine, 1.5 * self.REGION)
        self.assertLess(fine, 0.5 * plain)
        self.assertGreater(elsewhere, 2.0 * fine)  # graded up from the hole: 2.6 times measured
        self.assertGreater(elsewhere, 0.6 * self.SIZE)
        self.assertGreater(self.obj.ElementCount, plain_tets)

    def test_a_region_change_marks_the_mesh(self):
        region = self.add_region(1.0, [self.hole_name])
        bisectmesh.remesh(self.obj)
        self.doc.recompute()
        self.assertFalse(self.obj.NeedsRemesh)

        def stale_after(change):
            change()
            self.doc.recompute()
            stale = self.obj.NeedsRemesh
            self.assertTrue(self.obj.isValid(), self.obj.getStatusString())
            return stale

        self.assertTrue(stale_after(lambda: setattr(region, "CharacteristicLength", 0.8)))
        self.assertIn("mesh region", self.obj.MeshStatus)
        self.assertFalse(stale_after(lambda: setattr(region, "CharacteristicLength", 1.0)))  # as meshed again
        self.assertTrue(stale_after(lambda: setattr(region, "References", [(self.part, ("Face1",))])))
        self.assertFalse(stale_after(lambda: setattr(region, "References", [(self.part, (self.hole_name,))])))
        self.assertTrue(stale_after(lambda: setattr(self.obj, "MeshRegionList", [])))
        self.assertFalse(stale_after(lambda: setattr(self.obj, "MeshRegionList", [region])))
        # a region that asks for nothing (no size) is left out, as FreeCAD's Gmsh tools do
        self.assertTrue(stale_after(lambda: setattr(region, "CharacteristicLength", 0.0)))
        self.assertEqual(mesh_regions.regions_of(self.obj), [])

    def test_references_map_by_name_and_bad_ones_are_one_line(self):
        shape = self.part.Shape
        region = self.add_region(0.7, ["Face1", "Edge2", "Vertex3", "Solid1", "Edge2"])
        entry = mesh_regions.regions_of(self.obj)[0]
        self.assertEqual(entry, {"size": 0.7, "faces": [1], "edges": [2], "vertices": [3], "solids": [1]})
        region.References = [(self.part, ("",))]  # the whole object: its solids
        self.assertEqual(mesh_regions.regions_of(self.obj)[0]["solids"], list(range(1, len(shape.Solids) + 1)))
        self.assertEqual(mesh_regions.describe([entry]), ["0.7 mm on 1 face, 1 edge, 1 vertex, 1 solid"])

        def refused(*words):
            self.doc.recompute()
            self.assertTrue(self.obj.isValid(), "a recompute error: %s" % self.obj.getStatusString())
            self.assertTrue(self.obj.NeedsRemesh)
            self.assertNotIn("\n", self.obj.MeshStatus)
            for word in (self.obj.Label,) + words:
                self.assertIn(word, self.obj.MeshStatus)
            with self.assertRaisesRegex(ValueError, words[0]):
                bisectmesh.remesh(self.obj)

        region.References = [(self.part, ("Face%d" % (len(shape.Faces) + 1),))]
        refused("Face%d" % (len(shape.Faces) + 1), region.Label, self.part.Label)
        # another object: its Face1 is not the Part's Face1
        other = self.doc.addObject("Part::Feature", "OtherBox")
        other.Shape = Part.makeBox(3, 3, 3)
        region.References = [(other, ("Face1",))]
        refused("OtherBox", region.Label, self.part.Label)
        # something else than a mesh region in the list
        region.References = [(self.part, ("Face1",))]
        self.obj.MeshRegionList = [region, other]
        refused("OtherBox", "not a FEM mesh region")
        self.obj.MeshRegionList = [region]
        # an object whose shape is the very same shape as the Part's: the same names
        twin = self.doc.addObject("Part::Feature", "Twin")
        twin.Shape = self.part.Shape
        if twin.Shape.isSame(self.part.Shape):
            region.References = [(twin, ("Face2",))]
            self.assertEqual(mesh_regions.regions_of(self.obj)[0]["faces"], [2])

    def test_a_body_and_its_tip(self):
        body = self.doc.addObject("PartDesign::Body", "Body")
        box = self.doc.addObject("PartDesign::AdditiveBox", "Box")
        body.addObject(box)
        self.doc.recompute()
        obj = bisectmesh.make_mesh_object(self.doc, body, elements=500, order=1, name="BodyMesh")
        region = ObjectsFem.makeMeshRegion(self.doc, obj, 0.5, "TipRegion")
        region.References = [(box, ("Face2",))]  # what a selection in the 3D view may give
        self.doc.recompute()
        self.assertEqual(mesh_regions.regions_of(obj), [{"size": 0.5, "faces": [2]}])
        body.Placement.Base = FreeCAD.Vector(5, 0, 0)  # now the Tip's Face2 is not where the Body's is
        self.doc.recompute()
        self.assertTrue(obj.NeedsRemesh)
        self.assertIn("TipRegion refers to Box", obj.MeshStatus)

    def test_regions_survive_save_and_reopen(self):
        import os
        import shutil
        import tempfile

        self.add_region(1.0, [self.hole_name])
        bisectmesh.remesh(self.obj)
        name = self.obj.Name
        folder = tempfile.mkdtemp(prefix="bisectmesh-")
        try:
            path = os.path.join(folder, "regions.FCStd")
            self.doc.saveAs(path)
            FreeCAD.closeDocument(self.doc.Name)
            self.doc = FreeCAD.openDocument(path)
            obj = self.doc.getObject(name)
            self.assertEqual(len(obj.MeshRegionList), 1)
            self.assertEqual(mesh_regions.regions_of(obj)[0]["faces"], [int(self.hole_name[4:])])
            obj.touch()
            self.doc.recompute()
            self.assertFalse(obj.NeedsRemesh, obj.MeshStatus)
            self.assertTrue(mesh_object.is_mesh_object(obj))
        finally:
            shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    unittest.main()
