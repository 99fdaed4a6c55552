// A curved face made as a B-spline with degenerate edges at its poles (FreeCAD's scaled sphere,
// transformGeometry; the revolved shapes of STEP files): its curvature there is the surface's,
// not the round-off of a degenerate parametrisation, and the size field asks no more of it.
#include <gtest/gtest.h>

#include <cmath>

#include "bisect/generate.hpp"
#include "bisect/occ.hpp"
#include "bisect/quality.hpp"
#include "bisect/validate.hpp"
#include "occ_checks.hpp"
#include "occ_shapes.hpp"

namespace bisect {
namespace {

constexpr double kEllipsoidVolume = 4000 * M_PI / 3;

TEST(BrepPoles, TheEllipsoidsCurvatureIsItsOwnAtThePoles) {
  const BrepInput in = test::input_through_string(test::make_ellipsoid(), "ellipsoid");
  ASSERT_EQ(in.faces.size(), 1u);
  const ParametricSurface& s = *in.faces[0].surface;
  // over the whole parameter box, poles included: at most 1 / 1.25 (at the x tips); the pole
  // rows came out at 10^15, and the size field asked for its floor there
  const Vec2 lo = s.uv_min(), hi = s.uv_max();
  double most = 0;
  for (int i = 0; i <= 100; ++i)
    for (int j = 0; j <= 100; ++j) most = std::max(most, s.max_curvature(lo + (hi - lo).cwiseProduct(Vec2(i / 100.0, j / 100.0))));
  EXPECT_LE(most, 0.8 * (1 + 1e-6));
  EXPECT_GE(most, 0.79);
  // at the poles (0, 0, +-5): the curvatures there are 5 / 20^2 and 5 / 10^2
  for (double v : {lo.y(), hi.y()}) {
    const Vec2 pole(0.5 * (lo.x() + hi.x()), v);
    ASSERT_NEAR(std::abs(s.point(pole).z()), 5.0, 1e-9);
    EXPECT_NEAR(s.max_curvature(pole), 0.05, 1e-4);  // measured a millionth of the range beside it
  }
}

TEST(BrepPoles, AnEllipsoidMeshesAtItsCurvaturesFloor) {
  const BrepInput in = test::input_through_string(test::make_ellipsoid(), "ellipsoid");
  // R = 300 is under the curvature's floor (12 elements a turn on radii down to 1.25: elements
  // of 0.654 at the tips); with the poles' false curvature the floor was 14,195 tetrahedra
  // (elements of 0.07 round the poles) in 4.8 s, now some 3,900 in under a second
  GenerateOptions coarse;
  coarse.sizing.elements = 300;
  GenerateStats st;
  const TetMesh floor = generate_brep_mesh(in, coarse, &st);
  EXPECT_TRUE(validate(floor).empty());
  EXPECT_LT(floor.num_tets(), 6000u);
  EXPECT_NE(st.count_floor_reason.find("curvature: elements down to 0.65"), std::string::npos) << st.count_floor_reason;
  // above the floor: R is met, at order 2 too
  GenerateOptions opt;
  opt.sizing.elements = 30000;
  opt.order = 2;
  const TetMesh m = generate_brep_mesh(in, opt, &st);
  const std::vector<Violation> bad = validate(m);
  ASSERT_TRUE(bad.empty()) << bad.size() << " violations, first: " << to_string(bad.front().kind);
  EXPECT_EQ(st.count_floor, 0) << st.count_floor_reason;
  EXPECT_NEAR(static_cast<double>(m.num_tets()), 30000, 0.2 * 30000);
  EXPECT_NEAR(test::corner_volume(m), kEllipsoidVolume, 0.01 * kEllipsoidVolume);
  const QualitySummary q = summarize_quality(element_quality(m));
  EXPECT_GE(q.dihedral_min.min, 10.0);
  EXPECT_GE(q.alpha.mean, 0.25);
}

}  // namespace
}  // namespace bisect
