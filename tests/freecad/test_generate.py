"""bisectmesh._core.generate: the C++ pipeline in-process, as FreeCAD's Python calls it (no
subprocess, no files): valid meshes of the requested size, regions and shared interfaces,
second order, progress on the calling thread, cancellation, and errors that name the face."""

import threading
import unittest

import numpy as np

from bisectmesh import core


def box_nodes(x0, x1):
    """The 8 corners of the box [x0, x1] x [0, 1] x [0, 1]."""
    return [[x, y, z] for z in (0.0, 1.0) for y in (0.0, 1.0) for x in (x0, x1)]


# the faces of a box over box_nodes' numbering (+ offset), each a planar quadrilateral
BOX_FACES = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]


def two_boxes():
    """Two unit cubes side by side sharing the face x = 1: nodes, faces, regions."""
    nodes = np.array(box_nodes(0.0, 1.0) + box_nodes(1.0, 2.0)[1::2], float)
    # right box's corners: x = 1 ones are the left box's 1, 3, 5, 7; x = 2 ones are 8..11
    right = {0: 1, 1: 8, 2: 3, 3: 9, 4: 5, 5: 10, 6: 7, 7: 11}
    faces = [list(f) for f in BOX_FACES]
    shared = 5  # the left box's x = 1 face
    right_faces = []
    for k, f in enumerate(BOX_FACES):
        if k == 4:  # the right box's x = 1 face is the shared one
            right_faces.append(shared)
            continue
        faces.append([right[v] for v in f])
        right_faces.append(len(faces) - 1)
    return nodes, faces, [list(range(6)), right_faces]


class GenerateBindingTest(unittest.TestCase):
    def test_two_regions_valid_sized_and_sharing_their_interface(self):
        nodes, faces, regions = two_boxes()
        out = core().generate(nodes, faces, regions, elements=6000, threads=2)
        tets, region = out["tets"], out["region"]
        self.assertEqual(tets.shape[1], 4)
        self.assertLess(abs(len(tets) - 6000), 0.2 * 6000)
        self.assertEqual(core().validate(out["nodes"], tets), [])
        self.assertEqual(sorted(set(region.tolist())), [0, 1])
        self.assertEqual(out["stats"]["regions"], 2)
        self.assertEqual(out["stats"]["tets"], len(tets))
        # each region's volume is its cube's; the interface's nodes are used by both regions
        p = out["nodes"]
        a, b, c, d = (p[tets[:, k]] for k in range(4))
        vol = np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a)) / 6
        for r in (0, 1):
            self.assertAlmostEqual(vol[region == r].sum(), 1.0, places=9)
        on_interface = np.where(np.abs(p[:, 0] - 1.0) < 1e-12)[0]
        used = [set(tets[region == r].ravel().tolist()) for r in (0, 1)]
        self.assertGreater(len(on_interface), 20)
        for v in on_interface:
            self.assertIn(v, used[0])
            self.assertIn(v, used[1])
        # boundary triangles carry their input face: the shared face is among them
        self.assertIn(5, set(out["tri_tag"].tolist()))

    def test_second_order_and_the_same_mesh_on_any_thread_count(self):
        nodes, faces, regions = two_boxes()
        one = core().generate(nodes, faces, regions, elements=2000, threads=1)
        two = core().generate(nodes, faces, regions, elements=2000, threads=2, order=2)
        self.assertEqual(two["tets"].shape[1], 10)
        self.assertEqual(two["tris"].shape[1], 6)
        self.assertTrue(np.array_equal(two["tets"][:, :4], one["tets"]))
        mid = 0.5 * (two["nodes"][two["tets"][:, 0]] + two["nodes"][two["tets"][:, 1]])
        self.assertTrue(np.allclose(two["nodes"][two["tets"][:, 4]], mid, rtol=0, atol=1e-15))
        self.assertEqual(core().validate(two["nodes"], two["tets"]), [])

    def test_progress_on_the_calling_thread_and_cancel(self):
        nodes, faces, regions = two_boxes()
        me = threading.get_ident()
        seen = []
        core().generate(nodes, faces, regions, elements=3000, progress=lambda x: seen.append((x, threading.get_ident())))
        self.assertGreater(len(seen), 2)
        self.assertTrue(all(t == me for _, t in seen))
        fractions = [x for x, _ in seen]
        self.assertEqual(fractions, sorted(fractions))
        self.assertEqual(fractions[-1], 1.0)
        with self.assertRaises(core().Cancelled):
            core().generate(nodes, faces, regions, elements=3000, progress=lambda x: x < 0.5)

        class Mine(Exception):
            pass

        def fails(_):
            raise Mine("from the callback")

        with self.assertRaises(Mine):  # the callback's own exception, unchanged
            core().generate(nodes, faces, regions, elements=3000, progress=fails)

    def test_errors_name_the_face_node_or_region(self):
        nodes, faces, regions = two_boxes()
        with self.assertRaisesRegex(core().InputError, "face 2 refers to node 99"):
            bad = [list(f) for f in faces]
            bad[2][0] = 99
            core().generate(nodes, bad, regions, elements=1000)
        with self.assertRaisesRegex(core().InputError, "region 0 is not closed"):
            core().generate(nodes, faces, [regions[0][:5]], elements=1000)
        with self.assertRaisesRegex(core().InputError, r"give elements \(.*\) or size"):  # Python names, not -n/-s
            core().generate(nodes, faces, regions)
        with self.assertRaisesRegex(core().InputError, r"order must lie between 1 and 2 \(got 3\)"):
            core().generate(nodes, faces, regions, elements=1000, order=3)
        with self.assertRaisesRegex(core().InputError, "node_spacing needs one value per node"):
            core().generate(nodes, faces, regions, elements=1000, node_spacing=[0.1])
        with self.assertRaisesRegex(core().InputError, "node 3 asks for spacing"):
            hint = np.zeros(len(nodes))
            hint[3] = -1
            core().generate(nodes, faces, regions, elements=1000, node_spacing=hint)

    def test_node_spacing_hints_refine_near_their_nodes(self):
        nodes, faces, regions = two_boxes()
        plain = core().generate(nodes, faces, regions, size=2.0)
        hint = np.zeros(len(nodes))
        hint[:4] = 0.25  # the corners of the left box's face z = 0: its edges in 4 pieces each
        hinted = core().generate(nodes, faces, regions, size=2.0, node_spacing=hint)
        self.assertGreaterEqual(len(hinted["nodes"]), len(plain["nodes"]) + 4 * 3)
        low = np.array(hinted["nodes"])[:, 2] < 1e-12
        self.assertGreaterEqual(int(low.sum()), 4 + 4 * 3)


if __name__ == "__main__":
    unittest.main()
