"""Every public Python entry point refuses bad arguments with the exceptions the README promises:
TypeError for a wrong type, ValueError for a value that cannot be meshed, each naming the Python
argument (never the CLI's -n or -s), and before any work starts. The tables hold, for every
argument, zero, negative, NaN, infinite and huge values and wrong types."""

import math
import re
import time
import unittest

import FreeCAD
import Part

import bisectmesh
from bisectmesh import mesh_object

NAN, INF = float("nan"), float("inf")
# a refusal is immediate: no meshing may start before the arguments are checked
REFUSAL_SECONDS = 2.0


class RefusalTable:
    """Runs ``call(**{argument: value})`` for each (argument, value, exception) row."""

    def refuse(self, call, rows, fixed=None):
        for argument, value, exception, *named in rows:
            with self.subTest(argument=argument, value=value):
                kwargs = dict(fixed or {})
                kwargs[argument] = value
                start = time.perf_counter()
                with self.assertRaises(exception) as caught:
                    call(**kwargs)
                seconds = time.perf_counter() - start
                # exactly the promised class: a TypeError is not a ValueError and vice versa
                other = ValueError if exception is TypeError else TypeError
                self.assertNotIsInstance(caught.exception, other)
                message = str(caught.exception)
                self.assertIn(named[0] if named else argument, message)
                self.assertIsNone(re.search(r"(^|\s)-[ns]\b", message), message)
                self.assertLess(seconds, REFUSAL_SECONDS, "%s=%r took %.1f s to refuse" % (argument, value, seconds))


def number_rows(argument, positive_only=True):
    """Zero, negative, NaN, infinity: ValueError; a string, a list, a bool: TypeError."""
    rows = [(argument, v, ValueError) for v in ((0, 0.0, -1, -2.5) if positive_only else (-1, -2.5))]
    rows += [(argument, v, ValueError) for v in (NAN, INF, -INF)]
    rows += [(argument, v, TypeError) for v in ("2", [2.0], True, 1 + 2j)]
    return rows


def count_rows(argument, low=1, high=None):
    rows = [(argument, low - 1, ValueError), (argument, -7, ValueError)]
    if high is not None:
        rows.append((argument, high + 1, ValueError))
    rows += [(argument, v, TypeError) for v in (NAN, INF, 2.5, 1000.0, "1000", True, [3])]
    return rows


class MeshShapeArgumentsTest(unittest.TestCase, RefusalTable):

    def setUp(self):
        self.box = Part.makeBox(10, 10, 10)

    def call(self, **kwargs):
        shape = kwargs.pop("shape", self.box)
        return bisectmesh.mesh_shape(shape, **kwargs)

    def test_elements(self):
        rows = count_rows("elements") + [("elements", 10 ** 15, ValueError), ("elements", 2 ** 80, ValueError)]
        self.refuse(self.call, rows, {"order": 1})

    def test_size(self):
        rows = number_rows("size") + [("size", 1e-9, ValueError)]  # ~1e30 elements in 1000 mm^3
        self.refuse(self.call, rows, {"order": 1})

    def test_neither_or_both(self):
        for kwargs in ({}, {"elements": 100, "size": 1.0}):
            with self.assertRaisesRegex(ValueError, "elements or size"):
                self.call(order=1, **kwargs)

    def test_order(self):
        rows = [("order", v, ValueError) for v in (0, 3, -1)]
        rows += [("order", v, TypeError) for v in (1.0, NAN, "2", True, None)]
        self.refuse(self.call, rows, {"elements": 500})

    def test_resolution(self):
        rows = number_rows("resolution") + [("resolution", 1e-12, ValueError)]
        rows += [
            ("resolution", {"deviation": 0}, ValueError, "deviation"),
            ("resolution", {"deviation": NAN}, ValueError, "deviation"),
            ("resolution", {"deviation": 500}, ValueError, "deviation"),
            ("resolution", {"deviation": "1"}, TypeError, "deviation"),
            ("resolution", {"angular_deflection": 0.01}, ValueError, "angular_deflection"),
            ("resolution", {"angular_deflection": 200}, ValueError, "angular_deflection"),
            ("resolution", {"angular_deflection": INF}, ValueError, "angular_deflection"),
            ("resolution", {"deflection": -1}, ValueError, "deflection"),
            ("resolution", {"deflection": 1e-9}, ValueError, "deflection"),
            ("resolution", {"deflection": [1]}, TypeError, "deflection"),
            ("resolution", {"fineness": 1}, ValueError, "fineness"),
        ]
        self.refuse(self.call, rows, {"elements": 500})

    def test_flags_callables_dicts(self):
        rows = [("hints", v, TypeError) for v in (1, "yes", None)]
        rows += [("progress", v, TypeError) for v in (5, "print")]
        rows += [("report", v, TypeError) for v in ([], "r")]
        rows += [("threads", v, ValueError) for v in (-1, 10 ** 6)]
        rows += [("threads", v, TypeError) for v in (1.5, NAN, "2", True)]
        rows += [("shape", v, TypeError) for v in (None, "box", 5)]
        rows += [("shape", Part.Shape(), ValueError)]
        self.refuse(self.call, rows, {"elements": 500})

    def test_options(self):
        rows = []
        for name in ("min_size", "max_size", "chord_deviation", "curvature_elements"):
            rows += number_rows(name, positive_only=False)
        rows += [("max_size", 1e-9, ValueError), ("chord_deviation", 1e-12, ValueError),
                 ("curvature_elements", 2, ValueError)]
        for name in ("optimize", "smooth", "slivers", "mean_shape"):
            rows += [(name, -1, ValueError), (name, 10 ** 6, ValueError),
                     (name, 1.5, TypeError), (name, NAN, TypeError), (name, "3", TypeError)]
        rows += [("size_grading", v, ValueError) for v in (0, -1, NAN, INF)]
        rows += [("size_grading", "x", TypeError), ("boundary_flips", 1, TypeError), ("face_moves", 1, TypeError),
                 ("insertion", "random", ValueError),
                 ("regions", "Face1", TypeError), ("regions", [5], TypeError, "regions[0]"),
                 ("regions", [{"size": 0, "faces": [1]}], ValueError, "regions[0]"),
                 ("regions", [{"size": NAN, "faces": [1]}], ValueError, "regions[0]"),
                 ("regions", [{"size": 1.0, "faces": ["Edge1"]}], ValueError, "regions[0]"),
                 ("regions", [{"size": 1.0, "faces": [0]}], ValueError, "regions[0]"),
                 ("regions", [{"faces": [1]}], ValueError, "regions[0]"),
                 ("fineness", 3, TypeError), ("elements_per_mm", 1, TypeError)]
        self.refuse(self.call, rows, {"elements": 500, "order": 1})

    def test_good_arguments_still_mesh(self):
        # the bounds are not too tight: FreeCAD's own extremes of a view's resolution, a float
        # size, NumPy-free plain ints
        report = {}
        mesh = bisectmesh.mesh_shape(Part.makeCylinder(3, 8), elements=400, order=1,
                                     resolution={"deviation": 100, "angular_deflection": 180},
                                     threads=1, report=report, min_size=0, max_size=0)
        self.assertGreater(mesh.VolumeCount, 100)
        mesh = bisectmesh.mesh_shape(self.box, size=4, order=1, hints=True)
        self.assertGreater(mesh.VolumeCount, 10)
        self.assertTrue(all(math.isfinite(v) for v in report["stats"]["times"].values()))


class MeshObjectArgumentsTest(unittest.TestCase, RefusalTable):

    @classmethod
    def setUpClass(cls):
        cls.doc = FreeCAD.newDocument("BisectMeshArguments")
        cls.part = cls.doc.addObject("Part::Box", "Box")
        cls.doc.recompute()

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.doc.Name)

    def make(self, **kwargs):
        doc = kwargs.pop("doc", self.doc)
        part = kwargs.pop("part_obj", self.part)
        return bisectmesh.make_mesh_object(doc, part, **kwargs)

    def part_mesh(self, **kwargs):
        return mesh_object.mesh_part(self.part, **kwargs)

    def test_make_mesh_object(self):
        before = len(self.doc.Objects)
        rows = count_rows("elements") + number_rows("size")
        rows += [("order", 3, ValueError), ("order", "2", TypeError), ("use_hints", 1, TypeError)]
        for name in ("optimize", "smooth"):
            rows += [(name, -1, ValueError), (name, 1000, ValueError), (name, 1.5, TypeError), (name, NAN, TypeError)]
        rows += [("doc", None, TypeError), ("doc", "Unnamed", TypeError),
                 ("part_obj", None, TypeError), ("part_obj", Part.makeBox(1, 1, 1), TypeError),
                 ("name", 5, TypeError), ("name", "", TypeError),
                 ("analysis", self.part, TypeError), ("analysis", "Analysis", TypeError)]
        self.refuse(self.make, rows)
        self.assertEqual(len(self.doc.Objects), before, "a refused call added an object")

    def test_part_in_another_document(self):
        other = FreeCAD.newDocument("BisectMeshArgumentsOther")
        try:
            with self.assertRaisesRegex(ValueError, "part_obj"):
                bisectmesh.make_mesh_object(other, self.part, elements=100)
        finally:
            FreeCAD.closeDocument(other.Name)

    def test_mesh_part(self):
        self.refuse(self.part_mesh, count_rows("elements") + number_rows("size"))
        rows = [("order", 0, ValueError), ("order", 2.0, TypeError), ("use_hints", "no", TypeError),
                ("optimize", -3, ValueError), ("smooth", INF, TypeError), ("progress", 3, TypeError)]
        self.refuse(self.part_mesh, rows, {"elements": 500})


class QualityArgumentsTest(unittest.TestCase, RefusalTable):

    @classmethod
    def setUpClass(cls):
        cls.mesh = bisectmesh.mesh_shape(Part.makeBox(4, 4, 4), elements=200, order=1)

    def test_quality(self):
        rows = [("femmesh", v, TypeError) for v in (None, "mesh", 3, Part.makeBox(1, 1, 1))]
        rows += [("validate", v, TypeError) for v in (1, "yes", None)]
        rows += [("per_element", v, TypeError) for v in (0, "no")]
        self.refuse(lambda femmesh=self.mesh, **kw: bisectmesh.quality(femmesh, **kw),
                    [r for r in rows if r[0] != "femmesh"])
        # the mesh argument is named by what it must be
        self.refuse(lambda **kw: bisectmesh.quality(**kw),
                    [r + ("Fem.FemMesh",) for r in rows if r[0] == "femmesh"])

    def test_element_quality_mesh_arrays_format_report_view_resolution(self):
        with self.assertRaisesRegex(TypeError, "arrays"):
            bisectmesh.element_quality(self.mesh, arrays=[1, 2])
        with self.assertRaisesRegex(TypeError, "Fem.FemMesh"):
            bisectmesh.mesh_arrays(None)
        for value in (None, 5, {"tets": 1}):
            with self.assertRaisesRegex(TypeError, "report"):
                bisectmesh.format_report(value)
        for value in (None, Part.makeBox(1, 1, 1), "Box"):
            with self.assertRaisesRegex(TypeError, "obj"):
                bisectmesh.view_resolution(value)
        # and the good calls work
        report = bisectmesh.quality(self.mesh, validate=True, per_element=False)
        self.assertIn("tetrahedra", bisectmesh.format_report(report))


class CoreArgumentsTest(unittest.TestCase, RefusalTable):
    """The compiled module's own entry points (bisectmesh.core().generate, mesh_brep)."""

    def setUp(self):
        import numpy as np

        self.nodes = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float) * 10
        self.faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]]
        self.regions = [[0, 1, 2, 3]]
        self.brep = Part.makeBox(10, 10, 10).exportBrepToString()

    def generate(self, **kwargs):
        return bisectmesh.core().generate(self.nodes, self.faces, self.regions, **kwargs)

    def mesh_brep(self, **kwargs):
        return bisectmesh.core().mesh_brep(self.brep, **kwargs)

    def test_no_count_names_python_arguments(self):
        for call in (self.generate, self.mesh_brep):
            for kwargs in ({}, {"elements": 0}, {"size": 0}, {"elements": 0, "size": 0.0}):
                with self.assertRaises(ValueError) as caught:
                    call(**kwargs)
                message = str(caught.exception)
                self.assertIn("elements", message)
                self.assertIn("size", message)
                self.assertNotIn("-n", message)

    def test_option_values_and_types(self):
        rows = [("size", v, ValueError) for v in (NAN, INF, -1.0)]
        rows += [("elements", v, TypeError) for v in (NAN, 2.5, "100", True)]
        rows += [("elements", v, ValueError) for v in (-1, 2 ** 70)]
        rows += [("order", 3, ValueError), ("order", "2", TypeError), ("threads", -1, ValueError),
                 ("smooth", 1.5, TypeError), ("boundary_flips", 1, TypeError), ("min_size", "1", TypeError),
                 ("regions", 5, TypeError), ("bogus", 1, TypeError, "bogus")]
        for call in (self.generate, self.mesh_brep):
            self.refuse(call, rows, {"elements": 50})


if __name__ == "__main__":
    unittest.main()
