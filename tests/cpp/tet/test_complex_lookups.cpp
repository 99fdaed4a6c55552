// The complex's lookups that the optimiser leans on at 10^6 tetrahedra: the build's face
// matching (through each face's smallest node), point location that stays near its start, and
// the optimiser's work lists (a long list marked instead of sorted).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "optimize/grid_cube.hpp"
#include "optimize/node_stars.hpp"
#include "tet/tet_test_meshes.hpp"
#include "tet/tet_complex.hpp"

namespace bisect::tet {
namespace {

using optimize::GridCube;

// every face and the tetrahedron across it with its face there (4 u + g, as TetComplex::adj holds
// them), as the build's definition says: faces with the same three nodes are neighbours, in pairs
// in the order of the tetrahedra
std::vector<Tet> pairs_by_map(const TetComplex& cx) {
  std::vector<Tet> want(cx.tet.size(), Tet{-1, -1, -1, -1});
  std::map<std::array<Index, 3>, std::pair<Index, int>> open;
  for (std::size_t t = 0; t < cx.tet.size(); ++t)
    for (int f = 0; f < 4; ++f) {
      const FaceKey k = [&] {
        const auto fv = cx.face(static_cast<Index>(t), f);
        return face_key(fv[0], fv[1], fv[2]);
      }();
      const std::array<Index, 3> key{k.a, k.b, k.c};
      const auto it = open.find(key);
      if (it == open.end()) {
        open.emplace(key, std::make_pair(static_cast<Index>(t), f));
      } else {
        want[t][f] = 4 * it->second.first + it->second.second;
        want[it->second.first][it->second.second] = static_cast<Index>(4 * t + f);
        open.erase(it);
      }
    }
  return want;
}

TEST(ComplexLookups, BuildMatchesEveryFaceWithTheTetrahedronAcross) {
  GridCube g(5, 0.02);
  TetComplex cx(g.X);
  cx.build(g.tets);
  ASSERT_GT(cx.tet.size(), 500u);
  std::size_t boundary = 0;
  for (std::size_t t = 0; t < cx.tet.size(); ++t)
    for (int f = 0; f < 4; ++f) {
      const Index n = cx.neighbour(t, f);
      if (n < 0) {
        ++boundary;
        continue;
      }
      const int back = cx.face_towards(n, static_cast<Index>(t));
      ASSERT_GE(back, 0) << "tetrahedron " << t << " face " << f;
      EXPECT_EQ(cx.neighbour_face(t, f), back) << "the way back, stored";
      const auto a = cx.face(static_cast<Index>(t), f), b = cx.face(n, back);
      const FaceKey ka = face_key(a[0], a[1], a[2]), kb = face_key(b[0], b[1], b[2]);
      EXPECT_TRUE(ka == kb) << "tetrahedron " << t << " face " << f;
    }
  EXPECT_EQ(boundary, 12u);  // the cube's two triangles a side, nothing else open
  EXPECT_EQ(cx.adj, pairs_by_map(cx));
}

TEST(ComplexLookups, AThirdTetrahedronOnAFaceIsLeftOpenAsInItsOrder) {
  // three tetrahedra on the face (0, 1, 2) (not a valid complex, but the pairing is defined):
  // the first two are neighbours, the third's face stays open
  const std::vector<Vec3> X{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {0.2, 0.2, 2}};
  TetComplex cx(X);
  cx.build({{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 1, 2, 5}});
  EXPECT_EQ(cx.adj, pairs_by_map(cx));
  EXPECT_EQ(cx.neighbour(0, 3), 1);
  EXPECT_EQ(cx.neighbour(2, 3), -1);
}

// the grid cube's tetrahedra with their centroid off the corner x, y > 0.55: an L-shaped complex,
// not convex, which a straight walk across the notch leaves
TetComplex l_shape(const GridCube& g) {
  std::vector<Tet> kept;
  for (const Tet& t : g.tets) {
    const Vec3 c = 0.25 * (g.X[t[0]] + g.X[t[1]] + g.X[t[2]] + g.X[t[3]]);
    if (!(c.x() > 0.55 && c.y() > 0.55)) kept.push_back(t);
  }
  TetComplex cx(g.X);
  cx.build(kept);
  return cx;
}

bool holds(const TetComplex& cx, Index t, const Vec3& p) {
  for (int f = 0; f < 4; ++f) {
    const auto fv = cx.face(t, f);
    if ((cx.X[fv[1]] - cx.X[fv[0]]).cross(cx.X[fv[2]] - cx.X[fv[0]]).dot(p - cx.X[fv[0]]) > 1e-12) return false;
  }
  return true;
}

TEST(ComplexLookups, NearLocationFindsAPointRoundANotchAndNoneOutside) {
  GridCube g(6, 0.02);
  const TetComplex cx = l_shape(g);
  // from a tetrahedron at x, y near 1, 0 to a point at 0, 1: the straight line crosses the notch
  Index start = -1;
  double best = 1e9;
  for (std::size_t t = 0; t < cx.tet.size(); ++t) {
    const Tet& k = cx.tet[t];
    const Vec3 c = 0.25 * (g.X[k[0]] + g.X[k[1]] + g.X[k[2]] + g.X[k[3]]);
    const double d = (c - Vec3(0.9, 0.9, 0.5)).norm();
    if (c.x() > 0.55 && c.y() < 0.5 && d < best) best = d, start = static_cast<Index>(t);
  }
  ASSERT_GE(start, 0);
  const Vec3 inside(0.45, 0.95, 0.5);
  for (bool near_only : {false, true}) {
    const Index t = cx.locate(inside, start, near_only);
    ASSERT_GE(t, 0) << "near_only " << near_only;
    EXPECT_TRUE(holds(cx, t, inside)) << "near_only " << near_only;
  }
  // in the notch, and beyond the cube: outside every tetrahedron
  for (const Vec3& outside : {Vec3(0.8, 0.8, 0.5), Vec3(1.3, 0.2, 0.5)})
    for (bool near_only : {false, true}) EXPECT_EQ(cx.locate(outside, start, near_only), -1) << "near_only " << near_only;
}

TEST(ComplexLookups, NearLocationOfAPointOutsideStopsAroundItsStart) {
  // the cube [0, 20]^3 as 20^3 cubes of 6 tetrahedra (48,000, test::cube_mesh): a point a fifth
  // of a cube outside a face, looked for from the tetrahedron nearest it, as the sliver repair's
  // trial nodes are. None holds it; the search gives up among the tetrahedra round the start
  // (by its distance bound, or after kNearSearch of them, whichever comes first), never over the
  // whole complex.
  const TetMesh grid = test::cube_mesh(20);
  std::vector<Tet> tets(grid.num_tets());
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (int i = 0; i < 4; ++i) tets[t][i] = grid.tet_node(t, i);
  const std::vector<Vec3>& X = grid.nodes;
  TetComplex cx(X);
  cx.build(tets);
  ASSERT_EQ(cx.tet.size(), 48000u);
  const Vec3 outside(20.2, 10.2, 10.4);
  Index start = -1;
  double best = 1e9;
  for (std::size_t t = 0; t < cx.tet.size(); ++t) {
    const Tet& k = cx.tet[t];
    const double d = (0.25 * (X[k[0]] + X[k[1]] + X[k[2]] + X[k[3]]) - outside).norm();
    if (d < best) best = d, start = static_cast<Index>(t);
  }
  ASSERT_GE(start, 0);
  EXPECT_EQ(cx.locate(outside, start, true), -1);
  EXPECT_GT(cx.near_searched, 0u);  // the walk met the boundary
  // about 700 tetrahedra lie within the distance bound round the start: the cap ends it first
  EXPECT_EQ(cx.near_searched, TetComplex::kNearSearch);
  // without near_only, the whole complex (every tetrahedron tried)
  EXPECT_EQ(cx.locate(outside, start, false), -1);
  // a point inside, from a start far off: the walk finds it (the bound is the near search's)
  const Vec3 inside(19.8, 10.2, 10.4);
  const Index t = cx.locate(inside, 0, true);
  ASSERT_GE(t, 0);
  EXPECT_TRUE(holds(cx, t, inside));
  EXPECT_EQ(cx.near_searched, 0u);
}

TEST(ComplexLookups, WorkListsLongAndShortAreTheSortedLiveOnesUnderTheKey) {
  GridCube g(6, 0.05);
  TetComplex cx(g.X);
  cx.build(g.tets);
  cx.improve_all(1 << 30);  // dead slots among the ids
  std::vector<double> keys;
  for (std::size_t t = 0; t < cx.tet.size(); ++t)
    if (cx.alive[t]) keys.push_back(cx.q[t]);
  std::sort(keys.begin(), keys.end());
  const double key = keys[keys.size() / 2];
  const auto reference = [&](const std::vector<Index>& ids) {
    std::vector<Index> out;
    for (std::size_t t = 0; t < cx.tet.size(); ++t)
      if (std::find(ids.begin(), ids.end(), static_cast<Index>(t)) != ids.end() && cx.alive[t] && cx.q[t] < key)
        out.push_back(static_cast<Index>(t));
    return out;
  };
  std::vector<Index> all;  // every id, live or not, twice, backwards: the long path
  for (Index t = static_cast<Index>(cx.tet.size()) - 1; t >= 0; --t) all.push_back(t), all.push_back(t);
  std::vector<Index> few{7, 3, 7, static_cast<Index>(cx.tet.size() - 1), 12};  // the short path
  for (const std::vector<Index>& ids : {all, few}) {
    const std::vector<Index> got = optimize::below_key(cx, ids, key);
    EXPECT_EQ(got, reference(ids));
  }
  EXPECT_FALSE(optimize::below_key(cx, all, key).empty());
  EXPECT_EQ(optimize::below_key(cx, all, key), optimize::all_below_key(cx, key));
}

}  // namespace
}  // namespace bisect::tet
