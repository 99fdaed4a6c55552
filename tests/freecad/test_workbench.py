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


def repository_dir():
    """The repository's root: tests/freecad/../.."""
    here = os.environ.get("BISECTMESH_TEST_DIR") or os.path.dirname(os.path.abspath(__file__))
    return os.path.normpath(os.path.join(here, os.pardir, os.pardir))


def check_package_xml(test, path):
    """Checks the package.xml at ``path`` as FreeCAD 0.20 loads it (its start-up scripts run
    Init.py and InitGui.py from the workbench's <subdirectory>, relative to package.xml, and take
    the workbench icon relative to that folder) and as the Addon Manager's developer checks
    (AddonManager.validate_package_xml) want it: name, version, date, description, maintainer
    with an email, licence, a repository URL with its branch, a readme URL, an icon, and the
    workbench's class name. Returns the workbench's metadata."""
    import datetime
    import re

    metadata = FreeCAD.Metadata(path)
    here = os.path.dirname(path)
    test.assertEqual(metadata.Name, "BisectMesh")
    test.assertEqual(metadata.Version, bisectmesh.__version__)
    test.assertTrue(metadata.Description)
    # FreeCAD 0.20's Metadata has no Date: read the element itself
    root = ElementTree.parse(path).getroot()
    namespace = {"p": "https://wiki.freecad.org/Package_Metadata"}
    date = root.find("p:date", namespace)
    test.assertIsNotNone(date, "package.xml has no <date>")
    datetime.date.fromisoformat(date.text.strip())  # YYYY-MM-DD, a real day
    test.assertEqual(metadata.License[0]["name"], "LGPL-2.1-or-later")
    test.assertTrue(metadata.Maintainer)
    for maintainer in metadata.Maintainer:
        test.assertTrue(maintainer["name"])
        test.assertRegex(maintainer["email"], r"^[^@\s]+@[^@\s]+\.[a-z]+$")
    urls = {url["type"]: url for url in metadata.Urls}
    test.assertIn("repository", urls)
    test.assertRegex(urls["repository"]["location"], r"^https://github\.com/[\w.-]+/[\w.-]+$")
    test.assertTrue(urls["repository"]["branch"], "the repository URL needs its branch")
    test.assertIn("readme", urls)
    test.assertTrue(os.path.isfile(os.path.join(here, metadata.Icon)), metadata.Icon)
    workbenches = metadata.Content["workbench"]
    test.assertEqual(len(workbenches), 1)
    workbench = workbenches[0]
    test.assertEqual(workbench.Classname, "BisectMeshWorkbench")
    test.assertEqual(workbench.FreeCADMin, "0.20.0")
    test.assertTrue(metadata.supportsCurrentFreeCAD() and workbench.supportsCurrentFreeCAD())
    # FreeCAD's own rule (FreeCADInit.py, FreeCADGuiInit.py): the workbench's name when empty
    folder = os.path.join(here, (workbench.Subdirectory or workbench.Name).replace("/", os.path.sep))
    for name in ("Init.py", "InitGui.py"):
        test.assertTrue(os.path.isfile(os.path.join(folder, name)), "%s not in %s" % (name, folder))
    with open(os.path.join(folder, "InitGui.py")) as source:
        test.assertIn("class %s(" % workbench.Classname, source.read())
    test.assertTrue(os.path.isfile(os.path.join(folder, workbench.Icon)), workbench.Icon)
    test.assertTrue(re.match(r"^\d+\.\d+\.\d+$", metadata.Version))
    return workbench


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

    def test_package_xml_staged_beside_initgui(self):
        # The copy cmake stages (and installs) sits beside InitGui.py: FreeCAD reads it at start-up
        # and runs Init.py and InitGui.py from <subdirectory> relative to it.
        path = os.path.join(workbench_dir(), "package.xml")
        if not os.path.isfile(path):
            self.skipTest("package.xml is staged beside the workbench only in the build tree")
        workbench = check_package_xml(self, path)
        self.assertEqual(os.path.normpath(workbench.Subdirectory), ".")

    def test_package_xml_of_the_repository(self):
        # The Addon Manager clones the repository and reads the package.xml at its root.
        path = os.path.join(repository_dir(), "package.xml")
        if not os.path.isfile(path):
            self.skipTest("no repository beside the tests (%s)" % path)
        workbench = check_package_xml(self, path)
        self.assertEqual(os.path.normpath(workbench.Subdirectory), os.path.join("Mod", "BisectMesh"))

    def test_icons_are_svg(self):
        from bisectmesh.gui import icon_path

        for name in ("BisectMesh.svg", "BisectMesh_Quality.svg", "BisectMesh_Mesh.svg", "BisectMesh_MeshStale.svg"):
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
        from bisectmesh.gui import colouring

        legend = colouring.legend_rgb(240, 14)
        self.assertEqual(legend.shape, (14, 240, 3))
        self.assertEqual(tuple(legend[0, 0]), (255, 0, 0))  # poor: red
        self.assertEqual(tuple(legend[0, -1]), (0, 255, 0))  # good: green


if __name__ == "__main__":
    unittest.main()
