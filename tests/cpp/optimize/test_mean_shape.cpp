// The passes for the mean shape (optimize/mean_shape.hpp): they raise the mean α̂, never lower a
// smallest solid angle nor make a dihedral angle under 10.5 degrees, move no fixed node, give
// the same mesh on every run and for every thread count; through the generator they raise the
// mean and keep the smallest angle of an L prism and a cube, and the nodes inside a plate's flat
// faces move in their planes only.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "bisect/generate.hpp"
#include "bisect/quality.hpp"
#include "bisect/validate.hpp"
#include "optimize/grid_cube.hpp"
#include "optimize/mean_shape.hpp"
#include "optimize/sliver_repair.hpp"
#include "poly_shapes.hpp"
#include "tet/tet_complex.hpp"

namespace bisect::optimize {
namespace {

using tet::Tet;
using tet::TetComplex;

constexpr double kPi = 3.14159265358979323846;

// A jittered 4 x 4 x 4 grid in the unit cube, improved by the min-max transformations: what the
// mean passes meet after the global passes.
struct JitteredCube : GridCube {
  JitteredCube() : GridCube(4, 0.04, 11) {}
};

struct Measures {
  double alpha_mean = 0, key_min = 1e300;
  std::size_t under = 0;  // tetrahedra with a dihedral angle under 10.5 degrees
};

Measures measure(const TetComplex& cx, const std::vector<Vec3>& X) {
  Measures m;
  std::size_t n = 0;
  for (std::size_t t = 0; t < cx.tet.size(); ++t) {
    if (!cx.alive[t]) continue;
    const Tet& u = cx.tet[t];
    EXPECT_TRUE(tet::positive(X, u)) << t;
    const TetQuality q = tet_quality(X[u[0]], X[u[1]], X[u[2]], X[u[3]]);
    m.alpha_mean += q.alpha, ++n;
    m.key_min = std::min(m.key_min, tet::tet_angle_key(X, u));
    if (worst_dihedral_cos(X[u[0]], X[u[1]], X[u[2]], X[u[3]]) > std::cos(10.5 * kPi / 180)) ++m.under;
  }
  m.alpha_mean /= static_cast<double>(n);
  return m;
}

TEST(MeanShape, RaisesTheMeanAndKeepsTheSmallestAngles) {
  JitteredCube c;
  TetComplex cx(c.X);
  cx.build(c.tets);
  cx.improve_all(1 << 30);
  const Measures before = measure(cx, c.X);
  const std::vector<Vec3> start = c.X;
  const MeanCounts n = improve_mean(cx, c.X, c.fixed, 2);
  const Measures after = measure(cx, c.X);
  EXPECT_GT(n.flips + n.moves, 0);
  EXPECT_GT(n.moves, 0);
  EXPECT_GT(after.alpha_mean, before.alpha_mean + 1e-4);
  EXPECT_GE(after.key_min, before.key_min);
  EXPECT_LE(after.under, before.under);
  for (std::size_t v = 0; v < 8; ++v) EXPECT_EQ(c.X[v], start[v]) << v;
  RecordProperty("alpha_mean", std::to_string(before.alpha_mean) + " -> " + std::to_string(after.alpha_mean));
  // the cached keys follow the moves and flips
  for (std::size_t t = 0; t < cx.tet.size(); ++t) {
    if (cx.alive[t]) {
      EXPECT_DOUBLE_EQ(cx.q[t], tet::tet_angle_key(c.X, cx.tet[t])) << t;
    }
  }
}

TEST(MeanShape, TheSameMeshOnEveryRun) {
  JitteredCube a, b;
  TetComplex ca(a.X), cb(b.X);
  ca.build(a.tets), cb.build(b.tets);
  ca.improve_all(1 << 30), cb.improve_all(1 << 30);
  improve_mean(ca, a.X, a.fixed, 2);
  improve_mean(cb, b.X, b.fixed, 2);
  EXPECT_EQ(a.X, b.X);
  EXPECT_EQ(ca.tets(), cb.tets());
}

// The node moves are tried colour by colour on several threads (no two nodes of a colour share
// a tetrahedron): the same mesh for 1, 2 and 4 threads, node for node. A 10 x 10 x 10 grid gives
// each colour hundreds of nodes, so the threads meet.
TEST(MeanShape, TheSameMeshForEveryThreadCount) {
  std::vector<Vec3> first_x;
  std::vector<Tet> first_tets;
  for (int threads : {1, 2, 4}) {
    GridCube c(10, 0.04, 5);
    TetComplex cx(c.X);
    cx.build(c.tets);
    cx.improve_all(1 << 30);
    const MeanCounts n = improve_mean(cx, c.X, c.fixed, 2, threads);
    EXPECT_GT(n.moves, 100) << threads;
    if (threads == 1) {
      first_x = c.X, first_tets = cx.tets();
      continue;
    }
    EXPECT_EQ(c.X, first_x) << threads << " threads";
    EXPECT_EQ(cx.tets(), first_tets) << threads << " threads";
  }
}

TEST(MeanShape, NoRoundsNoChange) {
  JitteredCube c;
  TetComplex cx(c.X);
  cx.build(c.tets);
  const std::vector<Vec3> start = c.X;
  const MeanCounts n = improve_mean(cx, c.X, c.fixed, 0);
  EXPECT_EQ(n.flips + n.moves, 0);
  EXPECT_EQ(c.X, start);
}

TEST(MeanShape, ThroughTheGeneratorTheMeanRisesAndTheSmallestAngleHolds) {
  for (const std::string& text : {test::unit_cube(), test::l_prism()})
    for (std::int64_t elements : {300, 3000}) {
      const PolyInput in = test::poly(text);
      QualitySummary q[2];
      std::int64_t changes[2] = {0, 0};
      for (int rounds : {0, 2}) {
        GenerateOptions opt;
        opt.sizing.elements = elements;
        opt.optimize.mean_rounds = rounds;
        GenerateStats st;
        const TetMesh m = generate_mesh(in, opt, &st);
        q[rounds / 2] = summarize_quality(element_quality(m));
        changes[rounds / 2] = st.mean_changes;
      }
      const std::string what = text.substr(0, 12) + " at " + std::to_string(elements);
      EXPECT_EQ(changes[0], 0) << what;
      EXPECT_GT(changes[1], 0) << what;
      EXPECT_GT(q[1].alpha.mean, q[0].alpha.mean) << what;
      EXPECT_GE(q[1].dihedral_min.min, std::min(q[0].dihedral_min.min, 10.5)) << what;
      EXPECT_LE(q[1].pct_dihedral_below_10 * static_cast<double>(q[1].tets), q[0].pct_dihedral_below_10 * static_cast<double>(q[0].tets) + 1e-9) << what;
    }
}

// A plate 4 x 3 x 1 at coarse counts, where most nodes are on its faces: with face moves some
// nodes inside a face move, in its plane only (the coordinate across it exactly as the grid left
// it), those on its edges and corners stay, the mean rises, and neither the smallest dihedral
// angle nor the boundary triangles' smallest angle falls below what the mesh had without them
// (or 10.5 and 30 degrees, the guards).
TEST(MeanShape, NodesInsideFlatFacesMoveInTheirPlanesOnly) {
  const PolyInput in = test::poly(test::prism({{0, 0}, {4, 0}, {4, 3}, {0, 3}}));
  const Vec3 extent(4, 3, 1);
  double gains = 0;
  for (std::int64_t elements : {900, 1000, 1100, 2800, 3000, 3200}) {
    TetMesh m[2];
    QualitySummary q[2];
    for (int moves : {0, 1}) {
      GenerateOptions opt;
      opt.sizing.elements = elements;
      opt.optimize.face_moves = moves == 1;
      m[moves] = generate_mesh(in, opt);
      EXPECT_TRUE(validate(m[moves]).empty()) << elements;
      q[moves] = summarize_quality(element_quality(m[moves]));
    }
    // the mean pass adds no node: the same ids in both
    ASSERT_EQ(m[0].nodes.size(), m[1].nodes.size()) << elements;
    std::vector<std::set<Index>> faces(m[0].nodes.size());
    for (std::size_t t = 0; t < m[0].num_tris(); ++t)
      for (int i = 0; i < 3; ++i) faces[m[0].tris[3 * t + i]].insert(m[0].tri_tag[t]);
    std::size_t moved = 0, face_nodes = 0;
    for (std::size_t v = 0; v < faces.size(); ++v) {
      const Vec3 &was = m[0].nodes[v], &now = m[1].nodes[v];
      if (faces[v].size() > 1) {
        EXPECT_EQ(now, was) << "node " << v << " on an edge moved, at " << elements;
      } else if (faces[v].size() == 1) {
        ++face_nodes;
        bool in_plane = false;  // the coordinate across its face: 0 or the plate's extent, kept exactly
        for (int k = 0; k < 3; ++k) in_plane = in_plane || ((was[k] == 0 || was[k] == extent[k]) && now[k] == was[k]);
        EXPECT_TRUE(in_plane) << "node " << v << " left its face, at " << elements;
        moved += now != was;
      }
    }
    // (measured: the mean rises by 0.0003 to 0.0010 at these six counts, a draw among close
    // counts: the gain at 1000 went from 0.0015 to 0.0007 when the count search moved its
    // spacing, so the bounds are on every count's sign and on their mean)
    EXPECT_GT(moved, face_nodes / 20) << elements;
    EXPECT_GT(q[1].alpha.mean, q[0].alpha.mean) << elements;
    gains += q[1].alpha.mean - q[0].alpha.mean;
    EXPECT_GE(q[1].dihedral_min.min, std::min(q[0].dihedral_min.min, 10.5)) << elements;
    EXPECT_GE(surface_min_angle_deg(m[1]), std::min(surface_min_angle_deg(m[0]), 30.0) - 1e-9) << elements;
    RecordProperty("alpha_mean_" + std::to_string(elements), std::to_string(q[0].alpha.mean) + " -> " + std::to_string(q[1].alpha.mean));
  }
  EXPECT_GT(gains / 6, 0.0004);  // measured 0.00057
}

}  // namespace
}  // namespace bisect::optimize
