// The complex's journal: undo() takes back flips, edge removals and Delaunay insertions, last
// first, to the same tetrahedra (ids aside), with their tags, and a complex that works on.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "bisect/validate.hpp"
#include "optimize/grid_cube.hpp"
#include "tet/tet_complex.hpp"

namespace bisect::tet {
namespace {

// The live tetrahedra as sorted node lists with their tags, sorted: equal for the same mesh.
std::vector<std::pair<std::array<Index, 4>, Index>> canonical(const TetComplex& cx) {
  std::vector<std::pair<std::array<Index, 4>, Index>> out;
  for (std::size_t t = 0; t < cx.tet.size(); ++t) {
    if (!cx.alive[t]) continue;
    std::array<Index, 4> k = cx.tet[t];
    std::sort(k.begin(), k.end());
    out.push_back({k, cx.tag[t]});
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(Undo, TakesBackFlipsAndInsertionsToTheSameMesh) {
  optimize::GridCube g(7, 0.02);
  TetComplex cx(g.X);
  std::vector<Index> tags(g.tets.size());
  for (std::size_t i = 0; i < tags.size(); ++i) tags[i] = static_cast<Index>(i % 3);  // tags that differ
  cx.build(g.tets, tags);
  const auto before = canonical(cx);
  std::vector<TetComplex::Replacement> journal;
  cx.journal = &journal;
  const std::int64_t flips = cx.improve_all(std::numeric_limits<std::int64_t>::max());
  // two nodes put in with Delaunay cavities, and flips after each
  for (const Vec3& p : {Vec3(0.31, 0.42, 0.53), Vec3(0.77, 0.21, 0.66)}) {
    g.X.push_back(p);
    const std::vector<Index> made = cx.insert_delaunay(static_cast<Index>(g.X.size() - 1), 0);
    ASSERT_FALSE(made.empty());
    cx.improve_around(made);
  }
  cx.journal = nullptr;
  ASSERT_GT(flips, 0);
  ASSERT_GT(journal.size(), static_cast<std::size_t>(flips));
  EXPECT_NE(canonical(cx), before);
  cx.undo(journal);
  EXPECT_TRUE(journal.empty());
  g.X.resize(g.X.size() - 2);
  EXPECT_EQ(canonical(cx), before);
  // the neighbours hold: a valid mesh, and the complex works on
  TetMesh m;
  m.nodes = g.X;
  for (const Tet& t : cx.tets()) m.add_tet(t.data());
  EXPECT_TRUE(validate(m).empty());
  for (std::size_t t = 0; t < cx.tet.size(); ++t)
    if (cx.alive[t])
      for (int f = 0; f < 4; ++f) {
        const Index n = cx.neighbour(t, f);
        if (n >= 0) {
          EXPECT_EQ(cx.face_towards(n, static_cast<Index>(t)), cx.neighbour_face(t, f));
        }
      }
  EXPECT_GT(cx.improve_all(std::numeric_limits<std::int64_t>::max()), 0);
}

// A local change undone from its own log (undo's `among`: the ids the change made, as `touched`
// logs them): the same mesh, without a search of the whole complex. The surface angles' pass
// (optimize/surface_angles.hpp) undoes a node's move with its flips this way.
TEST(Undo, TakesBackALocalChangeFromItsOwnLog) {
  optimize::GridCube g(7, 0.02);
  TetComplex cx(g.X);
  cx.build(g.tets);
  const auto before = canonical(cx);
  std::vector<TetComplex::Replacement> journal;
  std::vector<Index> touched;
  cx.journal = &journal, cx.touched = &touched;
  std::vector<Index> some;
  for (Index t = 0; t < 40; ++t) some.push_back(t);
  const std::int64_t flips = cx.improve_around(some);
  cx.journal = nullptr, cx.touched = nullptr;
  ASSERT_GT(flips, 0);
  EXPECT_NE(canonical(cx), before);
  cx.undo(journal, &touched);
  EXPECT_EQ(canonical(cx), before);
  TetMesh m;
  m.nodes = g.X;
  for (const Tet& t : cx.tets()) m.add_tet(t.data());
  EXPECT_TRUE(validate(m).empty());
}

// A 2-2 flip on the outer boundary (--boundary-flips) undone: its two boundary triangles and
// their input face come back. Before, undo() put the old tetrahedra back as if inside and threw
// "a replacement does not fill the space it replaces" (part.stl at 10^5 with --boundary-flips,
// the sliver repair's second go undone).
TEST(Undo, TakesBackAFlipOfTheOuterBoundaryWithItsFaceTags) {
  // two tetrahedra over the long diagonal x y of a flat rhombus x d y e, apex c: the 2-2 flip to
  // the short diagonal d e makes both better
  const std::vector<Vec3> X{{0, 0, 0}, {2, 0, 0}, {1, -0.5, 0}, {1, 0.5, 0}, {1, 0, 0.8}};
  const Index x = 0, y = 1, d = 2, e = 3, c = 4;
  TetComplex cx(X);
  std::vector<Tet> two{{x, y, d, c}, {x, y, e, c}};
  for (Tet& t : two)
    if (!positive(X, t)) std::swap(t[0], t[1]);
  cx.build(two);
  // every outer triangle tagged: the rhombus input face 7, each side its own
  Index side = 10;
  for (std::size_t t = 0; t < 2; ++t)
    for (int f = 0; f < 4; ++f) {
      if (cx.neighbour(static_cast<Index>(t), f) >= 0) continue;
      const auto fv = cx.face(static_cast<Index>(t), f);
      const bool flat = X[fv[0]].z() == 0 && X[fv[1]].z() == 0 && X[fv[2]].z() == 0;
      cx.surface_tag[face_key(fv[0], fv[1], fv[2])] = flat ? 7 : side++;
    }
  const auto before = canonical(cx);
  const auto tags_before = cx.surface_tag;
  std::vector<TetComplex::Replacement> journal;
  cx.journal = &journal;
  cx.boundary_flips = true;
  ASSERT_GT(cx.improve_all(std::numeric_limits<std::int64_t>::max()), 0);
  cx.journal = nullptr;
  ASSERT_EQ(cx.surface_tag.count(face_key(x, d, e)), 1u) << "the boundary was not flipped";
  EXPECT_EQ(cx.surface_tag.count(face_key(x, y, d)), 0u);
  ASSERT_NO_THROW(cx.undo(journal));
  EXPECT_EQ(canonical(cx), before);
  EXPECT_EQ(cx.surface_tag, tags_before);
  std::size_t outer = 0;
  for (std::size_t t = 0; t < cx.tet.size(); ++t)
    if (cx.alive[t])
      for (int f = 0; f < 4; ++f) outer += cx.neighbour(static_cast<Index>(t), f) < 0;
  EXPECT_EQ(outer, 6u);  // the two tetrahedra meet across x y c again
}

}  // namespace
}  // namespace bisect::tet
