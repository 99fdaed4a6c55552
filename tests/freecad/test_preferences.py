"""BisectMesh's preferences (Edit > Preferences > BisectMesh; bisectmesh/preferences.py), headless:
make_mesh_object takes its defaults from them (5000 elements when unset), explicit arguments win,
values a user.cfg edited by hand makes unusable fall back to the built-in ones, and the meshing
takes its thread count from them. The page itself: gui_size_control.py."""

import unittest

import FreeCAD

import bisectmesh
from bisectmesh import mesh_object, preferences, shape_mesher

import fc_helpers


class PreferencesTest(unittest.TestCase):
    def setUp(self):
        self.group = FreeCAD.ParamGet(preferences.PATH)
        self.saved = list(self.group.GetContents() or [])
        self.clear()
        self.doc = FreeCAD.newDocument("PreferencesTest")
        self.part = fc_helpers.box_minus_cylinder(self.doc)

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)
        self.clear()
        setters = {"Integer": "SetInt", "Boolean": "SetBool", "Float": "SetFloat", "String": "SetString",
                   "Unsigned Long": "SetUnsigned"}
        for kind, name, value in self.saved:  # the user's own values, as they were
            getattr(self.group, setters[kind])(name, value)

    def clear(self):
        for kind, name, _ in preferences.BUILT_IN:
            getattr(self.group, "Rem" + kind)(name)

    def test_unset_gives_the_built_in_defaults(self):
        obj = bisectmesh.make_mesh_object(self.doc, self.part)
        self.assertEqual(obj.TargetElements, 5000)
        self.assertEqual(preferences.DEFAULT_ELEMENTS, mesh_object.DEFAULT_ELEMENTS)
        self.assertEqual((obj.ElementOrder, obj.CurvatureElements, obj.OptimizePasses, obj.SmoothPasses),
                         ("2nd", 12, 3, 3))
        self.assertEqual(preferences.read("Threads"), 0)

    def test_make_mesh_object_honours_the_preferences(self):
        preferences.write({"DefaultElements": 1234, "DefaultOrder": 1, "CurvatureElements": 30,
                           "OptimizePasses": 1, "SmoothPasses": 0})
        obj = bisectmesh.make_mesh_object(self.doc, self.part)
        self.assertEqual((obj.TargetElements, obj.ElementOrder, obj.CurvatureElements, obj.OptimizePasses,
                          obj.SmoothPasses), (1234, "1st", 30, 1, 0))
        # by size
        preferences.write({"UseElementSize": True, "DefaultSize": 2.5})
        obj = bisectmesh.make_mesh_object(self.doc, self.part, name="BySize")
        self.assertEqual(obj.TargetElements, 0)
        self.assertAlmostEqual(obj.ElementSize.Value, 2.5)
        # what a macro says wins
        obj = bisectmesh.make_mesh_object(self.doc, self.part, elements=900, order=2, curvature_elements=0,
                                          optimize=2, smooth=2, name="Explicit")
        self.assertEqual((obj.TargetElements, obj.ElementOrder, obj.CurvatureElements, obj.OptimizePasses,
                          obj.SmoothPasses), (900, "2nd", 0, 2, 2))
        # the object keeps its own values once made
        preferences.write({"DefaultOrder": 2})
        self.assertEqual(self.doc.getObject("BisectMesh").ElementOrder, "1st")
        bisectmesh.remesh(obj)
        self.assertGreater(obj.ElementCount, 300)

    def test_unusable_values_fall_back(self):
        self.group.SetInt("DefaultElements", -5)
        self.group.SetInt("DefaultOrder", 3)
        self.group.SetInt("CurvatureElements", 2)
        self.group.SetInt("Threads", -1)
        self.group.SetFloat("DefaultSize", -1.0)
        values = preferences.defaults()
        self.assertEqual((values["DefaultElements"], values["DefaultOrder"], values["CurvatureElements"],
                          values["Threads"], values["DefaultSize"]), (5000, 2, 12, 0, 1.0))
        obj = bisectmesh.make_mesh_object(self.doc, self.part)
        self.assertEqual(obj.TargetElements, 5000)
        with self.assertRaises(KeyError):
            preferences.read("Bogus")
        with self.assertRaises(KeyError):
            preferences.write({"Bogus": 1})

    def test_threads_come_from_the_preferences(self):
        seen = []
        original = shape_mesher.mesh_shape

        def spy(shape, **kwargs):
            seen.append(kwargs["threads"])
            return original(shape, **kwargs)

        shape_mesher.mesh_shape = spy
        try:
            preferences.write({"Threads": 1})
            obj = bisectmesh.make_mesh_object(self.doc, self.part, elements=600, order=1)
            bisectmesh.remesh(obj)
            preferences.write({"Threads": 2})
            mesh_object.mesh_part(self.part, elements=600, order=1)
            mesh_object.mesh_part(self.part, elements=600, order=1, threads=3)
        finally:
            shape_mesher.mesh_shape = original
        self.assertEqual(seen, [1, 2, 3])
        # the thread count is no input of the mesh (the mesh is the same for any count)
        self.doc.recompute()
        self.assertFalse(obj.NeedsRemesh)


if __name__ == "__main__":
    unittest.main()
