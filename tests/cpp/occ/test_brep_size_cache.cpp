// The size field's sampling cache (size/brep_sizes.hpp): the count search builds the field again
// at every round; with the samples kept, the field must be the same as one built afresh, at
// every base, coarser and finer rounds mixed.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>

#include <random>

#include "bisect/occ.hpp"
#include "occ_checks.hpp"
#include "size/brep_sizes.hpp"

namespace bisect {
namespace {

TEST(BrepSizeCache, TheFieldIsTheSameWithTheSamplesKept) {
  const BrepInput in =
      test::input_through_string(BRepAlgoAPI_Cut(BRepPrimAPI_MakeCylinder(5, 50).Shape(), BRepPrimAPI_MakeCylinder(4, 50).Shape()).Shape(), "tube");
  const BrepTessellation tess = in.tessellate(0.05, 0.3);
  SizeOptions o;
  o.curvature_elements = 24;  // 1.05 on the bore (radius 4), 1.31 outside
  size::SizeSamplingCache cache;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-6, 6), z(-1, 51);
  for (double base : {4.0, 2.0, 8.0, 1.2, 2.0}) {
    size::BrepSizeReport fresh_report, kept_report;
    const size::SizeField fresh = size::brep_size_field(in, tess, base, o, &fresh_report);
    const size::SizeField kept = size::brep_size_field(in, tess, base, o, &kept_report, nullptr, &cache);
    EXPECT_EQ(kept.sources(), fresh.sources()) << base;
    EXPECT_EQ(kept_report.curvature_sources, fresh_report.curvature_sources) << base;
    EXPECT_EQ(kept_report.edge_sources, fresh_report.edge_sources) << base;
    EXPECT_EQ(kept_report.smallest_curvature_size, fresh_report.smallest_curvature_size) << base;
    EXPECT_GT(fresh.sources(), 0u) << "the tube's curvature asks for less than " << base;
    for (int i = 0; i < 200; ++i) {
      const Vec3 x(u(rng), u(rng), z(rng));
      EXPECT_EQ(kept.at(x), fresh.at(x)) << base << " at " << x.transpose();
    }
  }
  // every curved face's triangles were probed once and kept (planar faces have no curvature)
  ASSERT_EQ(cache.triangles.size(), tess.faces.size());
  for (std::size_t f = 0; f < in.faces.size(); ++f)
    for (const auto& t : cache.triangles[f]) EXPECT_EQ(t.probed, !in.faces[f].planar) << "face " << f + 1;
}

}  // namespace
}  // namespace bisect
