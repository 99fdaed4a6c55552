// Issue 17's quality table: element quality at every count down to the coarsest, through both
// routes (STL through the polyhedral generator, B-rep through the true-surface one), on the
// models that FEM users mesh coarse: cantilever, slender-appendage, lug, plate-hole (STL and
// B-rep) and two-boxes-cavity (B-rep), at R in {50, 100, 300, 1000, 3000}.
//
// Asserted at every R: smallest dihedral angle >= 10 degrees (so no tetrahedron under 5), mean
// alpha >= 0.20, and at R >= 1000 mean alpha >= 0.24; the mesh valid. Where a model falls short
// the shortfall is named below (SHORTFALLS) with the bound it keeps and why: those bounds are
// asserted instead, so a regression still fails. Each run prints one line for the README.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <tuple>

#include "bisect/generate.hpp"
#include "bisect/io.hpp"
#include "bisect/occ.hpp"
#include "bisect/quality.hpp"
#include "bisect/validate.hpp"

namespace bisect {
namespace {

namespace fs = std::filesystem;

struct Bounds {
  double dihedral = 10, alpha = 0.20, alpha_fine = 0.24;  // alpha_fine: at R >= 1000
};

// Measured shortfalls against issue 17's bounds, each with the bounds it keeps and the reason.
// Key: model path and R (0: every R).
const std::map<std::pair<std::string, int>, std::pair<Bounds, const char*>>& shortfalls() {
  // none since the count floor for quality's sake (pipeline/quality_floor.hpp): lug.stl, whose
  // holes are 64-gons of facets 0.1 wide in a 4 x 2 x 0.5 plate, had a mean alpha of 0.2139 at
  // R <= 1000 (its facets held the count at about 1,200) and 0.2394 at 3000; the floor now gives
  // it about 4,000 tetrahedra there, count_floor_reason "quality: ..."
  static const std::map<std::pair<std::string, int>, std::pair<Bounds, const char*>> table{};
  return table;
}

using Run = std::tuple<std::string, int>;
class QualityTable : public ::testing::TestWithParam<Run> {};

TEST_P(QualityTable, GoodElementsAtEveryCount) {
  const auto& [model, R] = GetParam();
  const fs::path path = fs::path(BISECT_SHARED_DIR) / model;
  if (!fs::exists(path)) GTEST_SKIP() << path << " is not here (../shared is absent)";
  GenerateOptions opt;
  opt.sizing.elements = R;
  GenerateStats st;
  const bool brep = path.extension() != ".stl";
  const TetMesh m = brep ? generate_brep_mesh(load_brep_file(path.string()), opt, &st) : generate_mesh(read_polyhedral(path.string()), opt, &st);
  ASSERT_TRUE(validate(m).empty()) << model << " at " << R;
  const QualitySummary q = summarize_quality(element_quality(m));
  Bounds b;
  std::string why;
  for (int key : {R, 0}) {
    const auto it = shortfalls().find({model, key});
    if (it != shortfalls().end()) {
      b = it->second.first, why = it->second.second;
      break;
    }
  }
  std::printf("[ table    ] %-30s R %5d: %6zu tets (floor %lld %s), min dihedral %5.2f, mean alpha %.3f%s%s\n", model.c_str(), R, m.num_tets(),
              static_cast<long long>(st.count_floor), st.count_floor_reason.substr(0, st.count_floor_reason.find(':')).c_str(), q.dihedral_min.min,
              q.alpha.mean, why.empty() ? "" : "; short: ", why.c_str());
  EXPECT_GE(q.dihedral_min.min, b.dihedral) << model << " at " << R;
  EXPECT_GE(q.alpha.mean, R >= 1000 ? b.alpha_fine : b.alpha) << model << " at " << R;
  if (st.count_floor > 0) {
    EXPECT_FALSE(st.count_floor_reason.empty()) << model;
  }
  // a floor for quality's sake came from a first mesh of at most 5,000 and holds at most 4 times
  // that (quality_floor.hpp), and says how many meshes it took
  if (st.count_floor_reason.rfind("quality", 0) == 0) {
    EXPECT_GE(st.quality_meshes, 1) << model;
    EXPECT_LE(m.num_tets(), 4u * 5000u) << model;
  }
}

std::vector<Run> runs() {
  std::vector<Run> out;
  for (const char* model : {"models/stl/cantilever.stl", "models/stl/slender-appendage.stl", "models/stl/lug.stl", "models/stl/plate-hole.stl",
                            "models/cantilever.brep", "models/slender-appendage.brep", "models/lug.brep", "models/plate-hole.brep",
                            "models/two-boxes-cavity.brep"})
    for (int R : {50, 100, 300, 1000, 3000}) out.emplace_back(model, R);
  return out;
}

INSTANTIATE_TEST_SUITE_P(Issue17, QualityTable, ::testing::ValuesIn(runs()), [](const ::testing::TestParamInfo<Run>& info) {
  std::string name = fs::path(std::get<0>(info.param)).filename().string() + "_" + std::to_string(std::get<1>(info.param));
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
});

}  // namespace
}  // namespace bisect
