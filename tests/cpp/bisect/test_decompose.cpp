// Convex decomposition (thesis 6.5, 6.7, 7.3) on hand-made shapes whose cells are known, on the
// thesis's examples and on the STL models.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "bisect/errors.hpp"
#include "bisect/io.hpp"
#include "bisect/polyhedral_model.hpp"
#include "bisect/shared_models.hpp"
#include "bisect/decomposition_checks.hpp"
#include "input_error.hpp"
#include "poly_shapes.hpp"

namespace bisect {
namespace {

namespace fs = std::filesystem;

using test::poly;

TEST(Decompose, LPrismBecomesTwoBoxes) {
  const Decomposition d = decompose(poly(test::l_prism()));
  ASSERT_EQ(d.cells.size(), 2u);
  test::expect_valid_cells(d, 3.0);
  EXPECT_EQ(d.stats.bisections.at("cut_face"), 1u);
  for (const ConvexCell& c : d.cells) {
    const double v = [&] {
      double s = 0;
      for (std::size_t k = 0; k < c.faces.size(); ++k)
        s += (c.outward[k] ? 1 : -1) * d.model.faces[c.faces[k]].offset * d.model.face_area(c.faces[k]) / 3;
      return s;
    }();
    EXPECT_TRUE(std::abs(v - 1) < 1e-12 || std::abs(v - 2) < 1e-12) << v;  // the face extensions
  }
}

TEST(Decompose, ConvexInputIsOneCell) {
  const Decomposition d = decompose(poly(test::unit_cube()));
  ASSERT_EQ(d.cells.size(), 1u);
  EXPECT_TRUE(d.stats.bisections.empty());
  test::expect_valid_cells(d, 1.0);
}

TEST(Decompose, CubeWithCavityAndNeighbour) {
  const PolyInput in = read_poly(std::string(BISECT_TEST_DATA) + "/cube-cavity-adjacent-cube.poly");
  const Decomposition d = decompose(in);
  test::expect_valid_cells(d, summarize(in).volume);
  // the cavity left no cell, the neighbouring cube is convex already
  std::size_t of_region2 = 0;
  for (const ConvexCell& c : d.cells) of_region2 += c.source_region == 1;
  EXPECT_EQ(of_region2, 1u);
  EXPECT_GE(d.stats.bisections.at("splitting"), 1u);  // cavity removal splits the cube
}

TEST(Decompose, ReentryBoxWithFaceHole) {
  const PolyInput in = read_poly(std::string(BISECT_TEST_DATA) + "/reentry-box.poly");
  const Decomposition d = decompose(in);
  EXPECT_GE(d.cells.size(), 5u);  // the pocket's four walls and its bottom are all reflex
  test::expect_valid_cells(d, summarize(in).volume);
}

class DecomposeSharedModels : public ::testing::TestWithParam<std::string> {};

TEST_P(DecomposeSharedModels, CellsAreConvexAndCoverTheInput) {
  const fs::path p = fs::path(BISECT_SHARED_DIR) / GetParam();
  if (!fs::exists(p)) GTEST_SKIP() << p << " is not here (../shared is absent)";
  const PolyInput in = read_polyhedral(p.string());
  const Decomposition d = decompose(in);
  // STL coordinates are single precision: faces meant to be coplanar are so only to ~1e-7
  test::expect_valid_cells(d, summarize(in).volume, p.extension() == ".stl" ? 1e-6 : 1e-9);
  EXPECT_EQ(d.stats.convex_cells, d.cells.size());
}

INSTANTIATE_TEST_SUITE_P(Files, DecomposeSharedModels,
                         ::testing::ValuesIn(test::kSharedPolyhedralInputs),
                         [](const auto& info) { return test::test_name_of(info.param); });

TEST(Decompose, CancelStopsTheWork) {
  DecomposeOptions opt;
  opt.progress = [](double) { return false; };
  EXPECT_THROW(decompose(poly(test::l_prism()), opt), Cancelled);
}

TEST(Decompose, StatsJsonNamesTheFigures) {
  const Decomposition d = decompose(poly(test::l_prism()));
  const std::string j = decompose_stats_json(d.stats);
  for (const char* key : {"\"convex_cells\": 2", "\"bisections\"", "\"cut_face\": 1", "\"rejected_planes\"", "\"init_geom\"", "\"bisect\""})
    EXPECT_NE(j.find(key), std::string::npos) << key << " in " << j;
}

}  // namespace
}  // namespace bisect
