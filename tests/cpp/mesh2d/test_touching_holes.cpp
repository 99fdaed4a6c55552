// Holes and sub-domains that touch their polygon's boundary (issue 20): a notch at a corner, a hole
// meeting the boundary at one node, a hole whose side runs along part of a boundary edge (its
// nodes not in the outer polygon), a hole touching the boundary at two nodes (the region falls
// apart in two), two holes touching each other, and two squares side by side sharing part of an
// edge. Each meshes validly: counter-clockwise triangles, no overlap, the net area covered, no
// triangle in a hole, and conforming (an edge inside the domain has a triangle on each side).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>

#include "bisect/io.hpp"
#include "geom/predicates.hpp"
#include "mesh2d/planar_mesher.hpp"
#include "mesh2d/tri_quality.hpp"

namespace bisect::mesh2d {
namespace {

Poly2Input poly2(const std::string& text) {
  std::istringstream in(text);
  return read_poly2(in, "test.poly2");
}

// The mesh is valid, covers `area`, and its boundary edges (one triangle) add up to `perimeter`:
// a hanging node or a gap would leave an edge with one triangle inside the domain and lengthen it.
void expect_valid(const TriMesh2& m, double area, double perimeter, const std::string& what) {
  std::map<std::pair<Index, Index>, int> directed;
  for (const auto& T : m.tris) {
    EXPECT_GT(geom::orient2d(m.nodes[T[0]], m.nodes[T[1]], m.nodes[T[2]]), 0) << what;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(++directed[std::make_pair(T[k], T[(k + 1) % 3])], 1) << what;
  }
  double boundary = 0;
  for (const auto& [e, uses] : directed)
    if (!directed.count({e.second, e.first})) boundary += (m.nodes[e.first] - m.nodes[e.second]).norm();
  EXPECT_NEAR(total_area(m), area, 1e-9 * area) << what;
  EXPECT_NEAR(boundary, perimeter, 1e-9 * perimeter) << what;
}

struct Case {
  const char* what;
  std::string text;
  double area, perimeter;
  Vec2 lo, hi;  // a hole's box: no triangle's centroid inside (lo == hi: none)
};

TEST(TouchingHoles, NotchesMeshValidly) {
  const std::vector<Case> cases = {
      {"a sub-domain in the corner (tests/data)", "", 4, 8, {0, 0}, {0, 0}},
      {"a hole at a corner, listed in the outer polygon",
       "200\n7 2\n6 -4\n0 0\n2 0\n2 2\n0 2\n1 0\n1 1\n0 1\n1 5 2 3 4 7\n1 5 6 7\n", 3, 8, {0, 0}, {1, 1}},
      {"a hole at a corner, its other nodes on the edges but not in the outer polygon",
       "200\n7 2\n4 -4\n0 0\n2 0\n2 2\n0 2\n1 0\n1 1\n0 1\n1 2 3 4\n1 5 6 7\n", 3, 8, {0, 0}, {1, 1}},
      {"a triangle hole touching at one node", "200\n7 2\n4 -3\n0 0\n1 0\n1 1\n0 1\n0.5 0.5\n0.8 0.3\n0.8 0.7\n1 2 3 4\n3 5 7\n",
       1 - 0.025, 4 + (Vec2(0.5, 0.5) - Vec2(1, 1)).norm() + (Vec2(0.8, 0.7) - Vec2(1, 1)).norm() + (Vec2(0.5, 0.5) - Vec2(0.8, 0.7)).norm(),
       {0.76, 0.725}, {0.775, 0.74}},
      {"a hole on part of an edge", "200\n8 2\n4 -4\n0 0\n1 0\n1 1\n0 1\n0.25 0\n0.75 0\n0.75 0.5\n0.25 0.5\n1 2 3 4\n5 6 7 8\n", 0.75,
       5, {0.25, 0}, {0.75, 0.5}},
      {"a diamond hole touching two sides: two pieces",
       "300\n8 2\n4 -4\n0 0\n2 0\n2 2\n0 2\n0 1\n1 0.5\n2 1\n1 1.5\n1 2 3 4\n5 6 7 8\n", 3, 8 + 4 * std::sqrt(1.25),
       {0.8, 0.9}, {1.2, 1.1}},
      {"two holes touching each other at one node",
       "300\n11 3\n4 -4 -3\n0 0\n3 0\n3 3\n0 3\n1 1\n1.5 1\n1.5 1.5\n1 1.5\n2 1.5\n2 2\n1.5 2\n1 2 3 4\n5 6 7 8\n7 9 10\n", 9 - 0.25 - 0.125,
       12 + 2 + 1 + std::sqrt(0.5), {1.05, 1.05}, {1.45, 1.45}},
      {"two squares side by side sharing part of an edge",
       "300\n8 2\n4 4\n0 0\n1 0\n1 1\n0 1\n1 0.25\n2 0.25\n2 0.75\n1 0.75\n1 2 3 4\n5 6 7 8\n", 1.5, 6, {0, 0}, {0, 0}},
  };
  for (const Case& c : cases) {
    const Poly2Input in = c.text.empty() ? read_poly2(std::string(BISECT_TEST_DATA) + "/square-corner-subdomain.poly2") : poly2(c.text);
    for (std::int64_t n : {0, 50, 2000}) {
      const std::string what = std::string(c.what) + " at " + std::to_string(n);
      TriMesh2 m;
      PlanarStats st;
      ASSERT_NO_THROW(m = mesh_planar(in, {n}, &st)) << what;
      expect_valid(m, c.area, c.perimeter, what);
      EXPECT_GE(st.min_angle_deg, 15.0) << what;
      for (const auto& T : m.tris) {
        const Vec2 g = (m.nodes[T[0]] + m.nodes[T[1]] + m.nodes[T[2]]) / 3;
        EXPECT_FALSE((g.array() > c.lo.array()).all() && (g.array() < c.hi.array()).all()) << what << ": a triangle in the hole";
      }
    }
  }
}

// The corner sub-domain is its own region: its triangles are region 2 and cover its unit square.
TEST(TouchingHoles, CornerSubdomainIsItsOwnRegion) {
  const Poly2Input in = read_poly2(std::string(BISECT_TEST_DATA) + "/square-corner-subdomain.poly2");
  const TriMesh2 m = mesh_planar(in, {500});
  double sub = 0;
  for (std::size_t t = 0; t < m.tris.size(); ++t) {
    const auto& T = m.tris[t];
    const Vec2 g = (m.nodes[T[0]] + m.nodes[T[1]] + m.nodes[T[2]]) / 3;
    EXPECT_EQ(m.tri_region[t] == 1, g.x() < 1 && g.y() < 1);
    const Vec2 u = m.nodes[T[1]] - m.nodes[T[0]], v = m.nodes[T[2]] - m.nodes[T[0]];
    if (m.tri_region[t] == 1) sub += 0.5 * (u.x() * v.y() - u.y() * v.x());
  }
  EXPECT_NEAR(sub, 1.0, 1e-9);
}

}  // namespace
}  // namespace bisect::mesh2d
