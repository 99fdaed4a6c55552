// The generated test solids are what they claim to be: closed, of the right size and volume.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "generated_solids.hpp"

namespace bisect::testing {
namespace {

// every edge used by exactly two loops (holes included)
bool closed(const PolyInput& in) {
  std::map<std::pair<Index, Index>, int> uses;
  for (const PolyFace& f : in.faces)
    for (std::size_t i = 0; i < f.nodes.size(); ++i) {
      const Index a = f.nodes[i], b = f.nodes[(i + 1) % f.nodes.size()];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  for (const auto& [e, n] : uses)
    if (n != 2) return false;
  return true;
}

TEST(GeneratedSolids, SpheresHaveTheAskedFacetsAndConverge) {
  double previous_error = 1;
  for (int facets : {100, 1000, 10000, 100000}) {
    const PolyInput s = sphere_polyhedron(facets, 2.0);
    EXPECT_NEAR(static_cast<double>(s.faces.size()), facets, 0.1 * facets) << facets;
    EXPECT_TRUE(closed(s));
    for (const Vec3& p : s.nodes) EXPECT_NEAR(p.norm(), 2.0, 1e-12);
    const double v = summarize(s).volume, exact = 4.0 / 3 * M_PI * 8;
    const double err = (exact - v) / exact;
    EXPECT_GT(err, 0);  // inscribed
    EXPECT_LT(err, previous_error);
    previous_error = err;
  }
  EXPECT_LT(previous_error, 1e-3);
}

TEST(GeneratedSolids, DoubleSphereWithHole) {
  for (int facets : {1000, 10000, 50000}) {
    const PolyInput s = double_sphere_with_hole(facets);
    EXPECT_NEAR(static_cast<double>(s.faces.size()), facets, 0.1 * facets) << facets;
    EXPECT_TRUE(closed(s));
    const PolySummary sum = summarize(s);
    EXPECT_EQ(sum.regions[0].shells, 1u);  // the hole goes through: one genus-1 surface
    EXPECT_NEAR(sum.volume, double_sphere_with_hole_volume(), (facets < 5000 ? 0.03 : 0.005) * sum.volume);
  }
}

TEST(GeneratedSolids, RandomCsgIsDeterministicClosedAndSometimesHollow) {
  int cavities = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    std::string what;
    bool cavity = false;
    const PolyInput a = random_csg_polyhedron(seed, &what, &cavity);
    ASSERT_FALSE(a.faces.empty()) << what;
    const PolyInput b = random_csg_polyhedron(seed);
    ASSERT_EQ(a.nodes.size(), b.nodes.size()) << what;
    for (std::size_t i = 0; i < a.nodes.size(); ++i) EXPECT_EQ(a.nodes[i], b.nodes[i]);
    double occ_volume = 0;
    random_csg_polyhedron(seed, nullptr, nullptr, &occ_volume);
    EXPECT_GT(occ_volume, 0.5) << what;
    EXPECT_TRUE(closed(a)) << what;
    EXPECT_NEAR(summarize(a).volume, occ_volume, 1e-9 * occ_volume) << what;
    cavities += cavity;
  }
  EXPECT_GT(cavities, 3);
}

}  // namespace
}  // namespace bisect::testing
