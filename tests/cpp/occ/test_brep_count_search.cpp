// The B-rep route's count search (pipeline/brep_generate.cpp, count_calibration.hpp's
// expected_spacing): where it starts, and that it places the nodes once where the start predicts
// R within 5% and a bounded number of times where the count jumps between two spacings.
#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>

#include <cmath>

#include "bisect/generate.hpp"
#include "bisect/occ.hpp"
#include "bisect/validate.hpp"
#include "occ_checks.hpp"
#include "occ_shapes.hpp"
#include "pipeline/count_calibration.hpp"

namespace bisect {
namespace {

// The shape meshed at R = 10^5, checked valid and within 10% of R; its statistics.
GenerateStats mesh_at_100k(const TopoDS_Shape& shape, const char* name) {
  GenerateOptions opt;
  opt.sizing.elements = 100000;
  GenerateStats st;
  const TetMesh m = generate_brep_mesh(test::input_through_string(shape, name), opt, &st);
  EXPECT_TRUE(validate(m).empty()) << name;
  EXPECT_NEAR(static_cast<double>(m.num_tets()), 1e5, 1e4) << name;
  return st;
}

TEST(CountSearch, TheExpectedSpacingSolvesItsEquation) {
  for (double V : {1.0, 64.0, 5e5})
    for (double A : {0.0, 6.0, 4e4})
      for (double R : {100.0, 1e5, 1e6}) {
        const double h = pipeline::expected_spacing(V, A, R, pipeline::kBrepNodes);
        ASSERT_GT(h, 0) << V << " " << A << " " << R;
        EXPECT_NEAR((6.0 * V / h / h / h + 1.7 * A / h / h) / R, 1.0, 1e-9) << V << " " << A << " " << R;
        // with no boundary term, the volume's alone: finer than the thesis's nominal spacing
        // (8 V / h^3); a boundary's nodes carry tetrahedra too, so its term makes it coarser
        if (A == 0) {
          EXPECT_NEAR(h, std::cbrt(6.0 * V / R), 1e-9 * h);
          EXPECT_LT(h, nominal_spacing(V, R));
        } else {
          EXPECT_GT(h, pipeline::expected_spacing(V, 0, R, pipeline::kBrepNodes));
        }
      }
  EXPECT_EQ(pipeline::expected_spacing(0, 1, 1000, pipeline::kBrepNodes), 0);  // no volume: no spacing (the caller's nominal is 0 too)
}

// A box with a hole: the start predicts R within 5%, so the nodes are placed once (twice when the
// search started at the nominal spacing, which predicted 20% too few tetrahedra).
TEST(CountSearch, ABoxWithAHolePlacesItsNodesOnce) {
  const GenerateStats st = mesh_at_100k(test::make_box_minus_cylinder(), "box-hole");
  EXPECT_EQ(st.placements, 1);
  EXPECT_EQ(st.proxy_attempts, 1);
}

// A 100 x 10 x 10 bar at 10^5: its count jumps between two spacings 3% apart (91.5k and 108.5k
// predicted), and cube-root steps from either side jumped back and forth (five placements). Once
// two spacings bracket R the next lies between them: three placements.
TEST(CountSearch, ABarWhoseCountJumpsIsBracketed) {
  EXPECT_LE(mesh_at_100k(BRepPrimAPI_MakeBox(100, 10, 10).Shape(), "bar").placements, 3);
}

}  // namespace
}  // namespace bisect
