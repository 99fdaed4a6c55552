// The size field's sampling cache (size/brep_sizes.hpp): the count search builds the field again
// at every round; with the samples kept, the field must be the same as one built afresh, at
// every base, coarser and finer rounds mixed. And a body of a compound takes its sizes from its
// own geometry alone.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Ax2.hxx>

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

// A compound of two bodies apart: a cylinder of radius 1 at the origin and one of radius 0.2 at
// x = 20. Meshed body by body (brep_bodies.cpp), the first's input lists its solid alone but
// keeps every face; its field has no source of the thin one's curvature (which asked for 0.105
// there, and 0.105 as the smallest curvature size), and is the same as the whole one's at its own
// surface.
TEST(BrepSizeField, ABodyTakesItsSizesFromItsOwnFaces) {
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  b.Add(c, BRepPrimAPI_MakeCylinder(1, 2).Shape());
  b.Add(c, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(20, 0, 0), gp_Dir(0, 0, 1)), 0.2, 2).Shape());
  const BrepInput in = test::input_through_string(c, "two cylinders");
  ASSERT_EQ(in.solids.size(), 2u);
  BrepInput first = in;
  first.solids.clear();
  for (const BrepSolid& s : in.solids)
    if (s.bbox_max.x() < 10) first.solids.push_back(s);
  ASSERT_EQ(first.solids.size(), 1u);
  const BrepTessellation tess = in.tessellate(0.05, 0.3);
  SizeOptions o;
  o.curvature_elements = 12;  // 2 pi / 12 r: 0.52 on the first, 0.105 on the thin one
  const double base = 1;
  size::BrepSizeReport whole_report, own_report;
  const size::SizeField whole = size::brep_size_field(in, tess, base, o, &whole_report);
  const size::SizeField own = size::brep_size_field(first, tess, base, o, &own_report);
  EXPECT_LT(own.sources(), whole.sources());
  EXPECT_NEAR(whole_report.smallest_curvature_size, 2 * M_PI / 12 * 0.2, 0.01);
  EXPECT_NEAR(own_report.smallest_curvature_size, 2 * M_PI / 12, 0.05);
  const Vec3 thin(20.2, 0, 1), wide(1, 0, 1);
  EXPECT_LT(whole.at(thin), 0.2);
  EXPECT_EQ(own.at(thin), base);
  EXPECT_EQ(own.at(wide), whole.at(wide));
  EXPECT_LT(own.at(wide), 0.6);
}

}  // namespace
}  // namespace bisect
