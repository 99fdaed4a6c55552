// Quality measures on tetrahedra whose values are known in closed form, checked also against
// reference formulas that share no code path with quality.cpp: dihedral angles from vertex
// projections (not face normals), solid angles from the identity Ω = Σ dihedrals − π (not Van
// Oosterom–Strackee), areas by Heron, the circumradius by Crelle's formula from edge lengths.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <string>

#include "bisect/errors.hpp"
#include "bisect/quality.hpp"
#include "tet/tet_test_meshes.hpp"

namespace bisect {
namespace {

constexpr double kPi = 3.14159265358979323846;
double deg(double rad) { return rad * 180 / kPi; }

using Tet = std::array<Vec3, 4>;

TetQuality quality(const Tet& p) { return tet_quality(p[0], p[1], p[2], p[3]); }

// ---- reference formulas --------------------------------------------------------------------

// Interior angle at edge ij between the faces through k and l, from the projections of k and l
// on the plane normal to the edge. Radians.
double ref_dihedral(const Tet& p, int i, int j) {
  int k = -1, l = -1;
  for (int m = 0; m < 4; ++m)
    if (m != i && m != j) (k < 0 ? k : l) = m;
  const Vec3 e = (p[j] - p[i]).normalized();
  Vec3 a = p[k] - p[i], b = p[l] - p[i];
  a -= a.dot(e) * e;
  b -= b.dot(e) * e;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// Ω_i = sum of the dihedral angles at the three edges through corner i, minus π.
double ref_solid_angle(const Tet& p, int i) {
  double s = -kPi;
  for (int j = 0; j < 4; ++j)
    if (j != i) s += ref_dihedral(p, i, j);
  return s;
}

double ref_volume(const Tet& p) {
  Eigen::Matrix3d m;
  m << p[1] - p[0], p[2] - p[0], p[3] - p[0];
  return m.determinant() / 6;
}

// Heron, in Kahan's stable arrangement (a ≥ b ≥ c).
double heron(double a, double b, double c) {
  if (a < b) std::swap(a, b);
  if (a < c) std::swap(a, c);
  if (b < c) std::swap(b, c);
  return 0.25 * std::sqrt((a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c)));
}

double ref_area(const Tet& p) {
  auto d = [&](int i, int j) { return (p[i] - p[j]).norm(); };
  return heron(d(0, 1), d(1, 2), d(0, 2)) + heron(d(0, 1), d(1, 3), d(0, 3)) + heron(d(0, 2), d(2, 3), d(0, 3)) +
         heron(d(1, 2), d(2, 3), d(1, 3));
}

// Crelle's formula, from the products of opposite edges:
// 24 V R = sqrt((aa'+bb'+cc')(aa'+bb'−cc')(aa'−bb'+cc')(−aa'+bb'+cc')), products of opposite edges.
double ref_circumradius(const Tet& p) {
  auto d = [&](int i, int j) { return (p[i] - p[j]).norm(); };
  const double x = d(0, 1) * d(2, 3), y = d(0, 2) * d(1, 3), z = d(0, 3) * d(1, 2);
  return std::sqrt((x + y + z) * (x + y - z) * (x - y + z) * (-x + y + z)) / (24 * std::abs(ref_volume(p)));
}

struct Reference {
  double dmin = 1e9, dmax = -1e9, omega_min = 1e9, gamma = 0, alpha = 0, volume = 0;
};

Reference reference(const Tet& p) {
  Reference r;
  for (const auto& e : kTetEdge) {
    const double a = deg(ref_dihedral(p, e[0], e[1]));
    r.dmin = std::min(r.dmin, a);
    r.dmax = std::max(r.dmax, a);
  }
  for (int i = 0; i < 4; ++i) r.omega_min = std::min(r.omega_min, ref_solid_angle(p, i));
  r.volume = ref_volume(p);
  const double v = std::abs(r.volume), s = ref_area(p);
  r.gamma = 374.123 * v * v / (s * s * s);
  r.alpha = (3 * v / s) / ref_circumradius(p);
  return r;
}

void expect_matches_reference(const Tet& p, double tol) {
  const TetQuality q = quality(p);
  const Reference r = reference(p);
  EXPECT_NEAR(q.volume, r.volume, tol * std::abs(r.volume));
  EXPECT_NEAR(q.dihedral_min, r.dmin, tol * 180);
  EXPECT_NEAR(q.dihedral_max, r.dmax, tol * 180);
  EXPECT_NEAR(q.solid_angle_min, r.omega_min, tol * 4);
  EXPECT_NEAR(q.gamma, r.gamma, tol * std::max(1.0, r.gamma));
  EXPECT_NEAR(q.alpha, r.alpha, tol);
}

// ---- known tetrahedra ----------------------------------------------------------------------

// Edge 2√2, positively oriented.
Tet regular() { return {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, -1, 1), Vec3(-1, 1, -1)}; }

Tet right_corner() { return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}; }

// The square's corners lifted alternately by ±h; positively oriented.
Tet sliver(double h) { return {Vec3(0, 0, h), Vec3(1, 0, -h), Vec3(0, 1, -h), Vec3(1, 1, h)}; }

// Equilateral base of the given side in z = 0, apex above its centroid at the given height: a
// needle when the base is small, a cap when the apex is low.
Tet pyramid(double side, double height) {
  const double s3 = std::sqrt(3.0);
  return {Vec3(0, 0, 0), Vec3(side, 0, 0), Vec3(side / 2, side * s3 / 2, 0), Vec3(side / 2, side * s3 / 6, height)};
}

// The pyramid's angles in closed form, with t = height / inradius of the base. Each side face
// has outward normal ∝ (−t·m̂, 1) with m̂ the base direction from its edge to the centroid, and
// two such m̂ are 120° apart, so the side faces' normals have cosine (1 − t²/2)/(1 + t²).
struct PyramidAngles {
  double base, lateral;  // dihedral angles, radians
  double omega_apex, omega_base;
};

PyramidAngles pyramid_angles(double side, double height) {
  const double t = height / (side / (2 * std::sqrt(3.0)));
  PyramidAngles a;
  a.base = std::atan(t);
  a.lateral = kPi - std::acos((1 - t * t / 2) / (1 + t * t));
  a.omega_apex = 3 * a.lateral - kPi;
  a.omega_base = 2 * a.base + a.lateral - kPi;
  return a;
}

TEST(Quality, RegularTetrahedron) {
  const Tet p = regular();
  const TetQuality q = quality(p);
  const double edge = 2 * std::sqrt(2.0);
  EXPECT_NEAR(q.volume, edge * edge * edge / (6 * std::sqrt(2.0)), 1e-12);
  EXPECT_NEAR(q.dihedral_min, deg(std::acos(1.0 / 3)), 1e-10);
  EXPECT_NEAR(q.dihedral_max, deg(std::acos(1.0 / 3)), 1e-10);
  EXPECT_NEAR(q.dihedral_min, 70.5287793655, 1e-9);
  EXPECT_NEAR(q.solid_angle_min, std::acos(23.0 / 27), 1e-12);
  EXPECT_NEAR(q.gamma, 1.0, 1e-5);
  EXPECT_NEAR(q.alpha, 1.0 / 3, 1e-12);
  expect_matches_reference(p, 1e-10);
}

TEST(Quality, RightCornerTetrahedron) {
  const Tet p = right_corner();
  const TetQuality q = quality(p);
  const double s3 = std::sqrt(3.0);
  EXPECT_NEAR(q.volume, 1.0 / 6, 1e-15);
  // 90° at the edges through the origin, arccos(1/√3) at the edges of the slanted face.
  EXPECT_NEAR(q.dihedral_max, 90.0, 1e-12);
  EXPECT_NEAR(q.dihedral_min, deg(std::acos(1 / s3)), 1e-12);
  EXPECT_NEAR(q.dihedral_min, 54.7356103172, 1e-9);
  // Corner (1,0,0): edges (−1,0,0), (−1,1,0), (−1,0,1); triple product 1, lengths 1, √2, √2 and
  // dot products 1, 1, 1, so tan(Ω/2) = 1 / (2 + √2 + √2 + 1) = 3 − 2√2. The same value from the
  // dihedral angles: 90° + 2·arccos(1/√3) − 180°. The origin's π/2 is larger.
  const double omega = 2 * std::atan(3 - 2 * std::sqrt(2.0));
  EXPECT_NEAR(omega, 2 * std::acos(1 / s3) - kPi / 2, 1e-14);
  EXPECT_NEAR(q.solid_angle_min, omega, 1e-12);
  EXPECT_NEAR(ref_solid_angle(p, 0), kPi / 2, 1e-12);
  // S = 3·½ + (√3/4)·2 = (3 + √3)/2, V = 1/6: γ = β·(1/36) / S³.
  const double s = (3 + s3) / 2;
  EXPECT_NEAR(q.gamma, 374.123 / 36 / (s * s * s), 1e-12);
  EXPECT_NEAR(q.gamma, 0.7846097, 1e-6);
  // r = 3V/S = 1/(3 + √3), circumcentre (½,½,½) so R = √3/2.
  EXPECT_NEAR(q.alpha, (1 / (3 + s3)) / (s3 / 2), 1e-12);
  expect_matches_reference(p, 1e-10);
}

TEST(Quality, Needle) {
  const double side = 0.01, height = 1;
  const Tet p = pyramid(side, height);
  const PyramidAngles a = pyramid_angles(side, height);
  const TetQuality q = quality(p);
  // Lateral dihedrals tend to 60° (a thin triangular prism), base dihedrals to 90°.
  EXPECT_NEAR(q.dihedral_min, deg(a.lateral), 1e-9);
  EXPECT_NEAR(q.dihedral_max, deg(a.base), 1e-9);
  EXPECT_NEAR(q.dihedral_min, 60.0, 0.01);
  EXPECT_GT(q.dihedral_max, 89.8);
  // The apex sees the tiny base: Ω ≈ base area / height² = (√3/4)·10⁻⁴.
  EXPECT_NEAR(q.solid_angle_min, a.omega_apex, 1e-12);
  EXPECT_NEAR(q.solid_angle_min, std::sqrt(3.0) / 4 * side * side, 1e-7);
  // V = (√3/4)s²·H/3; S ≈ base + 3·(s/2)·slant height.
  const double v = std::sqrt(3.0) / 4 * side * side * height / 3;
  const double slant = std::sqrt(height * height + side * side / 12);
  const double s = std::sqrt(3.0) / 4 * side * side + 3 * side / 2 * slant;
  EXPECT_NEAR(q.gamma, 374.123 * v * v / (s * s * s), 1e-12);
  // Circumcentre on the axis at height z with ρ² + z² = (H − z)², ρ = s/√3 the base circumradius.
  const double rho2 = side * side / 3, z = (height * height - rho2) / (2 * height);
  EXPECT_NEAR(q.alpha, (3 * v / s) / (height - z), 1e-12);
  EXPECT_LT(q.alpha, 0.01);
  expect_matches_reference(p, 1e-9);
}

TEST(Quality, Sliver) {
  for (double h : {0.1, 0.01, 1e-4}) {
    SCOPED_TRACE(h);
    const Tet p = sliver(h);
    const TetQuality q = quality(p);
    // By hand, projecting the two other corners on the plane normal to each edge: at a
    // diagonal they project to (±½, ∓½, −2h) about its midpoint, an angle of π − 2·atan(2√2·h);
    // at a square side to (±4h²/L², 1, ±2h/L²) with L² = 1 + 4h², an angle of 2·atan(2h/L).
    const double side_angle = 2 * std::atan(2 * h / std::sqrt(1 + 4 * h * h));
    const double diagonal_angle = kPi - 2 * std::atan(2 * std::sqrt(2.0) * h);
    EXPECT_NEAR(q.volume, 2 * h / 3, 1e-15);
    EXPECT_NEAR(q.dihedral_min, deg(side_angle), 1e-9);
    EXPECT_NEAR(q.dihedral_max, deg(diagonal_angle), 1e-9);
    // All four corners alike: one diagonal and two sides meet at each.
    EXPECT_NEAR(q.solid_angle_min, diagonal_angle + 2 * side_angle - kPi, 1e-12);
    // Four congruent faces of area ½·√2·√(½ + 4h²): S = 2√(1 + 8h²). Circumcentre (½,½,0).
    const double s = 2 * std::sqrt(1 + 8 * h * h), v = 2 * h / 3;
    EXPECT_NEAR(q.gamma, 374.123 * v * v / (s * s * s), 1e-12);
    EXPECT_NEAR(q.alpha, (3 * v / s) / std::sqrt(0.5 + h * h), 1e-12);
    if (h <= 0.01) {
      EXPECT_LT(q.dihedral_min, 2.5);
      EXPECT_GT(q.dihedral_max, 176.0);
    }
    expect_matches_reference(p, 1e-8);
  }
}

TEST(Quality, Cap) {
  const double side = 1, height = 0.01;
  const Tet p = pyramid(side, height);
  const PyramidAngles a = pyramid_angles(side, height);
  const TetQuality q = quality(p);
  // The apex nearly in the base: side faces fold to nearly 180°, the base angle is small.
  EXPECT_NEAR(q.dihedral_min, deg(a.base), 1e-9);
  EXPECT_NEAR(q.dihedral_min, deg(std::atan(height * 2 * std::sqrt(3.0))), 1e-12);
  EXPECT_NEAR(q.dihedral_max, deg(a.lateral), 1e-9);
  EXPECT_GT(q.dihedral_max, 170.0);
  // The apex sees almost a hemisphere (Ω > π: Van Oosterom–Strackee's denominator is negative
  // there); the minimum is at a base corner.
  EXPECT_GT(a.omega_apex, 0.9 * 2 * kPi);
  EXPECT_NEAR(q.solid_angle_min, a.omega_base, 1e-12);
  expect_matches_reference(p, 1e-9);
}

// A generic tetrahedron (no symmetry) under the similarity transformations.
Tet generic() { return {Vec3(0.1, -0.2, 0.05), Vec3(1.3, 0.1, -0.2), Vec3(0.4, 1.1, 0.3), Vec3(0.6, 0.35, 0.9)}; }

template <class F>
Tet transformed(const Tet& p, F f) {
  return {f(p[0]), f(p[1]), f(p[2]), f(p[3])};
}

void expect_same_shape(const TetQuality& a, const TetQuality& b) {
  EXPECT_NEAR(a.dihedral_min, b.dihedral_min, 1e-9);
  EXPECT_NEAR(a.dihedral_max, b.dihedral_max, 1e-9);
  EXPECT_NEAR(a.solid_angle_min, b.solid_angle_min, 1e-12);
  EXPECT_NEAR(a.gamma, b.gamma, 1e-12);
  EXPECT_NEAR(a.alpha, b.alpha, 1e-12);
}

TEST(Quality, InvariantUnderSimilarity) {
  const Tet p = generic();
  const TetQuality q = quality(p);
  ASSERT_GT(q.volume, 0);
  expect_matches_reference(p, 1e-10);

  const Vec3 shift(1e3, -250.5, 17);
  const TetQuality moved = quality(transformed(p, [&](const Vec3& x) { return Vec3(x + shift); }));
  expect_same_shape(q, moved);
  EXPECT_NEAR(moved.volume, q.volume, 1e-9);

  for (double s : {1e-6, 1e-3, 7.5, 1e6}) {
    SCOPED_TRACE(s);
    const TetQuality scaled = quality(transformed(p, [&](const Vec3& x) { return Vec3(s * x); }));
    expect_same_shape(q, scaled);
    EXPECT_NEAR(scaled.volume, q.volume * s * s * s, 1e-12 * s * s * s);
  }

  const Eigen::Matrix3d rot = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const TetQuality rotated = quality(transformed(p, [&](const Vec3& x) { return Vec3(rot * x); }));
  expect_same_shape(q, rotated);
  EXPECT_NEAR(rotated.volume, q.volume, 1e-12);

  // A mirror image grades the same; only the signed volume tells it apart.
  const TetQuality mirrored = quality(transformed(p, [](const Vec3& x) { return Vec3(x.x(), -x.y(), x.z()); }));
  expect_same_shape(q, mirrored);
  EXPECT_NEAR(mirrored.volume, -q.volume, 1e-12);

  // Renumbering the corners (an odd permutation is a reflection of the numbering).
  const TetQuality swapped = quality({p[1], p[0], p[2], p[3]});
  expect_same_shape(q, swapped);
  EXPECT_NEAR(swapped.volume, -q.volume, 1e-12);
}

TEST(Quality, HugeAndTinyCoordinatesDoNotOverflow) {
  // In raw units V² ~ 1e±360 and S³ ~ 1e±360 would overflow or underflow; the measures are shape
  // only. (Far beyond ±1e100 the exact orientation test itself under- or overflows.)
  const TetQuality big = quality(transformed(regular(), [](const Vec3& x) { return Vec3(1e60 * x); }));
  EXPECT_NEAR(big.gamma, 1.0, 1e-5);
  EXPECT_NEAR(big.alpha, 1.0 / 3, 1e-12);
  EXPECT_NEAR(big.volume / 1e180, 8.0 / 3, 1e-12);
  const TetQuality small = quality(transformed(regular(), [](const Vec3& x) { return Vec3(1e-60 * x); }));
  EXPECT_NEAR(small.gamma, 1.0, 1e-5);
  EXPECT_NEAR(small.alpha, 1.0 / 3, 1e-12);
  EXPECT_NEAR(small.solid_angle_min, std::acos(23.0 / 27), 1e-12);
  EXPECT_NEAR(small.volume * 1e180, 8.0 / 3, 1e-12);
}

TEST(Quality, DegenerateTetrahedraGradeZero) {
  const Tet flat{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
  const Tet repeated{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 1)};
  const Tet collinear{Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2), Vec3(3, 3, 3)};
  const Tet nan{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, std::nan(""))};
  for (const Tet& p : {flat, repeated, collinear, nan}) {
    const TetQuality q = quality(p);
    EXPECT_EQ(q.volume, 0);
    EXPECT_EQ(q.dihedral_min, 0);
    EXPECT_EQ(q.dihedral_max, 0);
    EXPECT_EQ(q.solid_angle_min, 0);
    EXPECT_EQ(q.gamma, 0);
    EXPECT_EQ(q.alpha, 0);
  }
}

TEST(Quality, ElementQualityUsesCornerNodes) {
  TetMesh m = test::two_tet_mesh();
  const auto q1 = element_quality(m);
  ASSERT_EQ(q1.size(), 2u);
  const TetQuality direct = tet_quality(m.nodes[0], m.nodes[1], m.nodes[2], m.nodes[3]);
  EXPECT_EQ(q1[0].gamma, direct.gamma);
  EXPECT_GT(q1[1].volume, 0);

  // Order 2 with the mid-edge nodes pulled off their edges: the measures do not change.
  TetMesh m2 = test::to_order2(m);
  for (std::size_t n = m.nodes.size(); n < m2.nodes.size(); ++n) m2.nodes[n] += Vec3(0.05, -0.03, 0.02);
  const auto q2 = element_quality(m2);
  ASSERT_EQ(q2.size(), 2u);
  for (int t = 0; t < 2; ++t) {
    EXPECT_EQ(q2[t].volume, q1[t].volume);
    EXPECT_EQ(q2[t].dihedral_min, q1[t].dihedral_min);
  }

  // A tetrahedron naming a missing node grades as degenerate rather than reading past the end.
  m.tets[7] = 42;
  EXPECT_EQ(element_quality(m)[1].gamma, 0);
}

// A mixed set of hand-graded tetrahedra, values from the closed forms above:
//   regular     dihedral 70.53°/70.53°, Ω 0.5513, γ 1,      α 1/3
//   sliver .02  dihedral 4.58°/173.52°, Ω 0.0468, γ 0.0083, α 0.0282
//   needle .1   dihedral 60.08°/88.35°, Ω 0.0043, γ 0.2118, α 0.0559
//   flat        all 0
std::vector<TetQuality> mixed() {
  const Tet flat{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
  return {quality(regular()), quality(sliver(0.02)), quality(pyramid(0.1, 1)), quality(flat)};
}

std::vector<std::size_t> bins(std::size_t n, std::initializer_list<std::pair<std::size_t, std::size_t>> set) {
  std::vector<std::size_t> h(n, 0);
  for (auto [bin, count] : set) h[bin] = count;
  return h;
}

TEST(Quality, SummaryCountsAndHistograms) {
  const auto q = mixed();
  const QualitySummary s = summarize_quality(q);
  EXPECT_EQ(s.tets, 4u);

  EXPECT_EQ(s.dihedral_min.lo, 0);
  EXPECT_EQ(s.dihedral_min.hi, 90);
  EXPECT_EQ(s.dihedral_min.histogram, bins(18, {{0, 2}, {12, 1}, {14, 1}}));
  EXPECT_EQ(s.dihedral_max.hi, 180);
  EXPECT_EQ(s.dihedral_max.histogram, bins(18, {{0, 1}, {7, 1}, {8, 1}, {17, 1}}));
  EXPECT_EQ(s.solid_angle_min.hi, 0.6);
  EXPECT_EQ(s.solid_angle_min.histogram, bins(12, {{0, 3}, {11, 1}}));
  // γ of the regular tetrahedron is 1 + 7e-8, just above hi: clamped into the last bin.
  EXPECT_EQ(s.gamma.histogram, bins(10, {{0, 2}, {2, 1}, {9, 1}}));
  EXPECT_NEAR(s.alpha.hi, 1.0 / 3, 1e-15);
  EXPECT_EQ(s.alpha.histogram, bins(10, {{0, 2}, {1, 1}, {9, 1}}));

  EXPECT_EQ(s.dihedral_min.min, 0);
  EXPECT_NEAR(s.dihedral_min.max, 70.5287793655, 1e-9);
  EXPECT_NEAR(s.dihedral_max.max, q[1].dihedral_max, 0);
  EXPECT_NEAR(s.dihedral_min.mean, (q[0].dihedral_min + q[1].dihedral_min + q[2].dihedral_min) / 4, 1e-12);
  EXPECT_NEAR(s.gamma.mean, (q[0].gamma + q[1].gamma + q[2].gamma) / 4, 1e-15);
  EXPECT_NEAR(s.solid_angle_min.max, std::acos(23.0 / 27), 1e-12);
  EXPECT_DOUBLE_EQ(s.pct_dihedral_below_10, 50.0);
}

TEST(Quality, SummaryOfNothing) {
  const QualitySummary s = summarize_quality({});
  EXPECT_EQ(s.tets, 0u);
  EXPECT_EQ(s.dihedral_min.histogram, std::vector<std::size_t>(18, 0));
  EXPECT_EQ(s.solid_angle_min.histogram.size(), 12u);
  EXPECT_EQ(s.gamma.histogram.size(), 10u);
  EXPECT_EQ(s.pct_dihedral_below_10, 0);
}

TEST(Quality, SummaryOfStructuredMesh) {
  // The Kuhn cube: every tetrahedron congruent to the path simplex with dihedrals 45°, 60°, 90°.
  const auto q = element_quality(test::cube_mesh(2));
  const QualitySummary s = summarize_quality(q);
  EXPECT_EQ(s.tets, 48u);
  EXPECT_NEAR(s.dihedral_min.min, 45, 1e-9);
  EXPECT_NEAR(s.dihedral_max.max, 90, 1e-9);
  EXPECT_NEAR(s.gamma.min, s.gamma.max, 1e-12);
  EXPECT_EQ(s.pct_dihedral_below_10, 0);
}

TEST(Quality, ElementQualityIsTheSameOnEveryThreadCount) {
  // 6 * 12^3 = 10,368 tetrahedra: three chunks of the threads' work, the last one short; the
  // nodes jittered so that the tetrahedra differ
  TetMesh m = test::cube_mesh(12);
  for (std::size_t i = 0; i < m.nodes.size(); ++i) m.nodes[i] += 0.02 * Vec3(std::sin(3.0 * i), std::cos(5.0 * i), std::sin(7.0 * i));
  const auto one = element_quality(m, {}, 1);
  ASSERT_EQ(one.size(), m.num_tets());
  for (int threads : {2, 3, 0}) {
    const auto many = element_quality(m, {}, threads);
    ASSERT_EQ(many.size(), one.size());
    for (std::size_t t = 0; t < one.size(); ++t) {
      EXPECT_EQ(many[t].dihedral_min, one[t].dihedral_min) << "tetrahedron " << t << ", " << threads << " threads";
      EXPECT_EQ(many[t].alpha, one[t].alpha) << "tetrahedron " << t << ", " << threads << " threads";
    }
  }
  EXPECT_GT(one.back().alpha, 0);  // the last chunk's tetrahedra are graded too
  // Stop is asked between chunks, on this thread, whatever the count
  for (int threads : {1, 2}) {
    int asked = 0;
    EXPECT_THROW(element_quality(m, [&] { return ++asked == 2; }, threads), Cancelled);
    EXPECT_EQ(asked, 2);
  }
}

bool has_key(const std::string& json, const std::string& key) { return json.find("\"" + key + "\":") != std::string::npos; }

TEST(Quality, JsonHasTheContractKeys) {
  const std::string json = quality_json(summarize_quality(mixed()));
  ASSERT_FALSE(json.empty());
  EXPECT_EQ(json.front(), '{');
  EXPECT_EQ(json.back(), '}');
  for (const char* key : {"tets", "dihedral_min", "dihedral_max", "solid_angle_min", "solid_angle_mean", "gamma_mean",
                          "gamma_min", "alpha_mean", "pct_dihedral_below_10", "measures", "gamma", "alpha", "min",
                          "mean", "max", "lo", "hi", "histogram"})
    EXPECT_TRUE(has_key(json, key)) << key;
  EXPECT_NE(json.find("\"tets\":4,"), std::string::npos) << json;
  EXPECT_NE(json.find("\"pct_dihedral_below_10\":50"), std::string::npos) << json;
  EXPECT_NE(json.find("\"histogram\":[2,0,0,0,0,0,0,0,0,0,0,0,1,0,1,0,0,0]"), std::string::npos) << json;
  // Balanced braces and brackets, no NaN, no decimal comma.
  int depth = 0, brackets = 0;
  for (char c : json) {
    depth += c == '{' ? 1 : c == '}' ? -1 : 0;
    brackets += c == '[' ? 1 : c == ']' ? -1 : 0;
    ASSERT_GE(depth, 0);
  }
  EXPECT_EQ(depth, 0);
  EXPECT_EQ(brackets, 0);
  EXPECT_EQ(json.find("nan"), std::string::npos);
  EXPECT_EQ(json.find("inf"), std::string::npos);
}

TEST(Quality, JsonWritesNonFiniteAsNull) {
  QualitySummary s = summarize_quality({});
  s.gamma.mean = std::nan("");
  const std::string json = quality_json(s);
  EXPECT_NE(json.find("\"gamma_mean\":null"), std::string::npos) << json;
}

}  // namespace
}  // namespace bisect
