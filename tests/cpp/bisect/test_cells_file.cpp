// The written cells file, read back and checked by the independent checker of tests/support
// against the input: for the thesis's examples and for every STL model.
#include <gtest/gtest.h>

#include <filesystem>

#include "bisect/io.hpp"
#include "bisect/polyhedral_model.hpp"
#include "bisect/shared_models.hpp"
#include "decomposition_checker.hpp"

namespace bisect {
namespace {

namespace fs = std::filesystem;

testing::CellCheck decompose_and_check(const PolyInput& in, const std::string& name, double geom_tol) {
  const Decomposition d = decompose(in);
  const std::string path = ::testing::TempDir() + "/cells_" + name + ".poly";
  write_cells_poly(d, path);
  const PolyInput cells = read_poly(path);
  return testing::check_decomposition(in, cells, testing::cell_regions_of_file(path), geom_tol);
}

std::string report(const testing::CellCheck& c) {
  std::string s;
  for (const auto& p : c.problems) s += p + "\n";
  return s;
}

class CellsFile : public ::testing::TestWithParam<std::string> {};

TEST_P(CellsFile, IndependentCheckerAcceptsTheCells) {
  const fs::path p = fs::path(BISECT_SHARED_DIR) / GetParam();
  if (!fs::exists(p)) GTEST_SKIP() << p << " is not here (../shared is absent)";
  const PolyInput in = read_polyhedral(p.string());
  // STL coordinates are single precision: their coplanar facets are coplanar to about 1e-7
  const double tol = p.extension() == ".stl" ? 1e-6 : 1e-9;
  const testing::CellCheck c = decompose_and_check(in, p.stem().string(), tol);
  EXPECT_TRUE(c.problems.empty()) << report(c);
  EXPECT_LT(c.max_volume_rel_error, 1e-9);
  EXPECT_LT(c.max_coverage_rel_error, 1e-9);
  RecordProperty("cells", static_cast<int>(c.cells));
}

INSTANTIATE_TEST_SUITE_P(Shared, CellsFile,
                         ::testing::ValuesIn(test::kSharedPolyhedralInputs),
                         [](const auto& info) { return test::test_name_of(info.param); });

TEST(CellsFile, BundledExamplesWithoutShared) {
  for (const char* f : {"cube-cavity-adjacent-cube.poly", "reentry-box.poly"}) {
    const PolyInput in = read_poly(std::string(BISECT_TEST_DATA) + "/" + f);
    const testing::CellCheck c = decompose_and_check(in, fs::path(f).stem().string() + "_bundled", 1e-9);
    EXPECT_TRUE(c.problems.empty()) << f << "\n" << report(c);
  }
}

}  // namespace
}  // namespace bisect
