// The working tetrahedral complex of the cell fill (thesis 7.5, 7.6): adjacency kept by
// `replace`, point insertion inside, on a face and on an edge, Delaunay insertion, and the
// min-max transformations never touching constrained faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <unordered_set>

#include "bisect/errors.hpp"
#include "bisect/quality.hpp"
#include "tet/tet_complex.hpp"
#include "geom/predicates.hpp"

namespace bisect::tet {
namespace {

// Every live tetrahedron positive, adjacency symmetric and matching shared faces, and the face
// stored as the way back (adj's 4 u + g) the one that leads back.
void expect_consistent(const TetComplex& cx) {
  for (std::size_t t = 0; t < cx.tet.size(); ++t) {
    if (!cx.alive[t]) continue;
    EXPECT_TRUE(positive(cx.X, cx.tet[t])) << t;
    for (int f = 0; f < 4; ++f) {
      const Index n = cx.neighbour(t, f);
      if (n < 0) continue;
      ASSERT_TRUE(cx.alive[n]);
      const int g = cx.face_towards(n, static_cast<Index>(t));
      ASSERT_GE(g, 0) << "adjacency not symmetric";
      EXPECT_EQ(cx.neighbour_face(t, f), g) << "tetrahedron " << t << " face " << f << ": the stored way back";
      const auto a = cx.face(static_cast<Index>(t), f), b = cx.face(n, g);
      EXPECT_TRUE(face_key(a[0], a[1], a[2]) == face_key(b[0], b[1], b[2]));
    }
  }
}

double volume(const TetComplex& cx) {
  double v = 0;
  for (const Tet& t : cx.tets()) v += (cx.X[t[1]] - cx.X[t[0]]).dot((cx.X[t[2]] - cx.X[t[0]]).cross(cx.X[t[3]] - cx.X[t[0]])) / 6;
  return v;
}

std::size_t boundary_faces(const TetComplex& cx) {
  std::size_t n = 0;
  for (std::size_t t = 0; t < cx.tet.size(); ++t)
    if (cx.alive[t])
      for (int f = 0; f < 4; ++f) n += cx.neighbour(t, f) < 0;
  return n;
}

// The unit cube as 6 tetrahedra around its diagonal 0-6.
std::vector<Vec3> cube_nodes() { return {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}; }
std::vector<Tet> cube_tets(const std::vector<Vec3>& X) {
  std::vector<Tet> t = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  for (Tet& x : t)
    if (!positive(X, x)) std::swap(x[0], x[1]);
  return t;
}

// The cube's corners and n random points inside it.
std::vector<Vec3> random_cube_nodes(unsigned seed, int n) {
  std::vector<Vec3> X = cube_nodes();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.05, 0.95);
  for (int i = 0; i < n; ++i) X.push_back({u(rng), u(rng), u(rng)});
  return X;
}

// The cube's six tetrahedra with every other node of X inserted by Delaunay insertion.
void insert_the_rest(TetComplex& cx) {
  cx.build(cube_tets(cx.X));
  Index last = 0;
  for (Index v = 8; v < static_cast<Index>(cx.X.size()); ++v) last = cx.insert_delaunay(v, last).front();
}

TEST(TetComplex, InsertInsideOnAFaceAndOnAnEdge) {
  std::vector<Vec3> X = cube_nodes();
  X.push_back({0.6, 0.3, 0.2});  // 8: inside one tetrahedron
  X.push_back({0.5, 0.5, 0.25});  // 9: on the face 0-2-6 (z = x / 2 ... on the plane x = y)
  X.push_back({0.5, 0.5, 0.5});  // 10: on the diagonal 0-6, shared by all six
  TetComplex cx(X);
  cx.build(cube_tets(X));
  EXPECT_EQ(boundary_faces(cx), 12u);
  EXPECT_EQ(cx.insert(8, 0).size(), 4u);
  expect_consistent(cx);
  const std::size_t before = cx.live_count();
  const auto made = cx.insert(9, 0);
  EXPECT_EQ(cx.live_count() - before, 4u);  // 2 tetrahedra on the face become 6
  EXPECT_EQ(made.size(), 6u);
  expect_consistent(cx);
  const std::size_t before2 = cx.live_count();
  EXPECT_FALSE(cx.insert(10, 0).empty());
  EXPECT_GT(cx.live_count(), before2);
  expect_consistent(cx);
  EXPECT_NEAR(volume(cx), 1.0, 1e-12);
  EXPECT_EQ(boundary_faces(cx), 12u);  // the boundary untouched
  EXPECT_TRUE(cx.insert(3, 0).empty());  // an existing node is not inserted again
}

TEST(TetComplex, PointsOnTheBoundaryAreRefused) {
  std::vector<Vec3> X = cube_nodes();
  X.push_back({0.5, 0.5, 0});  // on the bottom face
  X.push_back({2, 2, 2});      // outside
  TetComplex cx(X);
  cx.build(cube_tets(X));
  EXPECT_TRUE(cx.insert(8, 0).empty());
  EXPECT_TRUE(cx.insert(9, 0).empty());
  EXPECT_TRUE(cx.insert_delaunay(8, 0).empty());
  EXPECT_EQ(cx.live_count(), 6u);
}

TEST(TetComplex, DelaunayInsertionIsUndoneByReplacingWhatItMadeWithItsCavity) {
  std::vector<Vec3> X = cube_nodes();
  X.push_back({0.6, 0.3, 0.2});
  TetComplex cx(X);
  cx.build(cube_tets(X));
  auto sorted_tets = [](const TetComplex& c) {  // each tetrahedron's nodes sorted, then the list
    std::vector<Tet> out = c.tets();
    for (Tet& t : out) std::sort(t.begin(), t.end());
    std::sort(out.begin(), out.end());
    return out;
  };
  const std::vector<Tet> before = sorted_tets(cx);
  std::vector<Tet> replaced;
  const std::vector<Index> made = cx.insert_delaunay(8, 0, &replaced);
  ASSERT_FALSE(made.empty());
  EXPECT_FALSE(replaced.empty());
  cx.replace(made, replaced);
  expect_consistent(cx);
  EXPECT_EQ(cx.live_count(), 6u);
  EXPECT_NEAR(volume(cx), 1.0, 1e-12);
  EXPECT_EQ(boundary_faces(cx), 12u);
  EXPECT_EQ(sorted_tets(cx), before);  // the same six tetrahedra, the inserted node in none
}

TEST(TetComplex, RandomInsertionsBothWaysStayValidAndImprove) {
  for (bool delaunay : {false, true}) {
    std::vector<Vec3> X = random_cube_nodes(7, 300);
    TetComplex cx(X);
    cx.build(cube_tets(X));
    Index last = 0;
    for (Index v = 8; v < static_cast<Index>(X.size()); ++v) {
      const auto made = delaunay ? cx.insert_delaunay(v, last) : cx.insert(v, last);
      ASSERT_FALSE(made.empty()) << v;
      last = made.front();
    }
    expect_consistent(cx);
    EXPECT_NEAR(volume(cx), 1.0, 1e-12);
    double worst_before = 1e300;
    for (const Tet& t : cx.tets()) worst_before = std::min(worst_before, tet_angle_key(X, t));
    const std::int64_t ops = cx.improve_all(1000000);
    EXPECT_GT(ops, 0);
    expect_consistent(cx);
    EXPECT_NEAR(volume(cx), 1.0, 1e-12);
    EXPECT_EQ(boundary_faces(cx), 12u);
    double worst_after = 1e300;
    for (const Tet& t : cx.tets()) worst_after = std::min(worst_after, tet_angle_key(X, t));
    EXPECT_GE(worst_after, worst_before) << (delaunay ? "delaunay" : "minmax");
  }
}

// Each tetrahedron's neighbour across each face, named by node sets: the same complex built
// afresh must give the same relation.
std::vector<std::pair<Tet, Tet>> neighbour_relation(const TetComplex& cx) {
  std::vector<std::pair<Tet, Tet>> out;
  for (std::size_t t = 0; t < cx.tet.size(); ++t) {
    if (!cx.alive[t]) continue;
    for (int f = 0; f < 4; ++f) {
      const Index n = cx.neighbour(t, f);
      Tet a = cx.tet[t], b{-1, -1, -1, -1};
      if (n >= 0) b = cx.tet[n];
      std::sort(a.begin(), a.end()), std::sort(b.begin(), b.end());
      out.push_back({a, b});
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// replace() over a flip's few tetrahedra and over a node's whole star: both keep the adjacency a
// fresh build gives, and both refuse a set that leaves a hole.
TEST(TetComplex, ReplacementsSmallAndLargeKeepTheAdjacency) {
  std::vector<Vec3> X = random_cube_nodes(3, 200);
  TetComplex cx(X);
  insert_the_rest(cx);
  EXPECT_GT(cx.improve_all(1000000), 0);  // flips: small replacements
  // a node's whole star replaced by itself: a large one
  std::vector<Index> star;
  std::size_t most = 0;
  for (Index v = 8; v < static_cast<Index>(X.size()); ++v) {
    std::vector<Index> at = cx.tets_at(v);
    if (at.size() > most) most = at.size(), star = at;
  }
  ASSERT_GT(star.size(), 12u);
  std::vector<Tet> same;
  for (Index t : star) same.push_back(cx.tet[t]);
  cx.replace(star, same);
  expect_consistent(cx);
  TetComplex fresh(X);
  fresh.build(cx.tets());
  EXPECT_EQ(neighbour_relation(cx), neighbour_relation(fresh));
  // a set that does not fill the space it replaces: two tetrahedra for one, and a star less one
  {
    const std::vector<Index> two{star[0], cx.neighbour(star[0], 0) >= 0 ? cx.neighbour(star[0], 0) : cx.neighbour(star[0], 1)};
    EXPECT_THROW(cx.replace(two, {cx.tet[two[0]]}), MeshingError);
  }
  TetComplex again(X);
  again.build(fresh.tets());
  std::vector<Index> big;
  for (std::size_t t = 0; t < again.tet.size(); ++t)
    if (std::find(same.begin(), same.end(), again.tet[t]) != same.end()) big.push_back(static_cast<Index>(t));
  ASSERT_EQ(big.size(), same.size());
  std::vector<Tet> less(same.begin() + 1, same.end());
  EXPECT_THROW(again.replace(big, less), MeshingError);
}

// build() and constrain() run in chunks on the threads (more than one chunk of tetrahedra and of
// nodes here): the neighbours, the quality keys and the constrained faces are the same for any
// thread count, slot for slot (tested up to 8, beyond the counting sort's 4 parts).
TEST(TetComplex, TheSameComplexIsBuiltOnAnyNumberOfThreads) {
  std::vector<Vec3> X = random_cube_nodes(11, 20000);
  TetComplex made(X);
  insert_the_rest(made);
  const std::vector<Tet> tets = made.tets();
  ASSERT_GT(tets.size(), 100000u);
  std::unordered_set<FaceKey, FaceKeyHash> held;  // every face of every seventh tetrahedron
  for (std::size_t t = 0; t < tets.size(); t += 7)
    for (int f = 0; f < 4; ++f) held.insert(face_key(tets[t][(f + 1) % 4], tets[t][(f + 2) % 4], tets[t][(f + 3) % 4]));
  TetComplex one(X);
  one.build(tets, {}, 1);
  one.constrain(held, 1);
  expect_consistent(one);
  for (int threads : {2, 4, 8}) {  // 8: more threads than the counting sort's parts
    TetComplex many(X);
    many.build(tets, {}, threads);
    many.constrain(held, threads);
    EXPECT_EQ(many.adj, one.adj) << threads << " threads";
    EXPECT_EQ(many.q, one.q) << threads << " threads";
    std::size_t differ = 0, constrained = 0;
    for (std::size_t t = 0; t < tets.size(); ++t)
      for (int f = 0; f < 4; ++f) {
        differ += many.is_constrained(static_cast<Index>(t), f) != one.is_constrained(static_cast<Index>(t), f);
        constrained += one.is_constrained(static_cast<Index>(t), f);
      }
    EXPECT_EQ(differ, 0u) << threads << " threads";
    EXPECT_GT(constrained, tets.size() / 2);
  }
}

TEST(TetComplex, ConstrainedFacesAreNeverFlipped) {
  // a tall tetrahedron on a flat one across their shared face: the 2-3 flip raises the smallest
  // solid angle from 0.078 to 0.207 sr; constraining the face stops it
  std::vector<Vec3> X = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, 0.4, 0.6}, {0.5, 0.4, -0.1}};
  auto make = [&] {
    std::vector<Tet> t = {{0, 1, 2, 3}, {0, 1, 2, 4}};
    for (Tet& x : t)
      if (!positive(X, x)) std::swap(x[0], x[1]);
    return t;
  };
  TetComplex free_cx(X);
  free_cx.build(make());
  EXPECT_EQ(free_cx.improve_all(10), 1);
  EXPECT_EQ(free_cx.live_count(), 3u);
  TetComplex held(X);
  held.build(make());
  held.constrain({face_key(0, 1, 2)});
  EXPECT_EQ(held.improve_all(10), 0);
  EXPECT_EQ(held.live_count(), 2u);
}

TEST(TetComplex, TwoThreeTetrahedraAreNotPositiveWhereTheApexesMissTheFace) {
  // two tetrahedra on the triangle (0, 1, 2) with apexes above and below it: over its centre
  // the three tetrahedra of the 2-3 transformation are positive; with the lower apex beyond the
  // edge (0, 1) the segment between the apexes misses the triangle, one of them is inverted,
  // positive_all says so, and the transformation is not made whatever the keys say
  for (const double y : {0.3, -0.5}) {
    std::vector<Vec3> X = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, 0.3, 0.6}, {0.5, y, -0.1}};
    std::vector<Tet> t = {{0, 1, 2, 3}, {0, 1, 2, 4}};
    for (Tet& x : t)
      if (!positive(X, x)) std::swap(x[0], x[1]);
    TetComplex cx(X);
    cx.build(t);
    const int f = cx.corner_of(0, 3);  // tetrahedron 0's face (0, 1, 2)
    std::vector<Tet> fresh;
    ASSERT_TRUE(cx.flip23_unchecked(0, f, &fresh));
    ASSERT_EQ(fresh.size(), 3u);
    const bool crosses = y > 0;
    EXPECT_EQ(cx.positive_all(fresh), crosses) << "y " << y;
    cx.improve_all(10);
    expect_consistent(cx);
    if (!crosses) EXPECT_EQ(cx.live_count(), 2u);
    TetComplex held(X);  // a constrained face has no 2-3 tetrahedra at all
    held.build(t);
    held.constrain({face_key(0, 1, 2)});
    EXPECT_FALSE(held.flip23_unchecked(0, f, &fresh));
  }
}

TEST(TetComplex, AFailedFlipIsTriedAgainOnceATetrahedronChanges) {
  // two tetrahedra on a unit triangle, apexes 0.8 above and below its centre: the 2-3 flip would
  // lower the smallest solid angle (0.545 to 0.190 sr), so it fails and is remembered; with the
  // lower apex moved to 0.1 below (0.092 before, 0.190 after) it is tried again and taken. A
  // memory not undone by the move would miss it.
  const Vec3 g(0.5, 0.2886751, 0);
  std::vector<Vec3> X = {{0, 0, 0}, {1, 0, 0}, {0.5, 0.8660254, 0}, g + Vec3(0, 0, 0.8), g - Vec3(0, 0, 0.8)};
  std::vector<Tet> t = {{0, 1, 2, 3}, {0, 1, 2, 4}};
  for (Tet& x : t)
    if (!positive(X, x)) std::swap(x[0], x[1]);
  TetComplex cx(X);
  cx.build(t);
  EXPECT_EQ(cx.improve_all(10), 0);
  EXPECT_EQ(cx.improve_all(10), 0);  // remembered: the same answer
  X[4] = g - Vec3(0, 0, 0.1);
  cx.moved({0, 1});
  EXPECT_EQ(cx.improve_all(10), 1);
  EXPECT_EQ(cx.live_count(), 3u);
  expect_consistent(cx);
}

// Removing a node by flips (the helper of 7.6): the cube's six tetrahedra with a node at the
// centre inserted (twelve around it, star of the centre), and a tetrahedron split 1-4; the
// node goes, the boundary and the volume stay, every tetrahedron is positive.
TEST(TetComplex, RemoveVertexByFlips) {
  {
    std::vector<Vec3> X = cube_nodes();
    X.push_back({0.52, 0.47, 0.55});  // 8: near the centre, off the diagonal
    TetComplex cx(X);
    cx.build(cube_tets(X));
    ASSERT_FALSE(cx.insert(8, 0).empty());
    const std::size_t faces = boundary_faces(cx);
    std::size_t around = 0;
    for (const Tet& t : cx.tets()) around += std::find(t.begin(), t.end(), 8) != t.end();
    ASSERT_GE(around, 4u);
    EXPECT_TRUE(cx.remove_vertex(8));
    for (const Tet& t : cx.tets()) EXPECT_EQ(std::find(t.begin(), t.end(), 8), t.end());
    expect_consistent(cx);
    EXPECT_EQ(boundary_faces(cx), faces);
    EXPECT_NEAR(volume(cx), 1, 1e-12);
    EXPECT_FALSE(cx.remove_vertex(0));  // a corner, in every tetrahedron: on the boundary, it stays
    EXPECT_NEAR(volume(cx), 1, 1e-12);
  }
  {
    std::vector<Vec3> X = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.2, 0.2, 0.2}};
    TetComplex cx(X);
    Tet t{0, 1, 2, 3};
    if (!positive(X, t)) std::swap(t[0], t[1]);
    cx.build({t});
    ASSERT_EQ(cx.insert(4, 0).size(), 4u);
    EXPECT_TRUE(cx.remove_vertex(4));  // 4-1
    ASSERT_EQ(cx.live_count(), 1u);
    expect_consistent(cx);
    EXPECT_FALSE(cx.remove_vertex(0));  // a boundary node is not removed
  }
}

// The 2-2 transformation (7.5): two tetrahedra over a thin rhombus on the outer boundary, its
// long diagonal x-y shared; the short diagonal d-e raises the smallest solid angle. It happens
// only with boundary_flips, only within one input face, and the boundary's tags follow.
TEST(TetComplex, TwoTwoFlipTakesTheBoundarysOtherDiagonal) {
  const std::vector<Vec3> X = {{-1, 0, 0}, {1, 0, 0}, {0, -0.3, 0}, {0, 0.3, 0}, {0, 0, 0.5}};
  const Index x = 0, y = 1, d = 2, e = 3, c = 4;
  auto make = [&](TetComplex& cx, Index tag_d, Index tag_e) {
    std::vector<Tet> t = {{x, y, d, c}, {x, y, e, c}};
    for (Tet& u : t)
      if (!positive(X, u)) std::swap(u[0], u[1]);
    cx.build(t);
    for (std::size_t k = 0; k < 2; ++k)
      for (int f = 0; f < 4; ++f)
        if (cx.neighbour(k, f) < 0) {
          const auto fv = cx.face(static_cast<Index>(k), f);
          const bool bottom = std::find(fv.begin(), fv.end(), c) == fv.end();
          cx.surface_tag[face_key(fv[0], fv[1], fv[2])] = bottom ? (k == 0 ? tag_d : tag_e) : 9;
        }
  };
  TetComplex off(X);
  make(off, 1, 1);
  EXPECT_EQ(off.improve_all(10), 0);  // boundary_flips is off by default
  TetComplex other_faces(X);
  make(other_faces, 1, 2);
  other_faces.boundary_flips = true;
  EXPECT_EQ(other_faces.improve_all(10), 0);  // the two triangles lie in different input faces
  TetComplex on(X);
  make(on, 1, 1);
  const double before = std::min(on.q[0], on.q[1]);
  on.boundary_flips = true;
  EXPECT_EQ(on.improve_all(10), 1);
  ASSERT_EQ(on.live_count(), 2u);
  double after = 1e300;
  for (const Tet& t : on.tets()) {
    EXPECT_TRUE(positive(X, t));
    EXPECT_NE(std::find(t.begin(), t.end(), d), t.end());
    EXPECT_NE(std::find(t.begin(), t.end(), e), t.end());
    after = std::min(after, tet_angle_key(X, t));
  }
  EXPECT_GT(after, before);
  EXPECT_EQ(on.surface_tag.count(face_key(x, y, d)), 0u);
  EXPECT_EQ(on.surface_tag.count(face_key(x, y, e)), 0u);
  EXPECT_EQ(on.surface_tag.at(face_key(x, d, e)), 1);
  EXPECT_EQ(on.surface_tag.at(face_key(y, d, e)), 1);
  EXPECT_EQ(on.surface_tag.size(), 6u);  // four sides and the two new bottom triangles
}

// Point location in a complex that is not convex (Delaunay boundary recovery fills cells that
// are not star-shaped): five unit cubes in a U, each in six tetrahedra round its diagonal. From
// one arm the walk towards a point of the other meets the boundary at the gap between the arms
// (no face on the way has a neighbour); the search from there, nearest tetrahedra first, still
// finds the one holding the point, and a point in the gap is in none.
TEST(TetComplex, TheKeyOfATetrahedronInsideOutIsNegative) {
  const std::vector<Vec3> X = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.2, 0.3, 1)};
  const double good = tet_angle_key(X, {0, 1, 2, 3});
  EXPECT_GT(good, 0);
  EXPECT_DOUBLE_EQ(tet_angle_key(X, {1, 0, 2, 3}), -good);  // the mirror image: the same angles
  EXPECT_DOUBLE_EQ(min_solid_angle_tan_half(X[1], X[0], X[2], X[3]), good);
}

// Three tetrahedra round an edge d e that passes beside the triangle a b c instead of through it:
// one of them is inside out. The 3-2 flip to a b c d and a c b e undoes it, though its two
// tetrahedra are poorer than the inverted one's mirror image (smallest-angle keys 0.112 against
// 0.150): the min-max criterion must count the fold as the worst, or it keeps it.
TEST(TetComplex, ATransformationUndoesATetrahedronInsideOut) {
  const std::vector<Vec3> X = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.9, 0.9, 1), Vec3(0.9, 0.9, -1)};
  const Index a = 0, b = 1, c = 2, d = 3, e = 4;
  const std::vector<Tet> ring = {{e, d, a, b}, {e, d, b, c}, {e, d, c, a}};
  ASSERT_EQ(std::count_if(ring.begin(), ring.end(), [&](const Tet& t) { return !positive(X, t); }), 1);
  TetComplex cx(X);
  cx.build(ring);
  EXPECT_GE(cx.improve_all(100), 1);
  const std::vector<Tet> now = cx.tets();
  ASSERT_EQ(now.size(), 2u);
  for (const Tet& t : now) EXPECT_TRUE(positive(X, t));
}

// replace() logs the ids it takes out and those it makes on `touched` (face recovery keeps its
// count of the present faces in step from it), and only while it is set.
TEST(TetComplex, ReplaceLogsWhatItTookOutAndWhatItMade) {
  const std::vector<Vec3> X = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.3, 0.3, 1), Vec3(0.3, 0.3, -1)};
  const Index a = 0, b = 1, c = 2, d = 3, e = 4;
  TetComplex cx(X);
  cx.build({{e, d, a, b}, {e, d, b, c}, {e, d, c, a}});
  for (const Tet& t : cx.tets()) ASSERT_TRUE(positive(X, t));
  std::vector<Index> log;
  cx.touched = &log;
  const std::vector<Index> made = cx.replace({0, 1, 2}, {{a, b, c, d}, {a, c, b, e}});
  cx.touched = nullptr;
  ASSERT_EQ(log.size(), 5u);
  EXPECT_EQ(std::vector<Index>(log.begin(), log.begin() + 3), (std::vector<Index>{0, 1, 2}));
  EXPECT_EQ(std::vector<Index>(log.begin() + 3, log.end()), made);
  cx.replace(made, {{e, d, a, b}, {e, d, b, c}, {e, d, c, a}});
  EXPECT_EQ(log.size(), 5u);
}

// With new_boundary, a tetrahedron with two faces on the boundary taken out for nothing: the
// faces it shared become the boundary of the tetrahedra beyond them (the surface's edge flips
// take such a cap out of a B-rep face). hold() marks a face constrained from both sides.
TEST(TetComplex, ReplaceTakesOutABoundaryCapAndHoldMarksBothSides) {
  const std::vector<Vec3> X = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.3, 0.3, 1), Vec3(0.3, 0.3, -1)};
  const Index a = 0, b = 1, c = 2, d = 3, e = 4;
  TetComplex cx(X);
  cx.build({{a, b, c, d}, {a, c, b, e}});
  for (const Tet& t : cx.tets()) ASSERT_TRUE(positive(X, t));
  const Index cap = cx.tet[0][3] == d ? 0 : 1, rest = 1 - cap;
  const int shared = cx.face_towards(rest, cap);
  ASSERT_GE(shared, 0);
  EXPECT_FALSE(cx.is_constrained(rest, shared));
  cx.hold(rest, shared);
  EXPECT_TRUE(cx.is_constrained(rest, shared));
  EXPECT_TRUE(cx.is_constrained(cap, cx.face_towards(cap, rest)));
  EXPECT_TRUE(cx.replace({cap}, {}, true).empty());
  EXPECT_EQ(cx.live_count(), 1u);
  EXPECT_EQ(cx.neighbour(rest, shared), -1);
  for (int f = 0; f < 4; ++f) EXPECT_EQ(cx.neighbour(rest, f), -1);
}

TEST(TetComplex, LocateFindsAPointRoundADent) {
  std::vector<Vec3> X;
  std::vector<Tet> tets;
  auto node = [&](const Vec3& p) {
    for (std::size_t i = 0; i < X.size(); ++i)
      if ((X[i] - p).norm() < 1e-12) return static_cast<Index>(i);
    X.push_back(p);
    return static_cast<Index>(X.size() - 1);
  };
  for (const Vec3& o : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(0, 1, 0), Vec3(2, 1, 0)}) {
    const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (const auto& p : perms) {
      const Vec3 a = Vec3::Unit(p[0]), b = a + Vec3::Unit(p[1]);
      Tet t{node(o), node(o + a), node(o + b), node(o + Vec3(1, 1, 1))};
      if (geom::orient3d(X[t[0]], X[t[1]], X[t[2]], X[t[3]]) < 0) std::swap(t[2], t[3]);
      tets.push_back(t);
    }
  }
  TetComplex cx(X);
  cx.build(tets);
  expect_consistent(cx);
  auto holds = [&](Index t, const Vec3& p) {
    for (int f = 0; f < 4; ++f) {
      const auto fv = cx.face(t, f);
      if (geom::orient3d(cx.X[fv[0]], cx.X[fv[1]], cx.X[fv[2]], p) > 0) return false;
    }
    return true;
  };
  Index start = -1;  // a tetrahedron of one arm
  for (std::size_t t = 0; t < cx.tet.size() && start < 0; ++t)
    if (holds(static_cast<Index>(t), Vec3(2.5, 1.6, 0.4))) start = static_cast<Index>(t);
  ASSERT_GE(start, 0);
  for (const Vec3& p : {Vec3(0.5, 1.5, 0.5), Vec3(0.2, 1.9, 0.1), Vec3(1.5, 0.5, 0.5)}) {
    const Index t = cx.locate(p, start);
    ASSERT_GE(t, 0) << p.transpose();
    EXPECT_TRUE(holds(t, p)) << p.transpose();
  }
  EXPECT_EQ(cx.locate(Vec3(1.5, 1.5, 0.5), start), -1);  // the gap
}

}  // namespace
}  // namespace bisect::tet
