// Decomposition of generated inputs, checked by the independent checker: the sphere families of
// thesis 6.10 and 1,000 random CSG solids (boxes and rotated prisms, some hollow).
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>

#include "bisect/errors.hpp"
#include "bisect/io.hpp"
#include "bisect/polyhedral_model.hpp"
#include "decomposition_checker.hpp"
#include "generated_solids.hpp"

namespace bisect {
namespace {

testing::CellCheck check(const PolyInput& in, const Decomposition& d, const std::string& name) {
  const std::string path = ::testing::TempDir() + "/gen_" + name + ".poly";
  write_cells_poly(d, path);
  return testing::check_decomposition(in, read_poly(path), testing::cell_regions_of_file(path));
}

std::string report(const testing::CellCheck& c) {
  std::string s;
  for (const auto& p : c.problems) s += p + "\n";
  return s;
}

TEST(GeneratedDecomposition, SpheresAreOneConvexCell) {
  for (int facets : {100, 1000, 10000}) {
    const PolyInput s = testing::sphere_polyhedron(facets);
    const Decomposition d = decompose(s);
    EXPECT_EQ(d.cells.size(), 1u) << facets;
    const testing::CellCheck c = check(s, d, "sphere" + std::to_string(facets));
    EXPECT_TRUE(c.problems.empty()) << report(c);
  }
}

TEST(GeneratedDecomposition, DoubleSphereWithHole) {
  for (int facets : {1000, 4000}) {
    const PolyInput s = testing::double_sphere_with_hole(facets);
    const Decomposition d = decompose(s);
    // the hole's wall has a reflex edge per segment, so there are at least that many cells
    EXPECT_GT(d.cells.size(), 8u);
    const testing::CellCheck c = check(s, d, "dsh" + std::to_string(facets));
    EXPECT_TRUE(c.problems.empty()) << report(c);
    EXPECT_LT(c.max_volume_rel_error, 1e-9);
  }
}

// 1,000 random solids: each must end in a valid decomposition or a clear one-line error, never
// a crash nor an invalid result. BISECT_RANDOM_SOLIDS overrides the count.
TEST(GeneratedDecomposition, RandomCsgSolids) {
  const char* env = std::getenv("BISECT_RANDOM_SOLIDS");
  const int n = env ? std::atoi(env) : 1000;
  int valid = 0, input_errors = 0, meshing_errors = 0, hollow = 0, retries = 0;
  std::string errors, retried;
  for (int seed = 1; seed <= n; ++seed) {
    std::string what;
    bool cavity = false;
    const PolyInput in = testing::random_csg_polyhedron(static_cast<std::uint64_t>(seed), &what, &cavity);
    ASSERT_FALSE(in.faces.empty()) << what;
    hollow += cavity;
    try {
      const Decomposition d = decompose(in);
      const testing::CellCheck c = check(in, d, "csg");
      EXPECT_TRUE(c.problems.empty()) << what << "\n" << report(c);
      valid += c.problems.empty();
      if (d.stats.narrow_margin_retry) ++retries, retried += " " + std::to_string(seed);
    } catch (const InputError& e) {
      ++input_errors;
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
      errors += what + ": " + e.what() + "\n";
    } catch (const MeshingError& e) {
      ++meshing_errors;
      EXPECT_FALSE(std::string(e.what()).empty());
      errors += what + ": " + e.what() + "\n";
    }
  }
  std::cout << "random CSG solids: " << n << " (" << hollow << " hollow): " << valid << " valid decompositions, "
            << input_errors << " input errors, " << meshing_errors << " meshing errors; " << retries
            << " decomposed again with the narrow vertex margin (seeds" << retried << ")\n";
  std::cout << errors;
  RecordProperty("valid", valid);
  RecordProperty("input_errors", input_errors);
  RecordProperty("meshing_errors", meshing_errors);
  RecordProperty("narrow_margin_retries", retries);
  EXPECT_EQ(valid + input_errors + meshing_errors, n);
}

// Seed 631 (a box and a prism) is one the wider vertex margin's cuts lead into a region that no
// plane resolves: the decomposition starts again with the thesis's margin alone, and the result
// is exactly that decomposition.
TEST(GeneratedDecomposition, NarrowMarginRetryKeepsTheMesh) {
  const PolyInput in = testing::random_csg_polyhedron(631);
  const Decomposition d = decompose(in);
  EXPECT_TRUE(d.stats.narrow_margin_retry);
  const testing::CellCheck c = check(in, d, "retry");
  EXPECT_TRUE(c.problems.empty()) << report(c);
  const Decomposition n = decompose(in, DecomposeOptions().thesis_margin_only());
  EXPECT_FALSE(n.stats.narrow_margin_retry);
  EXPECT_EQ(d.cells.size(), n.cells.size());
  EXPECT_EQ(d.stats.bisections, n.stats.bisections);
  EXPECT_EQ(d.model.nodes.size(), n.model.nodes.size());
}

}  // namespace
}  // namespace bisect
