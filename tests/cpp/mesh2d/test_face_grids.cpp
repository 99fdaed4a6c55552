// Face grids of polyhedral models (thesis 5.2): every face meshed in its own plane, every edge
// discretised once, so that the grids of a region's faces (or of a convex cell's faces) close up
// into one conforming triangulated surface; faces with holes keep them open.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>

#include "bisect/errors.hpp"
#include "bisect/io.hpp"
#include "bisect/polyhedral_model.hpp"
#include "mesh2d/face_grids.hpp"
#include "mesh2d/spacing.hpp"
#include "generated_solids.hpp"
#include "poly_shapes.hpp"

namespace bisect::mesh2d {
namespace {

double tri_area(const FaceGrids& g, const std::array<Index, 3>& t) {
  return 0.5 * (g.nodes[t[1]] - g.nodes[t[0]]).cross(g.nodes[t[2]] - g.nodes[t[0]]).norm();
}

// The faces (with their outward flags) form a closed conforming surface: oriented outwards,
// every directed triangle edge occurs exactly once and its reverse exactly once.
void expect_closed(const FaceGrids& g, const PolyhedralModel& m, const std::vector<Index>& faces, const std::vector<char>& outward,
                   const std::string& what) {
  std::map<std::pair<Index, Index>, int> directed;
  for (std::size_t k = 0; k < faces.size(); ++k)
    for (const auto& t : g.face_tris[faces[k]]) {
      const std::array<Index, 3> o = outward[k] ? t : std::array<Index, 3>{t[0], t[2], t[1]};
      for (int e = 0; e < 3; ++e) ++directed[{o[e], o[(e + 1) % 3]}];
    }
  std::size_t bad = 0;
  for (const auto& [e, n] : directed) {
    const auto rev = directed.find({e.second, e.first});
    if (n != 1 || rev == directed.end() || rev->second != 1) ++bad;
  }
  EXPECT_EQ(bad, 0u) << what << ": edges used other than once each way";
  (void)m;
}

// Each face: triangles counter-clockwise around its normal, lying in its plane, covering its area.
void expect_faces_covered(const FaceGrids& g, const PolyhedralModel& m) {
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    if (!m.faces[f].alive) {
      EXPECT_TRUE(g.face_tris[f].empty());
      continue;
    }
    double area = 0;
    for (const auto& t : g.face_tris[f]) {
      const Vec3 n = (g.nodes[t[1]] - g.nodes[t[0]]).cross(g.nodes[t[2]] - g.nodes[t[0]]);
      EXPECT_GT(n.dot(m.faces[f].normal), 0) << "face " << f;
      for (Index v : t) EXPECT_NEAR(m.faces[f].normal.dot(g.nodes[v]), m.faces[f].offset, 1e-9 * m.size) << "face " << f;
      area += tri_area(g, t);
    }
    EXPECT_NEAR(area, m.face_area(static_cast<Index>(f)), 1e-10 * m.size * m.size) << "face " << f;
  }
}

void expect_regions_closed(const FaceGrids& g, const PolyhedralModel& m) {
  for (std::size_t r = 0; r < m.regions.size(); ++r) {
    std::vector<Index> faces;
    std::vector<char> outward;
    for (Index f : m.live_faces(static_cast<Index>(r))) {
      faces.push_back(f);
      outward.push_back(m.faces[f].back == static_cast<Index>(r));  // the normal leaves the region
    }
    expect_closed(g, m, faces, outward, "region " + std::to_string(r));
  }
}

TEST(FaceGrids, CubeAtRequestedCount) {
  const PolyhedralModel m = prepare_model(test::poly(test::unit_cube()));
  for (std::int64_t n : {24, 600, 6000}) {
    FaceGridOptions opt;
    opt.elements = n;
    const FaceGrids g = mesh_faces(m, opt);
    EXPECT_NEAR(static_cast<double>(g.triangles), static_cast<double>(n), 0.15 * n) << n;
    EXPECT_GE(g.min_angle_deg, 20.0) << n;
    expect_faces_covered(g, m);
    expect_regions_closed(g, m);
    // every edge of the cube carries the same number of inner nodes (its two faces share them)
    for (const auto& [e, inner] : g.edge_nodes)
      EXPECT_NEAR(static_cast<double>(inner.size() + 1), 1 / g.h, 1.0) << e.first << "-" << e.second;
  }
}

// A node's spacing hint (PolyInput::node_spacing): an edge between two hinted nodes keeps the
// hint all along, an edge with one hinted end grades from it towards h, the rest stay at h.
TEST(FaceGrids, NodeSpacingHintsRefineTheirEdges) {
  PolyInput in = test::poly(test::unit_cube());
  const std::size_t n = in.nodes.size();
  in.node_spacing.assign(n, 0.0);
  in.node_spacing[0] = in.node_spacing[1] = 0.05;  // the ends of one edge of the cube
  const PolyhedralModel m = prepare_model(in);
  FaceGridOptions opt;
  opt.size = 0.25;
  const FaceGrids g = mesh_faces(m, opt);
  expect_faces_covered(g, m);
  expect_regions_closed(g, m);
  const double len01 = (m.nodes[0] - m.nodes[1]).norm();
  std::size_t both = 0, one = 0, none = 0;
  for (const auto& [e, inner] : g.edge_nodes) {
    const bool a = e.first < 2, b = e.second < 2;
    const double len = (m.nodes[e.first] - m.nodes[e.second]).norm();
    if (a && b) {
      EXPECT_NEAR(static_cast<double>(inner.size() + 1), len01 / 0.05, 1.0);
      ++both;
    } else if (a || b) {
      // finer than h near the hinted end, so more pieces than h alone gives, far fewer than the hint's
      EXPECT_GT(inner.size() + 1, std::size_t(std::lround(len / 0.25)));
      EXPECT_LT(static_cast<double>(inner.size() + 1), len / 0.05);
      ++one;
    } else {
      EXPECT_NEAR(static_cast<double>(inner.size() + 1), len / 0.25, 1.0);
      ++none;
    }
  }
  EXPECT_EQ(both, 1u);
  EXPECT_GT(one, 0u);
  EXPECT_GT(none, 0u);
  // one spacing per node, or none
  in.node_spacing.pop_back();
  EXPECT_THROW(prepare_model(in), InputError);
}

TEST(FaceGrids, ShortEdgesOfCutsRefineLessThanShortCreases) {
  // the unit cube's top face cut as the decomposition would: along x = 0.5, then from (0.5, 0.5)
  // to the right side and from (0.5, 0.52) to the left, so that the cuts leave an edge 0.02 long
  // across the face; and one of the cube's own edges split 0.02 below a corner
  PolyhedralModel m = prepare_model(test::poly(test::unit_cube()));
  auto node = [&](double x, double y, double z) {
    for (std::size_t v = 0; v < m.nodes.size(); ++v)
      if ((m.nodes[v] - Vec3(x, y, z)).norm() < 1e-12) return static_cast<Index>(v);
    ADD_FAILURE() << "no node at " << x << " " << y << " " << z;
    return Index{0};
  };
  auto face_with = [&](Index a, Index b) {  // the live top face whose outer loop holds both nodes
    for (Index f : m.faces_of_node(a)) {
      const auto& l = m.faces[f].loops[0];
      if (m.faces[f].normal.z() > 0.9 && std::find(l.begin(), l.end(), b) != l.end()) return f;
    }
    ADD_FAILURE() << "no top face with nodes " << a << " and " << b;
    return Index{0};
  };
  const Index p1 = m.insert_vertex_in_edge(node(0, 0, 1), node(1, 0, 1), {0.5, 0, 1});
  const Index p2 = m.insert_vertex_in_edge(node(0, 1, 1), node(1, 1, 1), {0.5, 1, 1});
  m.split_face(face_with(p1, p2), {{{p1, p2}}});
  const Index m1 = m.insert_vertex_in_edge(p1, p2, {0.5, 0.5, 1});
  const Index q1 = m.insert_vertex_in_edge(node(1, 0, 1), node(1, 1, 1), {1, 0.5, 1});
  m.split_face(face_with(m1, q1), {{{m1, q1}}});
  const Index m2 = m.insert_vertex_in_edge(m1, p2, {0.5, 0.52, 1});
  const Index q2 = m.insert_vertex_in_edge(node(0, 0, 1), node(0, 1, 1), {0, 0.52, 1});
  m.split_face(face_with(m2, q2), {{{m2, q2}}});
  const Index c = m.insert_vertex_in_edge(node(0, 0, 0), node(0, 0, 1), {0, 0, 0.98});
  FaceGridOptions opt;
  opt.size = 0.25;
  const FaceGrids g = mesh_faces(m, opt);
  expect_faces_covered(g, m);
  expect_regions_closed(g, m);
  // the cuts' short edge asks three times its length of its ends (a third of 0.25 would be more)
  EXPECT_NEAR(g.spacing[m1], 0.06, 1e-9);
  EXPECT_NEAR(g.spacing[m2], 0.06, 1e-9);
  EXPECT_NEAR(cut_edge_spacing(0.02, 0.25), 0.06, 1e-15);
  EXPECT_NEAR(cut_edge_spacing(0.05, 0.3), 0.1, 1e-15);  // a third of the face's spacing
  EXPECT_NEAR(cut_edge_spacing(0.2, 0.3), 0.2, 1e-15);   // no less than its length
  // a piece of the input's own edge keeps its length, and so does the corner beside it
  EXPECT_NEAR(g.spacing[c], 0.02, 1e-9);
  EXPECT_NEAR(g.spacing[node(0, 0, 1)], 0.02, 1e-9);
  // the top face's four pieces: fewer and better triangles than if the cuts' edge asked its
  // length (76 triangles, smallest angle 10.4 degrees; now 52 and 11.5)
  std::size_t top = 0;
  double smallest = 180;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    if (!m.faces[f].alive || m.faces[f].normal.z() < 0.9 || m.nodes[m.faces[f].loops[0][0]].z() < 0.5) continue;
    for (const auto& t : g.face_tris[f]) {
      ++top;
      for (int k = 0; k < 3; ++k) {
        const Vec3 u = g.nodes[t[(k + 1) % 3]] - g.nodes[t[k]], w = g.nodes[t[(k + 2) % 3]] - g.nodes[t[k]];
        smallest = std::min(smallest, std::atan2(u.cross(w).norm(), u.dot(w)) * 180 / M_PI);
      }
    }
  }
  EXPECT_LE(top, 60u);
  EXPECT_GE(smallest, 11.0);
}

TEST(FaceGrids, FaceWithHoleAndShortEdgesGrade) {
  // the re-entrant box (thesis 6.13, example 2): its top face has the pocket's mouth as a hole
  const PolyhedralModel m = prepare_model(read_poly(std::string(BISECT_TEST_DATA) + "/reentry-box.poly"));
  FaceGridOptions opt;
  opt.size = 0.1;
  const FaceGrids g = mesh_faces(m, opt);
  expect_faces_covered(g, m);
  expect_regions_closed(g, m);
  EXPECT_GE(g.min_angle_deg, 20.0);
  // no triangle of the top face (z = 1) covers the mouth of the pocket
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    if (m.faces[f].loops.size() < 2) continue;
    for (const auto& t : g.face_tris[f]) {
      const Vec3 c = (g.nodes[t[0]] + g.nodes[t[1]] + g.nodes[t[2]]) / 3;
      EXPECT_FALSE(c.x() > 0.25 && c.x() < 0.75 && c.y() > 0.25 && c.y() < 0.75) << "a triangle in the hole";
    }
  }
}

TEST(FaceGrids, InterfaceSharedByBothRegions) {
  // the thesis's cube with a cavity beside a second cube: the common face is meshed once
  const PolyhedralModel m = prepare_model(read_poly(std::string(BISECT_TEST_DATA) + "/cube-cavity-adjacent-cube.poly"));
  FaceGridOptions opt;
  opt.elements = 3000;
  const FaceGrids g = mesh_faces(m, opt);
  expect_faces_covered(g, m);
  expect_regions_closed(g, m);
  std::size_t interfaces = 0;
  for (std::size_t f = 0; f < m.faces.size(); ++f) interfaces += m.faces[f].alive && m.faces[f].front >= 0 && m.faces[f].back >= 0;
  EXPECT_GE(interfaces, 1u);
}

TEST(FaceGrids, EveryConvexCellOfADecompositionIsClosed) {
  // the grids the 3D generator fills: per cell, its faces' grids close up, cut faces included
  for (const std::string& text : {test::l_prism(), std::string()}) {
    const PolyInput in = text.empty() ? read_poly(std::string(BISECT_TEST_DATA) + "/reentry-box.poly") : test::poly(text);
    const Decomposition d = decompose(in);
    FaceGridOptions opt;
    opt.elements = 4000;
    const FaceGrids g = mesh_faces(d.model, opt);
    expect_faces_covered(g, d.model);
    for (std::size_t c = 0; c < d.cells.size(); ++c) expect_closed(g, d.model, d.cells[c].faces, d.cells[c].outward, "cell " + std::to_string(c));
    EXPECT_GE(g.min_angle_deg, 20.0) << (text.empty() ? "reentry box" : "L prism");
  }
}

// Random CSG solids (unions of boxes and rotated prisms, some hollow), decomposed: the grids of
// every cell close up. BISECT_RANDOM_SOLIDS overrides the count (default 200).
TEST(FaceGrids, RandomCsgSolidsGiveClosedCellGrids) {
  const char* env = std::getenv("BISECT_RANDOM_SOLIDS");
  const int n = env ? std::atoi(env) : 200;
  int meshed = 0, skipped = 0;
  for (int seed = 1; seed <= n; ++seed) {
    std::string what;
    const PolyInput in = testing::random_csg_polyhedron(static_cast<std::uint64_t>(seed), &what, nullptr);
    Decomposition d;
    try {
      d = decompose(in);
    } catch (const Error&) {  // the decomposition's own test counts these
      ++skipped;
      continue;
    }
    FaceGridOptions opt;
    opt.elements = 3000;
    FaceGrids g;
    try {
      g = mesh_faces(d.model, opt);
    } catch (const Error& e) {
      ADD_FAILURE() << what << ": " << e.what();
      break;
    }
    expect_faces_covered(g, d.model);
    for (std::size_t c = 0; c < d.cells.size(); ++c)
      expect_closed(g, d.model, d.cells[c].faces, d.cells[c].outward, what + " cell " + std::to_string(c));
    ++meshed;
    if (HasFailure()) break;
  }
  std::cout << "face grids of random CSG solids: " << meshed << " meshed, " << skipped << " not decomposed\n";
  EXPECT_GE(meshed, n * 9 / 10);
}

TEST(FaceGrids, OptionsAndCancel) {
  const PolyhedralModel m = prepare_model(test::poly(test::unit_cube()));
  EXPECT_THROW(mesh_faces(m, {}), InputError);
  FaceGridOptions opt;
  opt.size = 0.25;
  int calls = 0;
  opt.progress = [&](double) { return ++calls < 3; };
  EXPECT_THROW(mesh_faces(m, opt), Cancelled);
  EXPECT_EQ(calls, 3);
  opt.progress = nullptr;
  opt.optimize = false;
  const FaceGrids g = mesh_faces(m, opt);
  EXPECT_DOUBLE_EQ(g.h, 0.25);
  expect_regions_closed(g, m);
}

}  // namespace
}  // namespace bisect::mesh2d
