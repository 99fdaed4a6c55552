// The shared corpus (../shared/models/corpus: real CAD nobody on this project drew), issue 20:
// every shape meshes at R = 2e4 as tetra10 into a valid mesh (CalculiX's Jacobian check
// included) whose count is within 20% of R or at a floor the statistics name, or is refused in
// a message that names the place in FreeCAD's terms (FaceN). The shapes that do not mesh yet
// are listed with the message they end with: a shape that starts meshing, or fails another way,
// fails this test until the list says so.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "bisect/errors.hpp"
#include "bisect/generate.hpp"
#include "bisect/occ.hpp"
#include "bisect/quality.hpp"
#include "bisect/validate.hpp"
#include "shared_breps.hpp"

namespace bisect {
namespace {

// file -> a piece of the message it is refused with today (measured 2026-11-26)
const std::map<std::string, std::string> kNotYet = {
    // an open shell: the cube's planar faces are missing (named, and nothing to mesh)
    {"cube_filet.brep", "edges bound one face only, where the shell is open (Edge"},
    // the proxy's coarse facets cross at every proxy tried, named by their B-rep face
    {"Block.brep", "degrees (" + std::string(BISECT_SHARED_DIR) + "/models/corpus/Block.brep: Face478's tessellation folds: two of its facets intersect at ("},
    // a cell no fill can take: moved onto the true surfaces, its boundary crosses itself (named:
    // the B-rep face of the crossing edge, what it passes through, and where)
    {"wrenchnut.brep", "its boundary crosses itself once its grids lie on the true surfaces (an edge on Face"},
};

// file -> the smallest dihedral angle (degrees) its order-2 mesh at 2*10^4 keeps: about four
// fifths of what it measured after the face moves (in brackets; before them: Cone_1 10.9,
// Kurbelwelle 0.05, x_as1_tu_203 6.8, x_cube_sphere_cube_compound 17.7, x_full_sphere 10.5,
// x_ring 5.7, x_rod 5.4, x_t20_data 2.2); Zylkopf's and Kurbelwelle's small ones are at their
// 0.2 mm features
const std::map<std::string, double> kSmallestDihedral = {
    {"Cone_1.brep", 10.0},                      // (12.33)
    {"Kurbelwelle.brep", 0.8},                  // (1.06)
    {"Zylkopf.brep", 0.6},                      // (0.80)
    {"x_as1_tu_203.brep", 7.0},                 // (8.85)
    {"x_cube_sphere_cube_compound.brep", 14.5}, // (18.08)
    {"x_full_sphere.brep", 15.0},               // (19.17)
    {"x_problemSphere.brep", 8.0},              // (10.30; 2.43 until a seam's loop was chained right)
    {"x_ring.brep", 8.0},                       // (10.01)
    {"x_rod.brep", 5.2},                        // (6.50)
    {"x_t20_data.brep", 1.9},                   // (2.41)
};

// file -> the face pieces it may mesh on their proxy facets' planes (GenerateStats::facet_pieces;
// every other shape: none). Cone_1's apex piece folds onto itself in (u, v) and is too curved for
// a plane (test_brep_apex.cpp). Kurbelwelle's two pieces of Face5 and Face6 went there until a
// piece whose (u, v) grid folds over in 3D got a third try, its boundary triangulated in the
// surface's metric (surface/region_mesher.hpp).
const std::map<std::string, std::int64_t> kFacetPieces = {
    {"Cone_1.brep", 1},
};

std::vector<std::string> corpus() {
  std::vector<std::string> out;
  for (const std::string& m : test::shared_brep_models())
    if (m.find("corpus/") != std::string::npos) out.push_back(m);
  if (out.empty()) out.push_back("");
  return out;
}

class Corpus : public ::testing::TestWithParam<std::string> {};

TEST_P(Corpus, MeshesOrIsRefusedNamingTheFace) {
  const std::string model = GetParam();
  if (model.empty()) GTEST_SKIP() << BISECT_SHARED_DIR << " is missing: no corpus to test";
  const std::string path = std::string(BISECT_SHARED_DIR) + "/" + model;
  const std::string file = std::filesystem::path(model).filename().string();
  const auto known = kNotYet.find(file);
  GenerateOptions opt;
  opt.sizing.elements = 20000;
  opt.order = 2;
  GenerateStats st;
  const auto start = std::chrono::steady_clock::now();
  try {
    const TetMesh m = generate_brep_mesh(load_brep_file(path), opt, &st);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_TRUE(known == kNotYet.end()) << file << " meshes now: take it off kNotYet (and the README's list)";
    const std::vector<Violation> bad = validate(m);
    ASSERT_TRUE(bad.empty()) << file << ": " << bad.size() << " violations, first: " << to_string(bad.front().kind);
    const double count = static_cast<double>(m.num_tets());
    if (st.count_floor > 0) EXPECT_FALSE(st.count_floor_reason.empty()) << file;
    else EXPECT_NEAR(count, 20000, 4000) << file;
    const QualitySummary q = summarize_quality(element_quality(m));
    const auto bound = kSmallestDihedral.find(file);
    ASSERT_TRUE(bound != kSmallestDihedral.end()) << file << ": give it a bound in kSmallestDihedral";
    EXPECT_GE(q.dihedral_min.min, bound->second) << file;
    const auto facets = kFacetPieces.find(file);
    EXPECT_LE(st.facet_pieces, facets == kFacetPieces.end() ? 0 : facets->second) << file << ": pieces meshed on the proxy's facets";
    std::printf("[ corpus   ] %-34s %7zu tets (floor: %s), min dihedral %5.2f, mean alpha %.3f, %.1f s\n", file.c_str(), m.num_tets(),
                st.count_floor_reason.empty() ? "none" : st.count_floor_reason.c_str(), q.dihedral_min.min, q.alpha.mean, seconds);
  } catch (const Cancelled&) {
    throw;
  } catch (const Error& e) {
    const std::string what = e.what();
    std::printf("[ corpus   ] %-34s refused: %.200s\n", file.c_str(), what.c_str());
    ASSERT_TRUE(known != kNotYet.end()) << file << " no longer meshes: " << what;
    EXPECT_NE(what.find(known->second), std::string::npos) << file << " fails another way: " << what;
    EXPECT_EQ(what.rfind(path, 0), 0u) << "the message starts with the file: " << what;
    // where it names a cell or a fold, it names their B-rep faces too: what a user can find in FreeCAD
    if (what.find("convex cell") != std::string::npos || what.find("inside out") != std::string::npos) {
      EXPECT_NE(what.find(" beside Face"), std::string::npos) << what;
    }
    // a cell no fill takes is named alone, at its own centre: not as the group of cells it was
    // joined with for the trial fillings (whose centre lay 22 mm away on wrenchnut)
    std::size_t unfilled = what.find(": no point sees its whole boundary");
    if (unfilled == std::string::npos) unfilled = what.find(": its boundary crosses itself");
    if (unfilled != std::string::npos) {
      EXPECT_EQ(what.substr(0, unfilled).find("(joined with"), std::string::npos) << what;
    }
  }
}

// Cone_1's first proxy left a tetrahedron flat to round-off at the apex (smallest dihedral angle
// 1e-13 degrees): the 4-node mesh was handed over with it, as only the order-2 check saw it; such
// a mesh is refused at order 1 too. Later the first proxy lost a surface node at the apex (its
// grid there folded onto itself, test_brep_apex.cpp) and the second meshed, 0.74 degrees. Now
// the first proxy meshes it.
TEST(CorpusCone, MeshesOnTheFirstProxyWithNoFlatTetrahedron) {
  const std::string path = std::string(BISECT_SHARED_DIR) + "/models/corpus/Cone_1.brep";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is missing";
  GenerateOptions opt;
  opt.sizing.elements = 20000;
  opt.order = 1;
  GenerateStats st;
  const TetMesh m = generate_brep_mesh(load_brep_file(path), opt, &st);
  EXPECT_TRUE(validate(m).empty());
  EXPECT_GT(summarize_quality(element_quality(m)).dihedral_min.min, 8.0);  // measured: 10.9
  EXPECT_EQ(st.proxy_attempts, 1) << st.proxy_retry_reason;
  EXPECT_FALSE(st.face_corner_retry);  // its decomposition keeps the limit
}

// A shape whose first proxy does not mesh (x_ring at 2*10^4: a cell no point sees whole): the
// statistics say so, and why, naming the file, the solid and the faces: what a user reads when
// the run took twice its time. Its decompositions under the face corner limit end in a region no
// plane resolves, and were made again without it: the statistics say that too.
TEST(CorpusRing, AShapeTheFirstProxyCannotMeshSaysWhy) {
  const std::string path = std::string(BISECT_SHARED_DIR) + "/models/corpus/x_ring.brep";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is missing";
  GenerateOptions opt;
  opt.sizing.elements = 20000;
  GenerateStats st;
  const TetMesh m = generate_brep_mesh(load_brep_file(path), opt, &st);
  EXPECT_TRUE(validate(m).empty());
  EXPECT_EQ(st.proxy_attempts, 2);
  EXPECT_NE(st.proxy_retry_reason.find("of Solid1 at ("), std::string::npos) << st.proxy_retry_reason;
  EXPECT_NE(st.proxy_retry_reason.find("beside Face"), std::string::npos) << st.proxy_retry_reason;
  const std::string json = generate_stats_json(st, summarize_quality(element_quality(m)));
  EXPECT_NE(json.find("\"proxy_attempts\": 2"), std::string::npos) << json;
  EXPECT_TRUE(st.face_corner_retry);
  EXPECT_NE(json.find("\"face_corner_retry\": true"), std::string::npos) << json;
  // the second proxy's count search starts at the spacing the first one's found: 9 node
  // placements in all (10 when it started again from the nominal spacing)
  EXPECT_GE(st.placements, 2);
  EXPECT_LE(st.placements, 9);
  EXPECT_NE(json.find("\"placements\": " + std::to_string(st.placements)), std::string::npos) << json;
}

// A shape its first proxy meshes: one attempt, no reason.
TEST(CorpusCone, AShapeTheFirstProxyMeshesTookOneAttempt) {
  const std::string path = std::string(BISECT_SHARED_DIR) + "/models/corpus/x_full_sphere.brep";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is missing";
  GenerateOptions opt;
  opt.sizing.elements = 5000;
  GenerateStats st;
  generate_brep_mesh(load_brep_file(path), opt, &st);
  EXPECT_EQ(st.proxy_attempts, 1);
  EXPECT_TRUE(st.proxy_retry_reason.empty()) << st.proxy_retry_reason;
}

INSTANTIATE_TEST_SUITE_P(Shared, Corpus, ::testing::ValuesIn(corpus()), [](const ::testing::TestParamInfo<std::string>& info) {
  return info.param.empty() ? std::string("none") : test::shared_test_name(info.param);
});

}  // namespace
}  // namespace bisect
