"""Size control on the BisectMesh mesh object, headless: MinSize, MaxSize, CurvatureElements and
ChordDeviation reach the mesher (measured on the mesh: the count and the hole's edge lengths),
their bad values are one line naming the object, a change marks the mesh as needing a re-mesh,
UseResolutionHints is off for a new object and, when on, makes the view resolution an input; and
a document saved before these properties existed restores with them, its mesh still current."""

import os
import shutil
import tempfile
import unittest

import FreeCAD

import bisectmesh
from bisectmesh import mesh_object, preferences

import fc_helpers
from test_mesh_regions import face_named, mean_edge_length

NEW_PROPERTIES = ("MinSize", "MaxSize", "CurvatureElements", "ChordDeviation", "MeshRegionList")


class SizeControlTest(unittest.TestCase):
    def setUp(self):
        self.doc = FreeCAD.newDocument("SizeControlTest")
        self.part = fc_helpers.box_minus_cylinder(self.doc)
        self.hole = face_named(self.part.Shape, "Cylinder")[1]

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)

    def make(self, **kwargs):
        kwargs.setdefault("elements", 1500)
        kwargs.setdefault("order", 1)
        for name, value in (("curvature_elements", 12), ("optimize", 3), ("smooth", 3)):
            kwargs.setdefault(name, value)  # whatever the user's BisectMesh preferences hold
        return bisectmesh.make_mesh_object(self.doc, self.part, **kwargs)

    def test_defaults(self):
        obj = bisectmesh.make_mesh_object(self.doc, self.part)
        self.assertEqual((obj.MinSize.Value, obj.MaxSize.Value, obj.ChordDeviation.Value), (0.0, 0.0, 0.0))
        self.assertEqual(obj.CurvatureElements, preferences.read("CurvatureElements"))  # 12 when unset
        obj.CurvatureElements = 12
        self.assertEqual(obj.MeshRegionList, [])
        self.assertFalse(obj.UseResolutionHints)  # the resolution hints are asked for, not implied
        for name in NEW_PROPERTIES + ("UseResolutionHints",):
            self.assertEqual(obj.getGroupOfProperty(name), "BisectMesh")
            self.assertTrue(obj.getDocumentationOfProperty(name))
        args = mesh_object.mesh_arguments(obj)
        self.assertEqual((args["min_size"], args["max_size"], args["curvature_elements"], args["chord_deviation"],
                          args["regions"]), (0.0, 0.0, 12, 0.0, []))

    def test_max_size_and_min_size_reach_the_mesher(self):
        obj = self.make(elements=300)
        bisectmesh.remesh(obj)
        coarse = obj.ElementCount
        obj.MaxSize = 1.2
        self.doc.recompute()
        self.assertTrue(obj.NeedsRemesh)
        bisectmesh.remesh(obj)
        capped = obj.ElementCount
        # a size of at most 1.2 mm in 1717 mm^3 needs about 1717 / (0.1179 * 1.2^3) = 8,400 tetrahedra
        print("300 asked: %d tetrahedra; with MaxSize 1.2 mm: %d" % (coarse, capped))
        self.assertGreater(capped, 3 * coarse)
        obj.MaxSize = 0
        obj.TargetElements = 20000
        obj.MinSize = 2.0
        bisectmesh.remesh(obj)
        floored = obj.ElementCount
        print("20000 asked with MinSize 2 mm: %d tetrahedra" % floored)
        self.assertLess(floored, 20000 / 3)
        self.assertTrue(bisectmesh.quality(obj.FemMesh)["valid"])

    def test_curvature_and_chord_deviation_refine_the_hole(self):
        obj = self.make(elements=800, curvature_elements=0)
        bisectmesh.remesh(obj)
        loose, _ = mean_edge_length(obj.FemMesh, self.hole)
        obj.CurvatureElements = 64
        self.doc.recompute()
        self.assertTrue(obj.NeedsRemesh)
        bisectmesh.remesh(obj)
        curved, _ = mean_edge_length(obj.FemMesh, self.hole)
        # 64 elements per turn of a radius-3 circle: chords of 2 pi 3 / 64 = 0.29 mm around it
        obj.CurvatureElements = 0
        obj.ChordDeviation = 0.005
        bisectmesh.remesh(obj)
        chord, _ = mean_edge_length(obj.FemMesh, self.hole)
        print("hole's mean edge: %.3f mm with no curvature bound, %.3f at 64 per circle, %.3f at a "
              "chord deviation of 0.005 mm" % (loose, curved, chord))
        self.assertLess(curved, 0.6 * loose)
        self.assertLess(chord, 0.6 * loose)

    def test_bad_values_are_one_line(self):
        obj = self.make()
        bisectmesh.remesh(obj)

        def says(*words):
            self.doc.recompute()
            self.assertTrue(obj.isValid(), obj.getStatusString())
            self.assertTrue(obj.NeedsRemesh)
            self.assertNotIn("\n", obj.MeshStatus)
            for word in (obj.Label,) + words:
                self.assertIn(word, obj.MeshStatus)
            with self.assertRaisesRegex(ValueError, words[0]):
                bisectmesh.remesh(obj)

        obj.MinSize, obj.MaxSize = 3.0, 2.0
        says("MinSize", "MaxSize")
        obj.MinSize = obj.MaxSize = 0
        obj.CurvatureElements = 2
        says("CurvatureElements")
        obj.CurvatureElements = -1
        says("CurvatureElements")
        obj.CurvatureElements = 12
        self.doc.recompute()
        self.assertFalse(obj.NeedsRemesh)
        with self.assertRaisesRegex(ValueError, "min_size"):
            self.make(min_size=3.0, max_size=1.0)
        with self.assertRaisesRegex(ValueError, "curvature_elements"):
            self.make(curvature_elements=2)
        with self.assertRaises(TypeError):
            self.make(max_size="1 mm")

    def test_resolution_hints_are_an_input_only_when_on(self):
        obj = self.make()
        bisectmesh.remesh(obj)
        prefs = FreeCAD.ParamGet("User parameter:BaseApp/Preferences/Mod/Part")
        old = prefs.GetFloat("MeshDeviation", 0.5)
        try:
            prefs.SetFloat("MeshDeviation", old / 4)
            obj.touch()
            self.doc.recompute()
            self.assertFalse(obj.NeedsRemesh)  # off: the view resolution is not an input
            obj.UseResolutionHints = True
            bisectmesh.remesh(obj)
            prefs.SetFloat("MeshDeviation", old)
            # headless, check_inputs is what the GUI's view watch runs on a change of Deviation
            self.assertFalse(mesh_object.check_inputs(obj, reason="view changed"))
            self.assertEqual(obj.MeshStatus, "view changed")
        finally:
            prefs.SetFloat("MeshDeviation", old)

    def test_a_document_of_the_version_before_restores(self):
        obj = self.make(elements=1200, use_hints=True)
        bisectmesh.remesh(obj)
        key = obj.MeshedInputs
        for name in NEW_PROPERTIES:  # as the version before saved it
            obj.removeProperty(name)
        self.assertNotIn("MinSize", obj.PropertiesList)
        name = obj.Name
        folder = tempfile.mkdtemp(prefix="bisectmesh-")
        try:
            path = os.path.join(folder, "before.FCStd")
            self.doc.saveAs(path)
            FreeCAD.closeDocument(self.doc.Name)
            self.doc = FreeCAD.openDocument(path)
            obj = self.doc.getObject(name)
            for prop in NEW_PROPERTIES:
                self.assertIn(prop, obj.PropertiesList)
            self.assertEqual(obj.CurvatureElements, 12)  # what that version meshed with
            self.assertEqual(obj.MeshedInputs, key)
            self.assertTrue(obj.UseResolutionHints)  # kept as saved
            obj.touch()
            self.doc.recompute()
            self.assertTrue(obj.isValid(), obj.getStatusString())
            self.assertFalse(obj.NeedsRemesh, obj.MeshStatus)  # the same inputs: the mesh is current
            obj.MaxSize = 1.5
            self.doc.recompute()
            self.assertTrue(obj.NeedsRemesh)
        finally:
            shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    unittest.main()
