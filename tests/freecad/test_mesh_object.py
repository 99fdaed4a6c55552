"""The BisectMesh FEM mesh object (bisectmesh.make_mesh_object), headless, as a macro user drives
it: bisectmesh.remesh(obj) meshes the Part, a recompute never meshes but marks the mesh as
needing a re-mesh when the Part or a parameter changes, changing TargetElements and re-meshing
changes the mesh, bad properties are one line naming the object (no recompute error, no
traceback) and mark the mesh, the object joins an analysis, and it survives saving and reopening
the document (properties, FemMesh, the fingerprint of its inputs)."""

import os
import shutil
import tempfile
import time
import unittest

import FreeCAD
import Part

import bisectmesh
from bisectmesh import mesh_object

import fc_helpers


def group_names(femmesh):
    return {femmesh.getGroupName(g) for g in femmesh.Groups}


class MeshObjectTest(unittest.TestCase):
    def setUp(self):
        self.doc = FreeCAD.newDocument("MeshObjectTest")
        self.part = fc_helpers.box_minus_cylinder(self.doc)

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)

    def assert_valid_mesh(self, obj, order):
        self.assertTrue(obj.isValid(), obj.getStatusString())
        femmesh = obj.FemMesh
        self.assertGreater(femmesh.VolumeCount, 100)
        report = bisectmesh.quality(femmesh)
        self.assertTrue(report["valid"], report["violations"][:5])
        self.assertEqual(report["order"], order)
        first = sorted(femmesh.Volumes)[0]
        self.assertEqual(len(femmesh.getElementNodes(first)), 10 if order == 2 else 4)
        self.assertEqual(obj.ElementCount, femmesh.VolumeCount)
        self.assertEqual(obj.NodeCount, femmesh.NodeCount)
        return report

    def test_remesh_gives_a_valid_tetra10_mesh(self):
        obj = bisectmesh.make_mesh_object(self.doc, self.part, elements=3000)
        self.assertEqual(obj.TypeId, "Fem::FemMeshObjectPython")
        self.assertTrue(mesh_object.is_mesh_object(obj))
        self.doc.recompute()
        self.assertEqual(obj.FemMesh.VolumeCount, 0)  # a recompute never meshes ...
        self.assertTrue(obj.NeedsRemesh)              # ... it says the mesh is missing
        self.assertEqual(obj.MeshStatus, "not meshed yet")
        result = bisectmesh.remesh(obj)
        self.assertEqual(result["tets"], obj.FemMesh.VolumeCount)
        self.assertFalse(obj.NeedsRemesh)
        self.assertEqual(obj.MeshStatus, "")
        report = self.assert_valid_mesh(obj, order=2)
        # the mesh fills the solid: tetra10 mid-nodes lie on the cylinder, the corners' facets cut it
        volume = fc_helpers.reference_measures(fc_helpers.fc_elements(obj.FemMesh)[1])["volume"].sum()
        self.assertAlmostEqual(abs(volume), self.part.Shape.Volume, delta=0.01 * self.part.Shape.Volume)
        names = group_names(obj.FemMesh)
        self.assertIn("Solid1", names)
        for k in range(len(self.part.Shape.Faces)):
            self.assertIn("Face%d_Nodes" % (k + 1), names)
        self.assertAlmostEqual(obj.MinDihedralAngle, report["dihedral_min"], places=6)
        self.assertGreater(obj.MeshingTime, 0.0)
        self.assertIn("tetrahedra (order 2)", obj.Summary)
        self.assertIn("total", obj.Summary)
        stored = mesh_object.stored_result(obj)
        self.assertEqual(stored["tets"], obj.FemMesh.VolumeCount)
        self.assertIn("gen_tets", stored["times"])
        # results are outputs: setting them does not ask for another meshing
        self.assertEqual(obj.State, ["Up-to-date"])
        self.doc.recompute()
        self.assertFalse(obj.NeedsRemesh)

    def test_recompute_never_meshes_but_marks_the_mesh(self):
        obj = bisectmesh.make_mesh_object(self.doc, self.part, elements=1500, order=1)
        bisectmesh.remesh(obj)
        tets = obj.FemMesh.VolumeCount
        # a parameter changes: the recompute is quick and leaves the mesh as it was, marked
        obj.TargetElements = 40000
        start = time.perf_counter()
        self.doc.recompute()
        seconds = time.perf_counter() - start
        self.assertLess(seconds, 0.5, "a recompute took %.2f s: it meshed" % seconds)
        self.assertEqual(obj.FemMesh.VolumeCount, tets)
        self.assertTrue(obj.NeedsRemesh)
        self.assertIn("changed", obj.MeshStatus)
        self.assertTrue(obj.isValid())  # not a recompute error
        # back to the meshed value: the mesh matches its inputs again
        obj.TargetElements = 1500
        self.doc.recompute()
        self.assertFalse(obj.NeedsRemesh)
        # an upstream geometry edit: the Part's shape changes, the mesh is marked, not re-meshed
        moved = Part.makeBox(20, 10, 10, FreeCAD.Vector(5, 0, 0))
        self.part.Shape = moved
        self.doc.recompute()
        self.assertEqual(obj.FemMesh.VolumeCount, tets)
        self.assertAlmostEqual(obj.FemMesh.BoundBox.XMax, 20.0, places=6)
        self.assertTrue(obj.NeedsRemesh)
        bisectmesh.remesh(obj)
        self.assertFalse(obj.NeedsRemesh)
        self.assertAlmostEqual(obj.FemMesh.BoundBox.XMax, 25.0, places=6)
        # the view resolution is an input when UseResolutionHints is on (headless: the Part
        # preferences hold it); a new object has it off
        self.assertFalse(obj.UseResolutionHints)
        obj.UseResolutionHints = True
        bisectmesh.remesh(obj)
        prefs = FreeCAD.ParamGet("User parameter:BaseApp/Preferences/Mod/Part")
        old = prefs.GetFloat("MeshDeviation", 0.5)
        try:
            prefs.SetFloat("MeshDeviation", old / 2)
            obj.touch()
            self.doc.recompute()
            self.assertTrue(obj.NeedsRemesh)
        finally:
            prefs.SetFloat("MeshDeviation", old)

    def test_target_elements_changes_the_count(self):
        obj = bisectmesh.make_mesh_object(self.doc, self.part, elements=2000, order=1)
        bisectmesh.remesh(obj)
        self.assert_valid_mesh(obj, order=1)
        coarse = obj.FemMesh.VolumeCount
        obj.TargetElements = 12000
        self.assertIn("Touched", obj.State)
        self.doc.recompute()
        self.assertEqual(obj.FemMesh.VolumeCount, coarse)
        progress = []
        bisectmesh.remesh(obj, progress=progress.append)
        self.assertEqual(progress[-1], 1.0)
        self.assertEqual(progress, sorted(progress))
        self.assert_valid_mesh(obj, order=1)
        fine = obj.FemMesh.VolumeCount
        self.assertGreater(fine, 2.5 * coarse, (coarse, fine))
        self.assertGreater(fine, 0.7 * 12000)

    def test_element_size_and_options(self):
        obj = bisectmesh.make_mesh_object(self.doc, self.part, size=1.5, use_hints=False, optimize=1,
                                          smooth=0, name="BySize")
        self.assertEqual(obj.TargetElements, 0)
        self.assertAlmostEqual(obj.ElementSize.Value, 1.5)
        self.assertFalse(obj.UseResolutionHints)
        self.assertEqual((obj.OptimizePasses, obj.SmoothPasses), (1, 0))
        bisectmesh.remesh(obj)
        self.assert_valid_mesh(obj, order=2)
        # the spacing is about the element size: about V / (0.1179 s^3) tetrahedra, within a factor 3
        expected = self.part.Shape.Volume / (0.1179 * 1.5 ** 3)
        self.assertGreater(obj.ElementCount, expected / 3)
        self.assertLess(obj.ElementCount, expected * 3)

    def test_bad_properties_are_one_line_and_mark_the_mesh(self):
        obj = bisectmesh.make_mesh_object(self.doc, self.part, elements=1000, order=1)
        bisectmesh.remesh(obj)
        tets = obj.FemMesh.VolumeCount

        def recompute_says(*words):
            self.doc.recompute()
            self.assertTrue(obj.isValid(), "a recompute error: %s" % obj.getStatusString())
            self.assertTrue(obj.NeedsRemesh)
            self.assertNotIn("\n", obj.MeshStatus)
            self.assertNotIn("Traceback", obj.MeshStatus)
            for word in words:
                self.assertIn(word, obj.MeshStatus)
            self.assertEqual(obj.FemMesh.VolumeCount, tets)  # the stale mesh stays, marked

        import Sketcher

        sketch = self.doc.addObject("Sketcher::SketchObject", "Sketch")
        sketch.addGeometry(Part.LineSegment(FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(5, 0, 0)))
        obj.Part = sketch
        recompute_says(obj.Label, "Sketch", "no solid")
        with self.assertRaisesRegex(ValueError, "Sketch"):
            bisectmesh.remesh(obj)

        face = self.doc.addObject("Part::Feature", "JustAFace")
        face.Shape = Part.makeBox(5, 5, 5).Faces[0]
        obj.Part = face
        recompute_says("JustAFace", "no solid")

        obj.Part = None
        recompute_says("Part")

        obj.Part = self.part
        obj.TargetElements = -5
        recompute_says(obj.Label, "TargetElements")
        obj.TargetElements = 0
        obj.ElementSize = 0.0
        recompute_says("ElementSize")
        obj.TargetElements = 1000
        obj.OptimizePasses = -1
        recompute_says("OptimizePasses")
        obj.OptimizePasses = 3
        self.doc.recompute()
        self.assertFalse(obj.NeedsRemesh)  # the inputs of the mesh on screen again

        # an open shell made into a "solid": remesh names the part and the solid
        open_box = self.doc.addObject("Part::Feature", "OpenBox")
        open_box.Shape = Part.Solid(Part.Shell(Part.makeBox(5, 5, 5).Faces[:5]))
        obj.Part = open_box
        self.doc.recompute()
        self.assertTrue(obj.NeedsRemesh)
        with self.assertRaisesRegex(ValueError, r"OpenBox: .*Solid1 is not closed: Edge\d+ bounds only Face\d"):
            bisectmesh.remesh(obj)
        self.assertTrue(obj.NeedsRemesh)
        with self.assertRaises(TypeError):
            bisectmesh.remesh(self.part)

        with self.assertRaises(ValueError):
            bisectmesh.make_mesh_object(self.doc, self.part, elements=100, size=1.0)
        with self.assertRaises(ValueError):
            bisectmesh.make_mesh_object(self.doc, self.part, order=3)

    def test_added_to_the_analysis(self):
        import ObjectsFem

        analysis = ObjectsFem.makeAnalysis(self.doc, "Analysis")
        obj = bisectmesh.make_mesh_object(self.doc, self.part, elements=1500, analysis=analysis)
        self.assertIn(obj, analysis.Group)
        alone = bisectmesh.make_mesh_object(self.doc, self.part, elements=1500, name="Alone")
        self.assertNotIn(alone, analysis.Group)  # no GUI, no active analysis: not added

    def test_adopted_mesh_is_not_computed_again(self):
        # what the task panel does: mesh in a worker, then hand the mesh to the object
        obj = bisectmesh.make_mesh_object(self.doc, self.part, elements=2500, order=1)
        femmesh, result = mesh_object.mesh_part(self.part, **mesh_object.mesh_arguments(obj))
        femmesh.addNode(1000.0, 0.0, 0.0, femmesh.NodeCount + 1000)  # a mark a new meshing would lose
        obj.Proxy.adopt(obj, femmesh, result)
        self.assertEqual(obj.State, ["Up-to-date"])
        self.doc.recompute()
        self.assertFalse(obj.NeedsRemesh)
        self.assertEqual(obj.FemMesh.NodeCount, femmesh.NodeCount)
        self.assertEqual(obj.FemMesh.BoundBox.XMax, 1000.0)
        self.assertEqual(obj.ElementCount, femmesh.VolumeCount)
        # the same geometry in a new shape object is the same input: still up to date
        self.part.Shape = self.part.Shape.copy()
        self.doc.recompute()
        self.assertFalse(obj.NeedsRemesh)
        self.assertEqual(obj.FemMesh.BoundBox.XMax, 1000.0)

    def test_kept_arrays_serve_quality_until_the_mesh_changes(self):
        obj = bisectmesh.make_mesh_object(self.doc, self.part, elements=2000, order=1)
        bisectmesh.remesh(obj)
        kept = obj.Proxy.mesh_arrays()
        self.assertIsNotNone(kept)
        self.assertIs(bisectmesh.mesh_arrays(obj), kept)  # no reading of the FemMesh
        self.assertEqual(len(kept.tets), obj.FemMesh.VolumeCount)
        self.assertEqual(bisectmesh.quality(obj), bisectmesh.quality(obj.FemMesh))
        # any other assignment of the FemMesh drops them: the arrays are read from the new mesh
        other = obj.FemMesh.copy()
        other.addNode(500.0, 0.0, 0.0, other.NodeCount + 500)
        obj.FemMesh = other
        self.assertIsNone(obj.Proxy.mesh_arrays())
        self.assertEqual(len(bisectmesh.mesh_arrays(obj).nodes), other.NodeCount)

    def test_save_and_reopen(self):
        import ObjectsFem

        analysis = ObjectsFem.makeAnalysis(self.doc, "Analysis")
        obj = bisectmesh.make_mesh_object(self.doc, self.part, elements=2500, order=2, use_hints=False,
                                          optimize=2, smooth=1, analysis=analysis)
        bisectmesh.remesh(obj)
        self.assert_valid_mesh(obj, order=2)
        counts = (obj.FemMesh.NodeCount, obj.FemMesh.VolumeCount, obj.FemMesh.FaceCount)
        groups = group_names(obj.FemMesh)
        summary, name, part_name, analysis_name = obj.Summary, obj.Name, self.part.Name, analysis.Name
        folder = tempfile.mkdtemp(prefix="bisectmesh-")
        try:
            path = os.path.join(folder, "mesh_object.FCStd")
            self.doc.saveAs(path)
            FreeCAD.closeDocument(self.doc.Name)
            self.doc = FreeCAD.openDocument(path)
            obj = self.doc.getObject(name)
            self.assertIsNotNone(obj)
            self.assertEqual(obj.TypeId, "Fem::FemMeshObjectPython")
            self.assertTrue(mesh_object.is_mesh_object(obj), getattr(obj, "Proxy", None))
            self.assertEqual(obj.Part, self.doc.getObject(part_name))
            self.assertEqual(obj.ElementOrder, "2nd")
            self.assertEqual((obj.TargetElements, obj.UseResolutionHints, obj.OptimizePasses, obj.SmoothPasses),
                             (2500, False, 2, 1))
            self.assertEqual(obj.Summary, summary)
            self.assertEqual((obj.FemMesh.NodeCount, obj.FemMesh.VolumeCount, obj.FemMesh.FaceCount), counts)
            self.assertEqual(group_names(obj.FemMesh), groups)
            self.assertIn(obj, self.doc.getObject(analysis_name).Group)
            self.assertNotIn("Touched", obj.State)
            # the fingerprint survives: a recompute after the reload finds the mesh current ...
            self.doc.getObject(part_name).touch()
            self.doc.recompute()
            self.assertFalse(obj.NeedsRemesh, obj.MeshStatus)
            # ... and a change marks it; remesh meshes
            obj.TargetElements = 6000
            self.doc.recompute()
            self.assertTrue(obj.NeedsRemesh)
            bisectmesh.remesh(obj)
            self.assert_valid_mesh(obj, order=2)
            self.assertGreater(obj.FemMesh.VolumeCount, 1.5 * counts[1])
        finally:
            shutil.rmtree(folder, ignore_errors=True)

    def test_design_one_way_imports_one_table_one_formula(self):
        import subprocess
        import sys

        from bisectmesh import arguments
        from bisectmesh.gui import view_provider

        # documents saved before the view provider moved to gui/ still find it
        self.assertIs(mesh_object.ViewProviderMeshObject, view_provider.ViewProviderMeshObject)
        with self.assertRaises(AttributeError):
            mesh_object.NoSuchThing
        # mesh_object imports nothing of the GUI: a plain interpreter without FreeCAD loads it
        mod = os.path.dirname(os.path.dirname(os.path.abspath(bisectmesh.__file__)))
        code = ("import sys; sys.path.insert(0, %r); import bisectmesh.mesh_object; "
                "print(sorted(m for m in sys.modules if m.startswith('bisectmesh.gui') or m == 'FreeCADGui'))" % mod)
        out = subprocess.run(["/usr/bin/python3", "-c", code], capture_output=True, text=True, timeout=60)
        self.assertEqual(out.returncode, 0, out.stderr)
        self.assertEqual(out.stdout.strip(), "[]")
        # one spacing formula: the element size the panel proposes asks for the count it names
        volume = self.part.Shape.Volume
        size = arguments.spacing_for(volume, 5000)
        self.assertAlmostEqual(arguments.elements_for(volume, size), 5000.0, places=6)
        self.assertAlmostEqual(arguments.VOLUME_PER_TET, 0.11785113, places=8)  # 1/(6 sqrt 2)
        # one table of stage names: the object's summary and the panel read the same one
        result = {"tets": 10, "order": 1, "nodes": 8, "seconds": 1.0,
                  "times": {key: 0.5 for key, _ in mesh_object.STAGES}, "quality": {}}
        line = mesh_object.summary(result).splitlines()[1]
        for _, label in mesh_object.STAGES:
            self.assertIn(label.lower() + " 0.500", line)

    def test_command_and_panel_modules(self):
        from xml.etree import ElementTree

        try:
            import PySide.QtGui  # noqa: F401  (FreeCAD's Qt shim)
        except ImportError as err:
            self.skipTest("no PySide in this FreeCAD: %s" % err)
        from bisectmesh.gui import command_mesh, mesh_panel

        self.assertEqual(command_mesh.COMMAND_NAME, "BisectMesh_Mesh")
        resources = command_mesh.MeshCommand().GetResources()
        self.assertEqual(resources["MenuText"], "Mesh with BisectMesh")
        self.assertTrue(os.path.isfile(resources["Pixmap"]), resources["Pixmap"])
        root = ElementTree.parse(resources["Pixmap"]).getroot()
        self.assertEqual(root.tag, "{http://www.w3.org/2000/svg}svg")
        self.assertEqual(root.get("viewBox"), "0 0 64 64")
        self.assertTrue(hasattr(mesh_panel.MeshPanel, "getStandardButtons"))
        from bisectmesh import arguments

        self.assertEqual(mesh_panel._size_for(1717.0, 5000), round(arguments.spacing_for(1717.0, 5000), 3))
        self.assertFalse(hasattr(mesh_panel, "_STAGES"))


if __name__ == "__main__":
    unittest.main()
