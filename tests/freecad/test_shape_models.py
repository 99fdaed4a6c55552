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


def is_planar(face):
    return isinstance(face.Surface, Part.Plane)


def chordal_error(mesh, shape, sample=60):
    """How far the boundary triangles' chords lie from the B-rep: per curved face, the mean
    distance of a sample of its triangles' centroids to the face, times the face's area."""
    total = 0.0
    for k, face in enumerate(shape.Faces):
        if is_planar(face):
            continue
        tris = group(mesh, "Face%d_Faces" % (k + 1))
        gaps = []
        for e in tris[:: max(1, len(tris) // sample)]:
            corners = [np.array(tuple(mesh.getNodeById(v))) for v in mesh.getElementNodes(e)[:3]]
            gaps.append(face.distToShape(Part.Vertex(FreeCAD.Vector(*(sum(corners) / 3))))[0])
        total += face.Area * (float(np.mean(gaps)) if gaps else 0.0)
    return total


@unittest.skipUnless(os.path.isdir(MODELS), "../shared/models is not beside the checkout")
class SharedModelsTest(unittest.TestCase):
    def test_every_model(self):
        """Every shared model at R = 10^3, 10^4 (tetra10) and 10^5 (tetra4) through mesh_shape:
        valid (order 2: every Jacobian positive at the corners and Gauss points), near R or at
        the reported count floor, of the B-rep's volume within its grid's chordal error, with the
        nodes FreeCAD's getNodesByFace finds on every face lying on it."""
        files = model_files()
        self.assertGreaterEqual(len(files), 10, MODELS)
        figures = {}
        for path in files:
            name = os.path.basename(path)
            shape = Part.read(path)
            for R, order in ((1000, 2), (10000, 2), (100000, 1)):
                with self.subTest(model=name, R=R):
                    report = {}
                    mesh = shape_mesher.mesh_shape(shape, elements=R, order=order, report=report)
                    quality = bisectmesh.quality(mesh)
                    self.assertTrue(quality["valid"], quality["violations"][:5])
                    self.assertEqual(quality["order"], order)
                    stats = report["stats"]
                    if stats["count_floor"] > 0:
                        self.assertTrue(stats["count_floor_reason"])
                        self.assertGreater(quality["tets"], 1.2 * R)
                    else:
                        self.assertLess(abs(quality["tets"] - R), 0.2 * R, (name, R, quality["tets"]))
                    figures["%s@%d" % (name, R)] = {
                        "tets": quality["tets"], "dihedral_min": quality["dihedral_min"],
                        "pct_dihedral_below_10": quality["pct_dihedral_below_10"], "alpha_mean": quality["alpha_mean"],
                        "count_floor": stats["count_floor"], "core_seconds": report["seconds"]["core"],
                        "femmesh_seconds": report["seconds"]["femmesh"]}
                    if R == 100000:
                        continue
                    bound = 1.5 * chordal_error(mesh, shape) + 1e-9 * shape.Volume
                    self.assertLessEqual(abs(mesh_volume(mesh) - shape.Volume), bound)
                    for k, face in enumerate(shape.Faces):
                        found = mesh.getNodesByFace(face)
                        self.assertTrue(found, "Face%d has no nodes" % (k + 1))
                        # every node of the face's own group is one FreeCAD finds on it, but the
                        # mid-nodes of edges straightened for their Jacobian (counted by the stats)
                        own = set(group(mesh, "Face%d_Nodes" % (k + 1)))
                        self.assertLessEqual(len(own - set(found)), stats["straightened_edges"], "Face%d" % (k + 1))
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
            curved = sum(f.Area for f in solid.Faces if not is_planar(f))
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


class ResolutionHintsTest(unittest.TestCase):
    def test_resolution_hints_act(self):
        """A finer view Deviation (the resolution hints of thesis 2.3, as a chord deviation):
        smaller elements on the curved wall, whose chords it bounds, while the planar faces
        away from it keep theirs. Box 100 x 100 x 40 minus a cylinder of radius 30, size 8:
        Deviation 0.5 gives a chord deviation of 0.4 mm, which a spacing of 9.8 meets (the size,
        8, decides); 0.1 gives 0.08 mm, a spacing of 4.4 on the wall. Measured: the wall's mean
        triangle area 25.1 -> 8.9 mm^2, the sides' 23.0 both times."""
        box = Part.makeBox(100, 100, 40)
        shape = box.cut(Part.makeCylinder(30, 40, FreeCAD.Vector(50, 50, 0)))
        wall = next(k for k, f in enumerate(shape.Faces) if not is_planar(f))
        away = [k for k, f in enumerate(shape.Faces)
                if not any(e.isSame(g) for e in f.Edges for g in shape.Faces[wall].Edges)]
        self.assertEqual(len(away), 4)
        found = {}
        for deviation in (0.5, 0.1, None):
            resolution = None if deviation is None else {"deviation": deviation}
            mesh = shape_mesher.mesh_shape(shape, size=8.0, order=1, resolution=resolution)
            self.assertTrue(bisectmesh.quality(mesh)["valid"])
            planar = [a for k in away for a in triangle_areas(mesh, k)]
            found[deviation] = (float(np.mean(triangle_areas(mesh, wall))), float(np.mean(planar)))
        with open(os.path.join(artifacts_dir(), "resolution_hints.json"), "w") as out:
            json.dump({str(k): {"wall_mean_area": w, "side_mean_area": p} for k, (w, p) in found.items()}, out, indent=1)
        (wall_coarse, side_coarse), (wall_fine, side_fine) = found[0.5], found[0.1]
        self.assertLess(wall_fine, 0.5 * wall_coarse, found)
        self.assertLess(abs(side_fine / side_coarse - 1), 0.25, found)
        # without a resolution the curvature bound's default (12 elements a turn: 15.7 on the
        # wall) leaves the size to decide, as Deviation 0.5 does
        self.assertLess(abs(found[None][0] / wall_coarse - 1), 0.1, found)


if __name__ == "__main__":
    unittest.main()
