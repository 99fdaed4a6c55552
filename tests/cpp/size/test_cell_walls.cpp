// The walls of convex cells (polyhedral route, issue 17): the thickness between a cell's facing
// input faces, and the generator keeping elements across a thin bar at a coarse count.
#include <gtest/gtest.h>

#include "bisect/generate.hpp"
#include "bisect/polyhedral_model.hpp"
#include "bisect/quality.hpp"
#include "poly_shapes.hpp"
#include "size/cell_walls.hpp"

namespace bisect::size {
namespace {

// A box x by y by z: the unit square prism scaled.
PolyInput box(double x, double y, double z) {
  PolyInput in = test::poly(test::unit_cube());
  for (Vec3& p : in.nodes) p = Vec3(p.x() * x, p.y() * y, p.z() * z);
  return in;
}

TEST(CellWalls, ABoxIsAsThickAsItsSmallestSide) {
  for (const auto& [dims, thickness] : std::vector<std::pair<Vec3, double>>{{{10, 1, 3}, 1.0}, {{3, 3, 3}, 3.0}, {{4, 7, 2.5}, 2.5}}) {
    const Decomposition d = decompose(box(dims.x(), dims.y(), dims.z()));
    ASSERT_EQ(d.cells.size(), 1u);
    const std::vector<double> t = cell_wall_thickness(d);
    ASSERT_EQ(t.size(), 1u);
    EXPECT_NEAR(t[0], thickness, 1e-12) << dims.transpose();
  }
}

TEST(CellWalls, EveryCellOfAnLPrismLiesInItsWalls) {
  // the L's arms are 1 wide, the prism 1 high: each cell is 1 thick whichever way it was cut
  const Decomposition d = decompose(test::poly(test::l_prism()));
  ASSERT_GE(d.cells.size(), 2u);
  for (double t : cell_wall_thickness(d)) EXPECT_NEAR(t, 1.0, 1e-12);
}

TEST(CellWalls, AThinBarAtACoarseCountGetsElementsAcrossIt) {
  // 10 x 1 x 1 at 20 elements: the spacing from R (about 1.6) is wider than the bar; capped at
  // 0.8 the bar gets nodes inside and no flat tetrahedra, more elements than asked, and says why
  GenerateOptions opt;
  opt.sizing.elements = 20;
  GenerateStats st;
  const TetMesh m = generate_mesh(box(10, 1, 1), opt, &st);
  const QualitySummary q = summarize_quality(element_quality(m));
  EXPECT_GE(q.dihedral_min.min, 10.0);
  EXPECT_GE(q.alpha.mean, 0.2);
  EXPECT_GT(m.num_tets(), 40u);
  EXPECT_GT(st.count_floor, 20);
  EXPECT_EQ(st.count_floor_reason.rfind("thickness: walls down to 1 thick", 0), 0u) << st.count_floor_reason;
}

}  // namespace
}  // namespace bisect::size
