// The count floor for quality's sake (pipeline/quality_floor.hpp): the counts it asks, its bars,
// and the polyhedral generator on a plate with a round end of 32 facets, built here, whose mesh
// for R = 300 the walls' cap leaves poor (mean alpha 0.13, a smallest dihedral of 4 degrees).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "bisect/generate.hpp"
#include "bisect/quality.hpp"
#include "bisect/validate.hpp"
#include "pipeline/quality_floor.hpp"
#include "poly_shapes.hpp"

namespace bisect {
namespace {

PolyInput round_ended_plate() { return test::poly(test::round_ended_plate()); }

QualitySummary quality_of(const TetMesh& m) { return summarize_quality(element_quality(m)); }

TEST(QualityFloorRule, CountsGrowByHalvesUpToFourTimesTheFirst) {
  EXPECT_EQ(pipeline::quality_floor_counts(1000), (std::vector<std::int64_t>{1500, 2250, 3375, 4000}));
  EXPECT_EQ(pipeline::quality_floor_counts(5000).back(), 20000);
  EXPECT_TRUE(pipeline::quality_floor_counts(5001).empty());  // not a coarse mesh
  EXPECT_TRUE(pipeline::quality_floor_counts(0).empty());
}

TEST(QualityFloorRule, TheBarsAndWhatIsKept) {
  EXPECT_DOUBLE_EQ(pipeline::quality_bars(999).alpha_mean, 0.20);
  EXPECT_DOUBLE_EQ(pipeline::quality_bars(1000).alpha_mean, 0.24);
  QualitySummary first, more;
  first.tets = 1000, first.alpha.mean = 0.214, first.dihedral_min.min = 12.2;
  const pipeline::QualityBars bars = pipeline::quality_bars(1000);
  EXPECT_FALSE(pipeline::meets_mean_bar(first, bars));
  more.tets = 3000, more.alpha.mean = 0.243, more.dihedral_min.min = 10.1;
  EXPECT_TRUE(pipeline::floor_keeps(more, first, bars));
  more.dihedral_min.min = 9.9;  // the first mesh met 10 degrees: so must the one kept
  EXPECT_FALSE(pipeline::floor_keeps(more, first, bars));
  first.dihedral_min.min = 6.6;  // it did not: 0.8 times its angle will do
  more.dihedral_min.min = 5.4;
  EXPECT_TRUE(pipeline::floor_keeps(more, first, bars));
  more.dihedral_min.min = 5.2;
  EXPECT_FALSE(pipeline::floor_keeps(more, first, bars));
  more.dihedral_min.min = 12, more.alpha.mean = 0.239;  // the mean's bar holds whatever the angle
  EXPECT_FALSE(pipeline::floor_keeps(more, first, bars));
}

TEST(QualityFloor, APoorCoarseMeshGetsMoreElementsAndSaysWhy) {
  const PolyInput in = round_ended_plate();
  GenerateOptions opt;
  opt.sizing.elements = 300;
  opt.quality_floor = false;
  GenerateStats off;
  const TetMesh first = generate_mesh(in, opt, &off);
  const QualitySummary q0 = quality_of(first);
  // the shortfall the floor is for: the walls' cap holds the count above R, and it is poor
  ASSERT_LT(q0.alpha.mean, 0.20) << first.num_tets() << " tetrahedra";
  EXPECT_EQ(off.quality_meshes, 0);

  opt.quality_floor = true;
  GenerateStats st;
  const TetMesh m = generate_mesh(in, opt, &st);
  ASSERT_TRUE(validate(m).empty());
  const QualitySummary q = quality_of(m);
  EXPECT_GE(q.alpha.mean, 0.20);
  EXPECT_GE(q.dihedral_min.min, 10.0);
  EXPECT_GT(m.num_tets(), first.num_tets());
  EXPECT_LE(m.num_tets(), 4 * first.num_tets());
  EXPECT_EQ(st.count_floor, static_cast<std::int64_t>(m.num_tets()));
  EXPECT_EQ(st.tets, static_cast<std::int64_t>(m.num_tets()));
  EXPECT_GE(st.quality_meshes, 1);
  EXPECT_GT(st.fillings, off.fillings);  // the work of the meshes made is counted
  EXPECT_EQ(st.count_floor_reason.rfind("quality: the mesh for R = 300 (" + std::to_string(first.num_tets()) + " tetrahedra)", 0), 0u)
      << st.count_floor_reason;

  // the same for any thread count
  opt.threads = 1;
  const TetMesh one = generate_mesh(in, opt);
  EXPECT_EQ(one.num_tets(), m.num_tets());
  EXPECT_EQ(one.nodes, m.nodes);
}

TEST(QualityFloor, AGivenSizeOrAGoodMeshIsLeftAlone) {
  const PolyInput in = round_ended_plate();
  GenerateOptions opt;
  opt.sizing.size = 0.5;  // the user chose the size
  GenerateStats st;
  const TetMesh m = generate_mesh(in, opt, &st);
  EXPECT_EQ(st.quality_meshes, 0);
  EXPECT_EQ(st.count_floor_reason.rfind("quality", 0), std::string::npos);
  opt.quality_floor = false;
  EXPECT_EQ(generate_mesh(in, opt).num_tets(), m.num_tets());

  // the unit cube at R = 1000 meets the bars: one mesh
  GenerateOptions cube;
  cube.sizing.elements = 1000;
  GenerateStats cs;
  const TetMesh c = generate_mesh(test::poly(test::unit_cube()), cube, &cs);
  EXPECT_GE(quality_of(c).alpha.mean, 0.24);
  EXPECT_EQ(cs.quality_meshes, 0);
  EXPECT_EQ(cs.count_floor_reason.rfind("quality", 0), std::string::npos);
}

}  // namespace
}  // namespace bisect
