// The passes in blocks on several threads (block_pass.hpp): the same mesh for every thread
// count, a valid mesh filling the same space, held faces and fixed nodes kept, and quality near
// what the passes over the whole mesh on one thread give.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "bisect/errors.hpp"
#include "bisect/validate.hpp"
#include "optimize/block_pass.hpp"
#include "optimize/grid_cube.hpp"
#include "optimize/min_max_passes.hpp"
#include "optimize/optimize_mesh.hpp"
#include "tet/tet_complex.hpp"

namespace bisect::optimize {
namespace {

using tet::Tet;

struct Quality {
  double worst = std::numeric_limits<double>::max();  // smallest key (tet_angle_key)
  double mean = 0;                                    // mean key
  std::size_t poor = 0;                               // keys under kWorkBelowKey
};

Quality quality(const std::vector<Vec3>& X, const std::vector<Tet>& tets) {
  Quality q;
  for (const Tet& t : tets) {
    const double k = tet::tet_angle_key(X, t);
    q.worst = std::min(q.worst, k);
    q.mean += k / static_cast<double>(tets.size());
    q.poor += k < kWorkBelowKey;
  }
  return q;
}

double volume(const std::vector<Vec3>& X, const std::vector<Tet>& tets) {
  double v = 0;
  for (const Tet& t : tets) v += (X[t[1]] - X[t[0]]).dot((X[t[2]] - X[t[0]]).cross(X[t[3]] - X[t[0]])) / 6;
  return v;
}

std::vector<tet::FaceKey> faces_of(const std::vector<Tet>& tets) {
  std::vector<tet::FaceKey> out;
  for (const Tet& t : tets)
    for (int f = 0; f < 4; ++f) out.push_back(tet::face_key(t[(f + 1) % 4], t[(f + 2) % 4], t[(f + 3) % 4]));
  return out;
}

// A jittered grid in the unit cube, Delaunay filled: about 45,000 tetrahedra of every shape, and
// those at the cube's faces long and flat (its boundary is the corners' twelve triangles).
struct Case {
  GridCube cube{20, 0.3 / 21, 11};
  FaceSet held;  // the faces of some interior tetrahedra, chosen at random: they must stay
  Case() {
    std::mt19937 rng(5);
    std::uniform_int_distribution<std::size_t> pick(0, cube.tets.size() - 1);
    for (int i = 0; i < 60; ++i) {
      const Tet& t = cube.tets[pick(rng)];
      if (std::any_of(t.begin(), t.end(), [](Index v) { return v < 8; })) continue;
      for (const tet::FaceKey& k : faces_of({t})) held.insert(k);
    }
    cube.fixed[100] = cube.fixed[2000] = 1;  // two inner nodes that must not move
  }
};

TEST(BlockPass, ASmallMeshIsLeftAlone) {
  GridCube small(6, 0.01);
  std::vector<Tet> tets = small.tets;
  std::vector<Index> tags;
  FaceTags surface;
  const BlockPassCounts n = block_pass(tets, tags, small.X, small.fixed, {}, surface, BlockOptions{});
  EXPECT_EQ(n.blocks, 0u);
  EXPECT_TRUE(tets == small.tets);
}

TEST(BlockPass, TheSameValidMeshForEveryThreadCountWithHeldFacesAndFixedNodesKept) {
  const Case c;
  ASSERT_GT(c.cube.tets.size(), 2 * kBlockTets);
  const Quality before = quality(c.cube.X, c.cube.tets);
  std::vector<Tet> first_tets;
  std::vector<Vec3> first_X;
  for (int threads : {1, 2, 3}) {
    std::vector<Vec3> X = c.cube.X;
    std::vector<Tet> tets = c.cube.tets;
    std::vector<Index> tags(tets.size(), 4);
    FaceTags surface;
    BlockOptions bo;
    bo.threads = threads;
    const BlockPassCounts n = block_pass(tets, tags, X, c.cube.fixed, c.held, surface, bo);
    EXPECT_GT(n.blocks, 1u);
    EXPECT_GT(n.flips, 0);
    EXPECT_GT(n.moves, 0);
    ASSERT_EQ(tags.size(), tets.size());
    EXPECT_TRUE(std::all_of(tags.begin(), tags.end(), [](Index g) { return g == 4; }));
    if (threads > 1) {
      EXPECT_TRUE(tets == first_tets) << threads << " threads";
      EXPECT_TRUE(X == first_X) << threads << " threads";
      continue;
    }
    first_tets = tets, first_X = X;
    // a valid mesh of the same cube: positive, conforming, closed, every node used
    TetMesh m;
    m.nodes = X;
    for (const Tet& t : tets) m.add_tet(t.data());
    EXPECT_TRUE(validate(m).empty());
    EXPECT_NEAR(volume(X, tets), 1.0, 1e-9);
    for (std::size_t v = 0; v < X.size(); ++v)
      if (c.cube.fixed[v]) {
        EXPECT_EQ(X[v], c.cube.X[v]) << "fixed node " << v;
      }
    std::vector<tet::FaceKey> faces = faces_of(tets);
    FaceSet present(faces.begin(), faces.end());
    for (const tet::FaceKey& k : c.held) EXPECT_TRUE(present.count(k)) << "held face " << k.a << " " << k.b << " " << k.c;
    // better than the fill, and near the passes over the whole mesh on one thread
    const Quality after = quality(X, tets);
    EXPECT_GT(after.worst, before.worst);
    EXPECT_GT(after.mean, before.mean);
    std::vector<Vec3> XW = c.cube.X;
    tet::TetComplex whole(XW);
    whole.build(c.cube.tets);
    whole.constrain(c.held);
    min_max_passes(whole, XW, c.cube.fixed, 3, 3, nullptr);
    const Quality serial = quality(XW, whole.tets());
    EXPECT_GT(after.mean, serial.mean * 0.99);
    EXPECT_LT(after.poor, serial.poor + serial.poor / 10 + 10);
    std::printf("blocks %zu: worst key %.4f (whole mesh %.4f), mean %.4f (%.4f), under %.2f: %zu (%zu)\n", n.blocks, after.worst, serial.worst,
                after.mean, serial.mean, kWorkBelowKey, after.poor, serial.poor);
  }
}

// Through optimize_filled on two threads, with a Stop: Cancelled, nothing left running.
TEST(BlockPass, StopEndsTheBlocks) {
  const Case c;
  std::vector<Vec3> X = c.cube.X;
  tet::TetComplex cx(X);
  FilledMesh filled{c.cube.tets, {}, c.held, {}, {}};
  int calls = 0;
  EXPECT_THROW(optimize_filled(cx, filled, X, c.cube.fixed, OptimizeOptions{}, [&](double) { return ++calls < 3; }, 2), Cancelled);
}

}  // namespace
}  // namespace bisect::optimize
