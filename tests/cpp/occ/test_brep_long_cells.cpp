// A rod (radius 5, length 200: one convex cell in the proxy) is a cell that no point sees whole
// once its faces lie on the true cylinder: the far triangles are seen edge-on from its middle and
// the bulge tilts them past. It is filled by Delaunay boundary recovery (tet/recovery_fill.hpp),
// at 2·10^4 elements and at 2,000, where its coarse grid is not a Delaunay surface and the
// missing triangles are restored by local re-triangulation (tet/face_recovery.hpp).
#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeCylinder.hxx>

#include <cmath>
#include <string>

#include "bisect/generate.hpp"
#include "bisect/occ.hpp"
#include "bisect/quality.hpp"
#include "bisect/validate.hpp"
#include "occ_checks.hpp"

namespace bisect {
namespace {

BrepInput cylinder(double r, double h, const char* name) {
  return test::input_through_string(BRepPrimAPI_MakeCylinder(r, h).Shape(), name);
}

BrepInput rod() { return cylinder(5, 200, "rod"); }

TEST(BrepLongCells, ARodIsFilledByBoundaryRecovery) {
  const BrepInput in = rod();
  for (int R : {2000, 20000}) {
  GenerateOptions opt;
  opt.sizing.elements = R;
  opt.order = R == 2000 ? 2 : 1;
  GenerateStats st;
  const TetMesh m = generate_brep_mesh(in, opt, &st);
  EXPECT_TRUE(validate(m).empty()) << R;
  EXPECT_GE(st.recovered_cells, 1) << R;
  // within 20% of R, or above it where the curvature bound (12 elements per turn of the rod's
  // circumference, 2.6 mm) asks for more than R allows: at 2,000 the spacing would be 4 mm
  if (st.count_floor > 0) EXPECT_NE(st.count_floor_reason.find("curvature"), std::string::npos) << R;
  else EXPECT_NEAR(static_cast<double>(m.num_tets()), R, 0.2 * R);
  const QualitySummary q = summarize_quality(element_quality(m));
  EXPECT_GE(q.dihedral_min.min, 5.0) << R;
  // within the chords' error: at 12 or more segments per turn the section is at least the
  // inscribed 12-gon's, 4.5% under the circle's
  const double v = test::corner_volume(m), want = 5000 * M_PI;
  EXPECT_LE(v, want * (1 + 1e-9));
  EXPECT_GE(v, want * 12 / (2 * M_PI) * std::sin(2 * M_PI / 12)) << R;
  }
}

// A short cylinder meshed coarsely is one cell whose side is one face piece running all the way
// round: the piece's proxy facets' normals sum to nothing, and its triangles' turn must be read
// facet by facet (brep_grids.cpp). It came out inside out at 200 to 1,000 elements.
TEST(BrepLongCells, AWholeCylinderSideTurnsOutwards) {
  const BrepInput in = cylinder(0.8, 2, "cylinder");
  for (int R : {200, 500, 1000}) {
    GenerateOptions opt;
    opt.sizing.elements = R;
    GenerateStats st;
    const TetMesh m = generate_brep_mesh(in, opt, &st);
    EXPECT_TRUE(validate(m).empty()) << R;
    const double v = test::corner_volume(m), want = 0.64 * 2 * M_PI;
    EXPECT_LE(v, want * (1 + 1e-9)) << R;
    EXPECT_GE(v, want * 12 / (2 * M_PI) * std::sin(2 * M_PI / 12)) << R;
  }
}

}  // namespace
}  // namespace bisect
