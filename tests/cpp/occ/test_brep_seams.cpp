// A face piece's boundary chained across a seam (pipeline/brep_piece_mesh.cpp, chain_loops): the
// piece of a full conical face runs up one side of its seam and down the other, and where the
// proxy has a node on the seam (a cone's tessellation has rows along its side) the chain has two
// ways on, down the same side or back up the other. Going back is the way it came in 3D, which the
// clockwise angle put at 0 or at 2 pi by the sign of a round-off: FreeCAD's Part.makeCone(10, 3,
// 30) chained its side as two loops, each crossing the seam, which no (u, v) mesher can use, and
// the side was meshed on the proxy facets' planes, with needles of 0.6 degrees along its
// generators.
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

constexpr double kFrustumVolume = 1390 * M_PI;

TEST(BrepSeams, AFrustumsSideIsMeshedOnItsSurface) {
  const BrepInput in = test::input_through_string(test::make_frustum(), "frustum");
  // R = 300 is under the curvature's floor (12 elements a turn on radius 3); 3,000 and 30,000
  // above it. Measured with the side on the facets: smallest surface angles 10.0, 10.3 and 16.1
  // degrees, smallest dihedral 4.2, 6.4 and 8.4, mean alpha 0.134, 0.199, 0.260; now 30.9, 30.2
  // and 27.9, 19.9, 24.2 and 12.8, 0.253, 0.271, 0.270.
  for (int R : {300, 3000, 30000}) {
    GenerateOptions opt;
    opt.sizing.elements = R;
    GenerateStats st;
    const TetMesh m = generate_brep_mesh(in, opt, &st);
    const std::vector<Violation> bad = validate(m);
    ASSERT_TRUE(bad.empty()) << R << ": " << bad.size() << " violations, first: " << to_string(bad.front().kind);
    // chords short of the circles: at the floor 12 a turn on radius 3 (an inscribed 12-gon holds
    // 95.5% of its circle's area)
    EXPECT_NEAR(test::corner_volume(m), kFrustumVolume, (R == 300 ? 0.05 : 0.01) * kFrustumVolume) << R;
    EXPECT_GE(st.surface_min_angle, 25.0) << R;
    const QualitySummary q = summarize_quality(element_quality(m));
    EXPECT_GE(q.dihedral_min.min, 11.0) << R;
    EXPECT_GE(q.alpha.mean, 0.24) << R;
    if (R > 300) {
      EXPECT_NEAR(static_cast<double>(m.num_tets()), R, 0.2 * R) << R;
    }
  }
}

// A piece whose (u, v) grid folds over in 3D, in either chart, gets a third try before the
// facets' planes: the same (u, v) mesher with the boundary first triangulated in the surface's
// metric averaged over it (RegionMeshOptions::boundary_in_surface_metric). FreeCAD's scaled
// sphere at R = 3,000 had one piece on its facets (smallest surface angle 21.5, dihedral 13.9
// degrees, mean alpha 0.251); now none (20.9, 15.3, 0.255).
TEST(BrepSeams, APieceThatFoldsInItsChartIsMeshedOnItsSurfaceAgain) {
  const BrepInput in = test::input_through_string(test::make_ellipsoid(), "ellipsoid");
  GenerateOptions opt;
  opt.sizing.elements = 3000;
  GenerateStats st;
  const TetMesh m = generate_brep_mesh(in, opt, &st);
  const std::vector<Violation> bad = validate(m);
  ASSERT_TRUE(bad.empty()) << bad.size() << " violations, first: " << to_string(bad.front().kind);
  EXPECT_EQ(st.facet_pieces, 0);
  EXPECT_GE(st.surface_min_angle, 18.0);
  EXPECT_GE(summarize_quality(element_quality(m)).dihedral_min.min, 12.0);
  // and the frustum, whose side meshes in its chart, has none either
  GenerateStats fs;
  opt.sizing.elements = 30000;
  const TetMesh f = generate_brep_mesh(test::input_through_string(test::make_frustum(), "frustum"), opt, &fs);
  EXPECT_TRUE(validate(f).empty());
  EXPECT_EQ(fs.facet_pieces, 0);
}

}  // namespace
}  // namespace bisect
