"""Issue 17's quality table through FreeCAD: ``mesh_shape`` (tetra10, as a FEM user meshes) on the
B-rep models that users mesh coarse, cantilever, slender-appendage, lug, plate-hole and
two-boxes-cavity, at R in {50, 100, 300, 1000, 3000}.

Asserted for every mesh: the smallest dihedral angle of the corner tetrahedra, computed here with
NumPy from the FemMesh (not from the mesher's report), is at least 10 degrees; the mean alpha the
mesher reports is at least 0.20, and 0.24 at R >= 1000, except where SHORTFALLS names the model,
the bound it keeps and why (tests/cpp/occ/test_quality_table.cpp holds the same table for the
CLI's routes, STL included). Figures go to $BISECTMESH_ARTIFACTS/quality_table.json. Skips when
../shared is absent.
"""

import json
import os
import unittest

import numpy as np

import Part

import bisectmesh
from bisectmesh import shape_mesher

from fc_helpers import artifacts_dir

SHARED = os.environ.get("BISECTMESH_SHARED_DIR") or os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "shared")
MODELS = ("cantilever.brep", "slender-appendage.brep", "lug.brep", "plate-hole.brep", "two-boxes-cavity.brep")
COUNTS = (50, 100, 300, 1000, 3000)
# (model, R) -> (mean alpha kept at R >= 1000, why); none since the mean shape's passes move the
# nodes inside faces too (two-boxes-cavity at 1,000 had 0.237 before)
SHORTFALLS = {}
FIGURES = {}


def smallest_dihedral(nodes, tets):
    """The smallest dihedral angle (degrees) over the tetrahedra (corner nodes)."""
    x = nodes[tets[:, :4]]
    smallest = np.full(len(tets), 180.0)
    for i, j, k, l in ((0, 1, 2, 3), (0, 2, 1, 3), (0, 3, 1, 2), (1, 2, 0, 3), (1, 3, 0, 2), (2, 3, 0, 1)):
        e = x[:, j] - x[:, i]
        e /= np.linalg.norm(e, axis=1)[:, None]
        a = x[:, k] - x[:, i]
        a -= (a * e).sum(1)[:, None] * e
        b = x[:, l] - x[:, i]
        b -= (b * e).sum(1)[:, None] * e
        cos = (a * b).sum(1) / (np.linalg.norm(a, axis=1) * np.linalg.norm(b, axis=1))
        smallest = np.minimum(smallest, np.degrees(np.arccos(np.clip(cos, -1, 1))))
    return float(smallest.min())


@unittest.skipUnless(os.path.isdir(os.path.join(SHARED, "models")), "../shared is absent")
class QualityTableTest(unittest.TestCase):
    @classmethod
    def tearDownClass(cls):
        with open(os.path.join(artifacts_dir(), "quality_table.json"), "w") as f:
            json.dump(FIGURES, f, indent=2, sort_keys=True)

    def check_model(self, model):
        shape = Part.read(os.path.join(SHARED, "models", model))
        for count in COUNTS:
            report = {}
            mesh = shape_mesher.mesh_shape(shape, elements=count, order=2, report=report)
            arrays = bisectmesh.mesh_arrays(mesh)
            self.assertEqual(arrays.order, 2)
            stats = report["stats"]
            dihedral = smallest_dihedral(arrays.nodes, arrays.tets)
            alpha = stats["quality"]["alpha_mean"]
            FIGURES["%s %d" % (model, count)] = {"tetrahedra": len(arrays.tets), "nodes": len(arrays.nodes),
                                                 "dihedral_min": dihedral, "alpha_mean": alpha,
                                                 "count_floor": stats["count_floor"],
                                                 "count_floor_reason": stats["count_floor_reason"]}
            fine_bound, why = SHORTFALLS.get((model, count), (0.24, ""))
            where = "%s at %d (%d tetrahedra)%s" % (model, count, len(arrays.tets), "; short: " + why if why else "")
            self.assertGreaterEqual(dihedral, 10.0, where)
            self.assertGreaterEqual(alpha, fine_bound if count >= 1000 else 0.20, where)

    def test_cantilever(self):
        self.check_model("cantilever.brep")

    def test_slender_appendage(self):
        self.check_model("slender-appendage.brep")

    def test_lug(self):
        self.check_model("lug.brep")

    def test_plate_hole(self):
        self.check_model("plate-hole.brep")

    def test_two_boxes_cavity(self):
        self.check_model("two-boxes-cavity.brep")


if __name__ == "__main__":
    unittest.main()
