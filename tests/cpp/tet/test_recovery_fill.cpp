// The fill by Delaunay boundary recovery (tet/recovery_fill.hpp) on a cell no point sees whole:
// a Z-shaped prism, its faces gridded finely with nodes moved a little within their planes (so
// that no four boundary nodes are cocircular and each grid square takes its Delaunay diagonal).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "bisect/errors.hpp"
#include "geom/predicates.hpp"
#include "tet/cell_fill.hpp"
#include "tet/recovery_fill.hpp"
#include "schoenhardt.hpp"

namespace bisect::tet {
namespace {

struct Cell {
  std::vector<Vec3> X;
  std::vector<std::array<Index, 3>> boundary;
  std::vector<Index> interior;
};

// An axis-aligned rectangle of the boundary: fixed axis `axis` at `at`, the others over
// [lo, hi], outward normal along +axis when `up`.
struct Rect {
  int axis;
  double at;
  Vec2 lo, hi;
  bool up;
};

// The Z-shaped polygon (0,0) (3,0) (3,2) (5,2) (5,3) (2,3) (2,1) (0,1), extruded over z in [0, 1]:
// its kernel is empty (the edge at y = 1 wants y <= 1, the one at y = 2 wants y >= 2).
// `against`: one grid square in that many takes the other diagonal (0: none), a triangle pair
// that is not a Delaunay surface, so that the recovery has faces to restore.
Cell z_prism(double h, int against = 0) {
  const std::vector<Rect> rects = {
      // bottom and top, as three rectangles each
      {2, 0, {0, 0}, {3, 1}, false}, {2, 0, {2, 1}, {3, 2}, false}, {2, 0, {2, 2}, {5, 3}, false},
      {2, 1, {0, 0}, {3, 1}, true},  {2, 1, {2, 1}, {3, 2}, true},  {2, 1, {2, 2}, {5, 3}, true},
      // the walls: (axis, at, range of the other in-plane axis and of z)
      {1, 0, {0, 0}, {3, 1}, false},  // y = 0, x in [0,3]
      {0, 3, {0, 0}, {2, 1}, true},   // x = 3, y in [0,2]
      {1, 2, {3, 0}, {5, 1}, false},  // y = 2, x in [3,5]
      {0, 5, {2, 0}, {3, 1}, true},   // x = 5, y in [2,3]
      {1, 3, {2, 0}, {5, 1}, true},   // y = 3, x in [2,5]
      {0, 2, {1, 0}, {3, 1}, false},  // x = 2, y in [1,3]
      {1, 1, {0, 0}, {2, 1}, true},   // y = 1, x in [0,2]
      {0, 0, {0, 0}, {1, 1}, false},  // x = 0, y in [0,1]
  };
  Cell c;
  std::map<std::array<long, 3>, Index> ids;  // grid coordinates (units of h) -> node
  std::vector<std::set<int>> fixed;          // per node: the axes its faces fix
  auto node = [&](const Vec3& p, int axis) {
    const std::array<long, 3> k = {std::lround(p.x() / h), std::lround(p.y() / h), std::lround(p.z() / h)};
    auto [it, fresh] = ids.emplace(k, static_cast<Index>(c.X.size()));
    if (fresh) c.X.push_back(p), fixed.emplace_back();
    fixed[it->second].insert(axis);
    return it->second;
  };
  std::vector<std::array<Index, 4>> squares;  // corners counter-clockwise seen from outside
  for (const Rect& r : rects) {
    const int a1 = r.axis == 0 ? 1 : 0, a2 = r.axis == 2 ? 1 : 2;
    const int n1 = static_cast<int>(std::lround((r.hi.x() - r.lo.x()) / h)), n2 = static_cast<int>(std::lround((r.hi.y() - r.lo.y()) / h));
    auto at = [&](int i, int j) {
      Vec3 p;
      p[r.axis] = r.at, p[a1] = r.lo.x() + i * h, p[a2] = r.lo.y() + j * h;
      return node(p, r.axis);
    };
    for (int i = 0; i < n1; ++i)
      for (int j = 0; j < n2; ++j) {
        std::array<Index, 4> q = {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
        Vec3 n = Vec3::Zero();
        n[r.axis] = r.up ? 1 : -1;
        const Vec3 turn = (c.X[q[1]] - c.X[q[0]]).cross(c.X[q[2]] - c.X[q[0]]);
        if (turn.dot(n) < 0) std::swap(q[1], q[3]);
        squares.push_back(q);
      }
  }
  // each node moved within its planes by up to 0.15 h (a fixed pseudo-random pattern)
  for (std::size_t v = 0; v < c.X.size(); ++v)
    for (int a = 0; a < 3; ++a)
      if (!fixed[v].count(a)) c.X[v][a] += 0.15 * h * std::sin(12.9898 * static_cast<double>(v) + 78.233 * a);
  // each square split along its Delaunay diagonal (in its plane)
  for (std::size_t k = 0; k < squares.size(); ++k) {
    const auto& q = squares[k];
    const bool other = against > 0 && k % static_cast<std::size_t>(against) == 0;
    const Vec3 &p0 = c.X[q[0]], &p1 = c.X[q[1]], &p2 = c.X[q[2]], &p3 = c.X[q[3]];
    // p3 inside the circle through p0, p1, p2: the diagonal p1-p3 is the Delaunay one
    const Vec3 n = (p1 - p0).cross(p2 - p0);
    const Vec3 m = p0 + (p1 - p0 + p2 - p0) / 3;
    const double cocircular = geom::insphere(p0, p1, p2, Vec3(m + n.normalized()), p3);
    if (cocircular != 0 && ((cocircular > 0) == (geom::orient3d(p0, p1, p2, Vec3(m + n.normalized())) > 0)) != other) {
      c.boundary.push_back({q[0], q[1], q[3]});
      c.boundary.push_back({q[1], q[2], q[3]});
    } else {
      c.boundary.push_back({q[0], q[1], q[2]});
      c.boundary.push_back({q[0], q[2], q[3]});
    }
  }
  // interior nodes on a coarser lattice, inside the Z
  auto inside = [](double x, double y) {
    return (y < 1 && x < 3) || (x > 2 && x < 3 && y < 2) || (x > 2 && y > 2);
  };
  for (double x = 0.4; x < 5; x += 0.6)
    for (double y = 0.3; y < 3; y += 0.6)
      for (double z = 0.3; z < 1; z += 0.4)
        if (inside(x, y) && x > 0.1 && y > 0.1 && x < 4.9 && y < 2.9) {
          c.interior.push_back(static_cast<Index>(c.X.size()));
          c.X.push_back(Vec3(x, y, z));
        }
  return c;
}

double volume(const std::vector<Vec3>& X, const Tet& t) {
  return (X[t[1]] - X[t[0]]).dot((X[t[2]] - X[t[0]]).cross(X[t[3]] - X[t[0]])) / 6;
}

void expect_filled(const Cell& c, bool steiner = false);

TEST(RecoveryFill, FillsACellThatNoPointSeesWhole) {
  const Cell c = z_prism(0.25);
  Index node;
  Vec3 point;
  ASSERT_FALSE(star_centre(c.X, c.boundary, c.interior, Vec3(2.5, 1.5, 0.5), &node, &point)) << "the Z prism has no kernel";
  expect_filled(c);
}

// One grid square in seven split along its other diagonal: those 138 triangles are not
// Delaunay faces. The local re-triangulation (face_recovery.hpp) restores most of them, not all:
// a square whose two diagonal ends see neither the whole ring of tetrahedra around the other
// diagonal keeps it (measured: 26 left; the fill then refuses the cell, naming how many).
TEST(RecoveryFill, RestoresMostBoundaryTrianglesThatAreNotDelaunay) {
  const Cell c = z_prism(0.25, 7);
  try {
    expect_filled(c);
  } catch (const MeshingError& e) {
    const std::string what = e.what();
    const std::size_t at = what.find("boundary recovery: ");
    ASSERT_NE(at, std::string::npos) << what;
    const long left = std::stol(what.substr(at + 19));
    EXPECT_LT(left, 138 / 4) << what;
  }
}

// With Steiner points allowed, the second phase (flips that bring a missing edge closer, then
// points inside a hole no node sees whole) restores what the fans alone left: the same Z prism
// with one square in seven turned against its Delaunay diagonal, 26 triangles left before.
TEST(RecoveryFill, FlipsRestoreWhatTheFansLeft) {
  EXPECT_NO_THROW(expect_filled(z_prism(0.25, 7), true));
}

// Schönhardt's twisted prism: no tetrahedralization of it without a point inside exists, so
// the recovery must add one (or more), strictly inside, and the boundary must stay exactly as it is.
TEST(RecoveryFill, AddsASteinerPointWhereNoTetrahedralizationWithoutOneExists) {
  const test::TwistedPrism prism = test::schoenhardt_prism();
  Cell c;
  c.X = prism.X, c.boundary = prism.boundary;
  // the fold is real: each side's second triangle lies outside the first's plane
  for (int i = 0; i < 3; ++i) {
    const auto& t = c.boundary[2 + 2 * i];
    ASSERT_GT(geom::orient3d(c.X[t[0]], c.X[t[1]], c.X[t[2]], c.X[c.boundary[3 + 2 * i][2]]), 0) << "side " << i << " is convex";
  }
  EXPECT_THROW(fill_by_recovery(c.X, c.boundary, c.interior), MeshingError) << "no fill without a Steiner point";
  CellFillStats st;
  std::vector<Vec3> steiner;
  const std::vector<Tet> tets = fill_by_recovery(c.X, c.boundary, c.interior, &st, &steiner);
  ASSERT_GE(steiner.size(), 1u);
  EXPECT_EQ(st.steiner, static_cast<std::int64_t>(steiner.size()));
  std::vector<Vec3> Y = c.X;
  Y.insert(Y.end(), steiner.begin(), steiner.end());
  for (const Vec3& p : steiner)  // strictly inside the prism's hull, off its boundary
    EXPECT_TRUE(p.z() > 0 && p.z() < 1 && p.head<2>().norm() < 1) << "a Steiner point outside: " << p.transpose();
  double v = 0, want = 0;
  std::map<std::array<Index, 3>, int> faces;
  for (const Tet& t : tets) {
    ASSERT_GT(geom::orient3d(Y[t[0]], Y[t[1]], Y[t[2]], Y[t[3]]), 0);
    v += volume(Y, t);
    for (const auto& f : std::array<std::array<int, 3>, 4>{{{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}}) ++faces[smallest_first({t[f[0]], t[f[1]], t[f[2]]})];
  }
  for (const auto& t : c.boundary) {
    want += c.X[t[0]].dot(c.X[t[1]].cross(c.X[t[2]])) / 6;  // the divergence theorem
    EXPECT_EQ(faces.count(smallest_first(t)) ? faces.at(smallest_first(t)) : 0, 1) << "a boundary triangle lost";
  }
  EXPECT_NEAR(v, want, 1e-12);
}

void expect_filled(const Cell& c, bool steiner) {
  CellFillStats st;
  std::vector<Vec3> added;
  const std::vector<Tet> tets = fill_by_recovery(c.X, c.boundary, c.interior, &st, steiner ? &added : nullptr);
  ASSERT_TRUE(added.empty()) << "the Z prism needs no Steiner point";
  double v = 0;
  std::map<std::array<Index, 3>, int> faces;  // each face, oriented out of its tetrahedron
  for (const Tet& t : tets) {
    ASSERT_GT(geom::orient3d(c.X[t[0]], c.X[t[1]], c.X[t[2]], c.X[t[3]]), 0);
    v += volume(c.X, t);
    // face f opposite corner f, turned to face out of t
    const std::array<std::array<int, 3>, 4> fv = {{{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};
    for (const auto& f : fv) {
      std::array<Index, 3> k = {t[f[0]], t[f[1]], t[f[2]]};
      std::rotate(k.begin(), std::min_element(k.begin(), k.end()), k.end());
      ++faces[k];
    }
  }
  EXPECT_NEAR(v, 7.0, 1e-9) << "the Z's area 7 times its height 1";
  // every boundary triangle is a face of exactly one tetrahedron, turned the same way; every
  // other face is shared by two tetrahedra, turned opposite ways
  std::size_t outer = 0;
  for (auto t : c.boundary) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    EXPECT_EQ(faces.count(t) ? faces.at(t) : 0, 1);
    ++outer;
  }
  std::size_t unmatched = 0;
  for (const auto& [k, n] : faces) {
    const std::array<Index, 3> back = {k[0], k[2], k[1]};
    if (!faces.count(back)) ++unmatched;
  }
  EXPECT_EQ(unmatched, outer);
  EXPECT_EQ(st.inserted + st.skipped, static_cast<std::int64_t>(c.interior.size()));
  EXPECT_EQ(st.skipped, 0);
}

TEST(RecoveryFill, RefusesABoundaryWithAHole) {
  Cell c = z_prism(0.5);
  c.boundary.pop_back();  // one triangle missing: the outside reaches in
  EXPECT_THROW(fill_by_recovery(c.X, c.boundary, c.interior), MeshingError);
}

}  // namespace
}  // namespace bisect::tet
