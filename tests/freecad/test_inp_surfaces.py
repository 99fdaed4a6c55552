"""The CLI's .inp as a CalculiX user takes it: a deck that only *INCLUDEs the mesh and names the
B-rep faces' sets and surfaces as the file gives them (Face<k> nodes, Face<k>_Surface element
faces), solved by ccx.

The part: a 100 x 10 x 10 box with a vertical hole of radius 3 at x = 50 (Part CSG, exported as
BREP for the CLI), tetra10. Its face x = 0 is fixed, its face x = 100 carries a pressure P_END
and the hole's cylinder a pressure P_HOLE, both by *DSLOAD on the faces' surfaces. Statics says
what the supports take: the end face's force P_END * 100 mm^2 along x (no node of it is fixed),
and nothing from the hole along x or y, whatever its mesh (the net force of a uniform pressure is
p times the vector area, which for the cylinder's two rims in planes z = const has no x or y
part); along z the rims' polygons differ by the grid, so only a small share. A face label that
named another face of the element puts the load on a face inside the part or on a wrong side:
the totals move by the load's whole size.
"""

import os
import shutil
import subprocess
import tempfile
import unittest

import FreeCAD
import Part

from test_cantilever import _which_ccx

P_END, P_HOLE = 2.0, 5.0  # MPa
END_AREA = 100.0  # mm^2: the 10 x 10 end face


def face_index(shape, test):
    """FreeCAD's 1-based number of the one face whose centre of mass passes ``test``."""
    found = [k + 1 for k, f in enumerate(shape.Faces) if test(f)]
    assert len(found) == 1, found
    return found[0]


def total_forces(dat_path):
    """The (fx, fy, fz) that ccx's *NODE PRINT ..., TOTALS=ONLY wrote, the last block of them."""
    with open(dat_path) as f:
        lines = f.read().splitlines()
    totals = None
    for k, line in enumerate(lines):
        if line.strip().startswith("total force"):
            values = [v for v in lines[k + 1:k + 4] if v.strip()]
            totals = tuple(float(x) for x in values[0].split())
    return totals


class InpSurfacesTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        cls.cli = os.environ.get("BISECTMESH_CLI")
        cls.ccx = _which_ccx()
        cls.tmp = tempfile.mkdtemp(prefix="bisect_inp_surfaces_")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_pressure_on_the_faces_surfaces_reaches_the_supports(self):
        if not self.cli or not os.path.isfile(self.cli):
            self.skipTest("BISECTMESH_CLI names no built bisect-mesh")
        if not self.ccx:
            self.skipTest("no ccx (CalculiX) on PATH or in FreeCAD's preferences")
        box = Part.makeBox(100, 10, 10)
        hole = Part.makeCylinder(3, 10, FreeCAD.Vector(50, 5, 0), FreeCAD.Vector(0, 0, 1))
        shape = box.cut(hole)
        fixed = face_index(shape, lambda f: abs(f.CenterOfMass.x) < 1e-9 and f.Surface.isPlanar())
        end = face_index(shape, lambda f: abs(f.CenterOfMass.x - 100) < 1e-9)
        bore = face_index(shape, lambda f: isinstance(f.Surface, Part.Cylinder))
        brep = os.path.join(self.tmp, "bored.brep")
        shape.exportBrep(brep)
        mesh = os.path.join(self.tmp, "bored.inp")
        run = subprocess.run([self.cli, brep, "-n", "3000", "--order", "2", "-o", mesh],
                             capture_output=True, text=True, timeout=300)
        self.assertEqual(run.returncode, 0, run.stderr)
        with open(mesh) as f:
            text = f.read()
        for k in (fixed, end, bore):
            self.assertIn("*NSET, NSET=Face%d\n" % k, text)
            self.assertIn("*ELSET, ELSET=Face%d_Elements\n" % k, text)
            self.assertIn("*SURFACE, NAME=Face%d_Surface, TYPE=ELEMENT\n" % k, text)
        deck = os.path.join(self.tmp, "deck.inp")
        with open(deck, "w") as f:
            f.write("*INCLUDE, INPUT=bored.inp\n"
                    "*MATERIAL, NAME=Steel\n*ELASTIC\n210000, 0.3\n"
                    "*SOLID SECTION, ELSET=Eall, MATERIAL=Steel\n"
                    "*STEP\n*STATIC\n"
                    "*BOUNDARY\nFace%d, 1, 3, 0.\n"
                    "*DSLOAD\nFace%d_Surface, P, %g\nFace%d_Surface, P, %g\n"
                    "*NODE PRINT, NSET=Face%d, TOTALS=ONLY\nRF\n"
                    "*END STEP\n" % (fixed, end, P_END, bore, P_HOLE, fixed))
        solve = subprocess.run([self.ccx, "-i", "deck"], cwd=self.tmp, capture_output=True,
                               text=True, timeout=300)
        self.assertEqual(solve.returncode, 0, solve.stdout[-2000:])
        self.assertNotIn("*ERROR", solve.stdout)
        forces = total_forces(os.path.join(self.tmp, "deck.dat"))
        self.assertIsNotNone(forces, "ccx wrote no total force")
        fx, fy, fz = forces
        hole_load = P_HOLE * 2 * 3.141592653589793 * 3 * 10  # the bore's area times its pressure
        self.assertAlmostEqual(fx, P_END * END_AREA, delta=1e-6 * P_END * END_AREA)
        self.assertLess(abs(fy), 1e-6 * hole_load)
        self.assertLess(abs(fz), 0.01 * hole_load)


if __name__ == "__main__":
    unittest.main()
