// The optimiser's work lists: stars found by walking, the log of changed tetrahedra, the key
// bound that lets sliver repair start from a list, and that list missing no sliver.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "optimize/grid_cube.hpp"
#include "optimize/min_max_passes.hpp"
#include "optimize/node_stars.hpp"
#include "optimize/sliver_repair.hpp"
#include "tet/cell_fill.hpp"
#include "tet/tet_complex.hpp"

namespace bisect::optimize {
namespace {

using tet::Tet;
using tet::TetComplex;

constexpr double kPi = 3.14159265358979323846;

double worst_cos(const std::vector<Vec3>& X, const Tet& t) { return worst_dihedral_cos(X[t[0]], X[t[1]], X[t[2]], X[t[3]]); }

TEST(WorkLists, StarWalkFindsWhatAScanFinds) {
  GridCube g;
  TetComplex cx(g.X);
  cx.build(g.tets);
  cx.improve_all(1 << 30);  // reused slots and fresh ids, as in the optimiser
  std::size_t checked = 0;
  for (Index v = 0; v < static_cast<Index>(g.X.size()); ++v) {
    std::vector<Index> scan = cx.tets_at(v);
    ASSERT_FALSE(scan.empty());
    for (Index t0 : {scan.front(), scan.back()}) {
      std::vector<Index> walk = star(cx, v, t0);
      EXPECT_EQ(walk.front(), t0);
      std::sort(walk.begin(), walk.end());
      EXPECT_EQ(walk, scan) << "node " << v;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2 * g.X.size());
}

TEST(WorkLists, LogHoldsEveryMadeOrMovedTetrahedron) {
  GridCube g;
  TetComplex cx(g.X);
  cx.build(g.tets);
  std::vector<Index> log;
  cx.changed = &log;
  const std::int64_t flips = cx.improve_all(1 << 30);
  ASSERT_GT(flips, 0);
  std::size_t differ = 0;
  for (std::size_t t = 0; t < cx.tet.size(); ++t)
    if (cx.alive[t] && (t >= g.tets.size() || cx.tet[t] != g.tets[t])) {
      ++differ;
      EXPECT_NE(std::find(log.begin(), log.end(), static_cast<Index>(t)), log.end()) << t;
    }
  EXPECT_GT(differ, 0u);
  log.clear();
  cx.moved({3, 5});
  EXPECT_EQ(log, (std::vector<Index>{3, 5}));
  // below_key: live ones under the key, sorted, once each
  const double key = cx.q[5] * 1.000001;
  const std::vector<Index> listed = below_key(cx, {5, 3, 5}, key);
  EXPECT_EQ(listed, cx.q[3] < key ? (std::vector<Index>{3, 5}) : (std::vector<Index>{5}));
  for (Index t : all_below_key(cx, 0.1)) EXPECT_LT(cx.q[t], 0.1);
}

// The passes (min_max_passes.hpp) hand the caller's log every tetrahedron they made or moved,
// those their own work lists took in between included: the sliver repair's second go finds the
// slivers from that log (a log that held only the last pass's changes missed 21 of 57 on
// part.stl at 10^5).
TEST(WorkLists, PassesLogEveryChange) {
  GridCube g(8, 0.02);
  const std::vector<Vec3> before = g.X;
  TetComplex cx(g.X);
  cx.build(g.tets);
  std::vector<std::array<Index, 4>> had;
  for (Tet t : g.tets) {
    std::sort(t.begin(), t.end());
    had.push_back(t);
  }
  std::sort(had.begin(), had.end());
  std::vector<Index> log;
  cx.changed = &log;
  const PassCounts n = min_max_passes(cx, g.X, g.fixed, 3, 3, nullptr);
  ASSERT_GT(n.flips, 0);
  ASSERT_GT(n.moves, 0);
  std::sort(log.begin(), log.end());
  std::size_t changed = 0;
  for (std::size_t t = 0; t < cx.tet.size(); ++t) {
    if (!cx.alive[t]) continue;
    Tet k = cx.tet[t];
    std::sort(k.begin(), k.end());
    bool differs = !std::binary_search(had.begin(), had.end(), k);
    for (Index v : k) differs = differs || !(g.X[v] == before[v]);
    if (!differs) continue;
    ++changed;
    EXPECT_TRUE(std::binary_search(log.begin(), log.end(), static_cast<Index>(t))) << "tetrahedron " << t;
  }
  EXPECT_GT(changed, 0u);
}

// A dihedral angle under theta bounds the key by tan(theta): on random, flattened and needle
// tetrahedra, no tetrahedron with a small dihedral angle is keyed above the bound.
TEST(WorkLists, SliverKeyBoundsEveryTetrahedronWithASmallDihedralAngle) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::size_t small = 0, above = 0;
  for (int i = 0; i < 200000; ++i) {
    std::vector<Vec3> X(4);
    const double squash = std::pow(10.0, -3 * (i % 4) / 3.0);  // 1, 0.1, 0.01, 0.001
    for (Vec3& p : X) p = Vec3(u(rng), u(rng), u(rng) * (i % 8 < 4 ? squash : 1));
    if (i % 8 >= 4) X[3] = X[2] + squash * Vec3(u(rng), u(rng), u(rng));  // a short edge: needles, wedges
    Tet t{0, 1, 2, 3};
    if (!tet::positive(X, t)) std::swap(t[0], t[1]);
    if (!tet::positive(X, t)) continue;
    for (double deg : {5.0, 10.0, 20.0}) {
      if (worst_cos(X, t) <= std::cos(deg * kPi / 180)) continue;
      ++small;
      EXPECT_LE(tet::tet_angle_key(X, t), sliver_key(deg)) << i << " " << deg;
    }
    if (tet::tet_angle_key(X, t) > sliver_key(10)) ++above;
  }
  EXPECT_GT(small, 10000u);
  EXPECT_GT(above, 100u);  // not a bound every tetrahedron meets
}

// The key list holds every sliver of a real filling; repair from it improves them and logs all
// it changes for the caller.
TEST(WorkLists, SliverRepairFromTheKeyList) {
  GridCube g;
  const std::vector<Vec3> start = g.X;
  TetComplex cx(g.X);
  cx.build(g.tets);
  const std::vector<Index> listed = all_below_key(cx, sliver_key(10));
  std::size_t slivers = 0;
  for (std::size_t t = 0; t < g.tets.size(); ++t)
    if (worst_cos(g.X, g.tets[t]) > std::cos(10 * kPi / 180)) {
      ++slivers;
      EXPECT_TRUE(std::binary_search(listed.begin(), listed.end(), static_cast<Index>(t))) << "sliver " << t << " not listed";
    }
  ASSERT_GT(slivers, 5u) << "the grid leaves no sliver";
  std::vector<Index> log;
  cx.changed = &log;
  EXPECT_GT(repair_slivers(cx, g.X, g.fixed, 10, 4, listed), 0u);
  EXPECT_EQ(cx.changed, &log);  // the caller's log is handed back
  std::sort(log.begin(), log.end());
  std::size_t left = 0, differ = 0;
  for (std::size_t t = 0; t < cx.tet.size(); ++t) {
    if (!cx.alive[t]) continue;
    const Tet& u = cx.tet[t];
    EXPECT_TRUE(tet::positive(g.X, u));
    left += worst_cos(g.X, u) > std::cos(10 * kPi / 180);
    bool same = t < g.tets.size() && u == g.tets[t];
    for (Index v : u) same = same && static_cast<std::size_t>(v) < start.size() && g.X[v] == start[v];
    if (!same) {
      ++differ;
      EXPECT_TRUE(std::binary_search(log.begin(), log.end(), static_cast<Index>(t))) << "changed " << t << " not logged";
    }
  }
  EXPECT_GT(differ, 0u);
  EXPECT_LT(left, slivers);
  for (std::size_t v = 0; v < 8; ++v) EXPECT_EQ(g.X[v], start[v]);
}

}  // namespace
}  // namespace bisect::optimize
