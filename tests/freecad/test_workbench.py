"""The workbench package headless: Init.py, InitGui.py, package.xml, icons, the GUI modules'
imports, and the colouring and histogram computations behind the quality panel."""

import os
import unittest
import xml.etree.ElementTree as ElementTree

import numpy as np

import FreeCAD

import bisectmesh
from bisectmesh import femmesh_arrays

import fc_helpers


def workbench_dir():
    """Mod/BisectMesh as FreeCAD sees it (the staged copy in the build tree under CTest)."""
    return os.path.dirname(os.path.dirname(os.path.abspath(bisectmesh.__file__)))


class WorkbenchFilesTest(unittest.TestCase):

    def test_package_is_the_one_under_test(self):
        build_mod = os.environ.get("BISECTMESH_BUILD_MOD")
        if not build_mod:
            self.skipTest("BISECTMESH_BUILD_MOD not set (run by hand)")
        self.assertEqual(os.path.realpath(workbench_dir()), os.path.realpath(build_mod))
        self.assertTrue(hasattr(bisectmesh.core(), "quality_summary"))

    def test_init_py_runs(self):
        path = os.path.join(workbench_dir(), "Init.py")
        with open(path) as source:
            code = compile(source.read(), path, "exec")
        exec(code, {"__name__": "BisectMeshInit", "FreeCAD": FreeCAD, "App": FreeCAD})

    def test_initgui_py_compiles_and_names_the_workbench(self):
        path = os.path.join(workbench_dir(), "InitGui.py")
        with open(path) as source:
            text = source.read()
        compile(text, path, "exec")  # running it needs the GUI: see gui_quality.py
        self.assertIn("class BisectMeshWorkbench", text)
        self.assertIn("addWorkbench(BisectMeshWorkbench())", text)

    def test_package_xml(self):
        path = os.path.join(workbench_dir(), "package.xml")
        if not os.path.isfile(path):
            self.skipTest("package.xml is staged beside the workbench only in the build tree")
        metadata = FreeCAD.Metadata(path)
        self.assertEqual(metadata.Name, "BisectMesh")
        self.assertEqual(metadata.Version, "0.1.0")
        self.assertEqual(metadata.License[0]["name"], "LGPL-2.1-or-later")
        self.assertEqual(metadata.Maintainer[0]["name"], "BisectMesh developers")
        workbenches = metadata.Content["workbench"]
        self.assertEqual(len(workbenches), 1)
        workbench = workbenches[0]
        self.assertEqual(workbench.Classname, "BisectMeshWorkbench")
        self.assertEqual(workbench.Subdirectory, "./")
        self.assertEqual(workbench.FreeCADMin, "0.20.0")
        for icon in (metadata.Icon, workbench.Icon):
            self.assertTrue(os.path.isfile(os.path.join(workbench_dir(), icon)), icon)

    def test_icons_are_svg(self):
        from bisectmesh.gui import icon_path

        for name in ("BisectMesh.svg", "BisectMesh_Quality.svg"):
            path = icon_path(name)
            self.assertTrue(os.path.isfile(path), name)
            root = ElementTree.parse(path).getroot()
            self.assertEqual(root.tag, "{http://www.w3.org/2000/svg}svg")
            self.assertEqual(root.get("viewBox"), "0 0 64 64")

    def test_gui_modules_import_headless(self):
        import importlib

        for name in ("bisectmesh.gui.colouring", "bisectmesh.gui.histograms"):  # no GUI needed
            importlib.import_module(name)
        try:
            importlib.import_module("PySide.QtGui")  # FreeCAD's Qt shim
        except ImportError as err:
            self.skipTest("no PySide in this FreeCAD: %s" % err)
        from bisectmesh.gui import command_quality, quality_panel

        self.assertEqual(command_quality.COMMAND_NAME, "BisectMesh_Quality")
        resources = command_quality.QualityCommand().GetResources()
        self.assertEqual(resources["MenuText"], "Mesh quality")
        self.assertIn("Select a FEM mesh object", resources["ToolTip"])
        self.assertTrue(os.path.isfile(resources["Pixmap"]))
        self.assertTrue(hasattr(quality_panel.QualityPanel, "getStandardButtons"))


class ColouringTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        cls.doc = FreeCAD.newDocument("BisectMeshColouringTest")
        part = fc_helpers.box_minus_cylinder(cls.doc)
        cls.mesh = fc_helpers.gmsh_mesh(cls.doc, part, 2, size=4.0)

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.doc.Name)

    def test_node_colours_take_the_worst_element(self):
        from bisectmesh.gui import colouring

        arrays = bisectmesh.mesh_arrays(self.mesh)
        ids, measures = bisectmesh.element_quality(self.mesh, arrays)
        gamma = measures["gamma"]
        colours = colouring.node_colours(arrays, gamma, "gamma")
        # Every node of the mesh is used by a tetrahedron (mid-edge nodes too) and gets a colour.
        self.assertEqual(sorted(colours), sorted(self.mesh.FemMesh.Nodes))
        for rgb in colours.values():
            self.assertEqual(len(rgb), 3)
            self.assertTrue(all(0.0 <= c <= 1.0 for c in rgb))
        # The nodes of the worst element carry its colour: no other element is worse.
        worst = int(np.argmin(gamma))
        expected = tuple(colouring.ramp(colouring.normalized("gamma", [gamma[worst]]))[0])
        for row in arrays.tets[worst]:
            np.testing.assert_allclose(colours[int(arrays.node_ids[row])], expected)
        node_ids, minima = femmesh_arrays.node_minimum(arrays, gamma)
        self.assertEqual(len(node_ids), self.mesh.FemMesh.NodeCount)
        self.assertAlmostEqual(float(minima.min()), float(gamma.min()))

    def test_scales(self):
        from bisectmesh.gui import colouring

        regular = {"gamma": 1.0, "alpha": 1.0 / 3.0, "dihedral_min": 70.52877936550931,
                   "solid_angle_min": 0.5512855984325309, "dihedral_max": 70.52877936550931}
        for name, value in regular.items():
            self.assertAlmostEqual(float(colouring.normalized(name, [value])[0]), 1.0, places=6)
            self.assertEqual(float(colouring.normalized(name, [0.0 if name != "dihedral_max" else 180.0])[0]), 0.0)
        red, green = colouring.ramp([0.0, 1.0])
        self.assertGreater(red[0], red[1])
        self.assertGreater(green[1], green[0])
        with self.assertRaises(ValueError):
            colouring.normalized("beauty", [1.0])

    def test_poor_element_nodes(self):
        from bisectmesh.gui import colouring

        arrays = bisectmesh.mesh_arrays(self.mesh)
        _, measures = bisectmesh.element_quality(self.mesh, arrays)
        values = measures["dihedral_min"]
        threshold = float(np.median(values))
        nodes = colouring.worst_element_nodes(arrays, values, "dihedral_min", threshold)
        expected = set(arrays.node_ids[np.unique(arrays.tets[values < threshold])].tolist())
        self.assertEqual(set(nodes), expected)
        self.assertEqual(colouring.worst_element_nodes(arrays, values, "dihedral_min", 0.0), [])

    def test_histogram_pictures(self):
        from bisectmesh.gui import histograms

        report = bisectmesh.quality(self.mesh)
        png = histograms.histogram_png(report)
        self.assertTrue(png.startswith(b"\x89PNG"))
        with open(os.path.join(fc_helpers.artifacts_dir(), "quality_histograms.png"), "wb") as out:
            out.write(png)
        self.assertTrue(histograms.legend_png().startswith(b"\x89PNG"))


if __name__ == "__main__":
    unittest.main()
