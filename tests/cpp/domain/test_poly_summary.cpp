// The input summary behind `bisect-mesh info`: shells, face holes, cavities and sub-domains found
// by containment whatever the direction of the faces, and net volumes that add up to the volume
// of the domain.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "bisect/errors.hpp"
#include "bisect/io.hpp"
#include "bisect/poly_input.hpp"

using namespace bisect;
namespace fs = std::filesystem;

namespace {

const std::string kData = BISECT_TEST_DATA;

// Builds inputs in code; nodes with equal coordinates are shared, as a file would share them.
struct Builder {
  PolyInput in;
  std::map<std::array<double, 3>, Index> ids;

  Index node(const Vec3& p) {
    auto [it, added] = ids.try_emplace({p.x(), p.y(), p.z()}, Index(in.nodes.size()));
    if (added) in.nodes.push_back(p);
    return it->second;
  }
  // The six faces of an axis-aligned box, in deliberately mixed directions.
  std::vector<Index> box(const Vec3& lo, const Vec3& hi) {
    Index c[8];
    for (int i = 0; i < 8; ++i) c[i] = node(Vec3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z()));
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 6, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 6, 4}, {1, 3, 7, 5}};
    std::vector<Index> faces;
    for (const auto& q : quads) {
      faces.push_back(Index(in.faces.size()));
      in.faces.push_back({{c[q[0]], c[q[1]], c[q[2]], c[q[3]]}, -1});
    }
    return faces;
  }
  void region(std::vector<Index> faces, bool cavity = false) { in.regions.push_back({std::move(faces), cavity}); }
};

std::vector<Index> join(std::vector<Index> a, const std::vector<Index>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// Signed volume straight from the triangles of a binary STL, as the file orients them: an
// independent check that shares no code with the reader or the summary.
double raw_stl_volume(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  std::uint32_t n;
  std::memcpy(&n, bytes.data() + 80, 4);
  double six_v = 0;
  for (std::uint32_t t = 0; t < n; ++t) {
    float v[9];
    std::memcpy(v, bytes.data() + 84 + 50 * std::size_t(t) + 12, sizeof v);
    const Vec3 a(v[0], v[1], v[2]), b(v[3], v[4], v[5]), c(v[6], v[7], v[8]);
    six_v += a.dot(b.cross(c));
  }
  return std::abs(six_v) / 6;
}

}  // namespace

TEST(Summary, CubeWithACavityBesideACube) {
  const PolySummary s = summarize(read_poly(kData + "/cube-cavity-adjacent-cube.poly"));
  ASSERT_EQ(s.regions.size(), 3u);
  const RegionSummary &r1 = s.regions[0], &r2 = s.regions[1], &r3 = s.regions[2];
  EXPECT_EQ(r1.faces, 6u);
  EXPECT_EQ(r1.nodes, 8u);
  EXPECT_EQ(r1.shells, 1u);
  EXPECT_EQ(r1.holes, 0u);
  EXPECT_FALSE(r1.cavity);
  EXPECT_EQ(r1.inside, -1);
  EXPECT_NEAR(r1.volume, 0.875, 1e-12);
  EXPECT_EQ(r2.nodes, 8u);
  EXPECT_EQ(r2.inside, -1);  // it shares face 11 with region 1 and lies beside it
  EXPECT_NEAR(r2.volume, 1.0, 1e-12);
  EXPECT_TRUE(r3.cavity);
  EXPECT_EQ(r3.inside, 0);
  EXPECT_NEAR(r3.volume, 0.125, 1e-12);
  EXPECT_EQ(s.faces, 17u);
  EXPECT_EQ(s.nodes, 20u);
  EXPECT_EQ(s.bbox_min, Vec3(0, 0, 0));
  EXPECT_EQ(s.bbox_max, Vec3(2, 1, 1));
  EXPECT_NEAR(s.volume, 1.875, 1e-12);  // cavities are not material
}

TEST(Summary, ReentryBoxLeavesOutItsPocket) {
  const PolySummary s = summarize(read_poly(kData + "/reentry-box.poly"));
  ASSERT_EQ(s.regions.size(), 1u);
  EXPECT_EQ(s.regions[0].shells, 2u);  // the box and the pocket closed by face 12
  EXPECT_EQ(s.regions[0].holes, 1u);
  EXPECT_EQ(s.regions[0].nodes, 16u);
  EXPECT_NEAR(s.regions[0].volume, 1 - 0.5 * 0.5 * 0.75, 1e-12);
  EXPECT_NEAR(s.volume, 0.8125, 1e-12);
}

TEST(Summary, FaceDirectionsDoNotMatter) {
  const PolyInput base = read_poly(kData + "/cube-cavity-adjacent-cube.poly");
  for (int pattern : {1, 2, 3, 5, 0x1ffff}) {
    PolyInput in = base;
    for (std::size_t f = 0; f < in.faces.size(); ++f)
      if (pattern >> (f % 17) & 1) std::reverse(in.faces[f].nodes.begin(), in.faces[f].nodes.end());
    const PolySummary s = summarize(in);
    EXPECT_NEAR(s.regions[0].volume, 0.875, 1e-12) << pattern;
    EXPECT_NEAR(s.regions[1].volume, 1.0, 1e-12) << pattern;
    EXPECT_NEAR(s.regions[2].volume, 0.125, 1e-12) << pattern;
    EXPECT_EQ(s.regions[2].inside, 0) << pattern;
  }
}

TEST(Summary, SubDomainLeavesTheRegionItLiesIn) {
  Builder b;
  const auto outer = b.box({0, 0, 0}, {2, 2, 2});
  const auto inner = b.box({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5});
  b.region(outer);
  b.region(inner);
  const PolySummary s = summarize(b.in);
  EXPECT_NEAR(s.regions[0].volume, 7, 1e-12);
  EXPECT_EQ(s.regions[1].inside, 0);
  EXPECT_NEAR(s.regions[1].volume, 1, 1e-12);
  EXPECT_NEAR(s.volume, 8, 1e-12);
}

// Thesis 6.12 (C), a hole interface: the outer region lists the sub-domain's surface as its
// inner boundary; its volume must not be taken away twice.
TEST(Summary, SubDomainListedAsTheInnerBoundaryToo) {
  Builder b;
  const auto outer = b.box({0, 0, 0}, {2, 2, 2});
  const auto inner = b.box({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5});
  b.region(join(outer, inner));
  b.region(inner);
  const PolySummary s = summarize(b.in);
  EXPECT_EQ(s.regions[0].shells, 2u);
  EXPECT_NEAR(s.regions[0].volume, 7, 1e-12);
  EXPECT_EQ(s.regions[1].inside, 0);
  EXPECT_NEAR(s.regions[1].volume, 1, 1e-12);
  EXPECT_NEAR(s.volume, 8, 1e-12);
}

TEST(Summary, IslandInsideACavity) {
  Builder b;
  b.region(b.box({0, 0, 0}, {4, 4, 4}));
  b.region(b.box({1, 1, 1}, {3, 3, 3}), true);
  b.region(b.box({1.5, 1.5, 1.5}, {2.5, 2.5, 2.5}));
  const PolySummary s = summarize(b.in);
  EXPECT_NEAR(s.regions[0].volume, 64 - 8, 1e-12);
  EXPECT_EQ(s.regions[1].inside, 0);
  EXPECT_NEAR(s.regions[1].volume, 8 - 1, 1e-12);  // the empty space
  EXPECT_EQ(s.regions[2].inside, 1);
  EXPECT_NEAR(s.regions[2].volume, 1, 1e-12);
  EXPECT_NEAR(s.volume, 57, 1e-12);
}

TEST(Summary, HollowRegionWithTwoShells) {
  Builder b;
  b.region(join(b.box({0, 0, 0}, {3, 3, 3}), b.box({1, 1, 1}, {2, 2, 2})));
  const PolySummary s = summarize(b.in);
  EXPECT_EQ(s.regions[0].shells, 2u);
  EXPECT_EQ(s.regions[0].inside, -1);
  EXPECT_NEAR(s.regions[0].volume, 26, 1e-12);
}

TEST(Summary, TwoCubesOfOneRegionTouchingAlongAnEdge) {
  Builder b;
  b.region(join(b.box({0, 0, 0}, {1, 1, 1}), b.box({1, 1, 0}, {2, 2, 1})));
  const PolySummary s = summarize(b.in);
  EXPECT_EQ(s.regions[0].shells, 2u);
  EXPECT_EQ(s.regions[0].nodes, 14u);
  EXPECT_NEAR(s.regions[0].volume, 2, 1e-12);
}

TEST(Summary, InterfaceFaceHoleDoesNotCountAsAShell) {
  const char* text =
      "12 16 2 0\n"
      "0 0 0\n2 0 0\n2 2 0\n0 2 0\n0 0 1\n2 0 1\n2 2 1\n0 2 1\n"
      "0.5 0.5 1\n1.5 0.5 1\n1.5 1.5 1\n0.5 1.5 1\n0.5 0.5 2\n1.5 0.5 2\n1.5 1.5 2\n0.5 1.5 2\n"
      "4 1 2 3 4\n4 5 6 7 8\n4 1 2 6 5\n4 2 3 7 6\n4 3 4 8 7\n4 4 1 5 8\n"
      "4 9 10 11 12\n"
      "4 13 14 15 16\n4 9 10 14 13\n4 10 11 15 14\n4 11 12 16 15\n4 12 9 13 16\n"
      "7 1 2 3 4 5 6 7\n"
      "6 7 8 9 10 11 12\n";
  std::istringstream in(text);
  const PolySummary s = summarize(read_poly(in, "stack.poly"));
  EXPECT_EQ(s.regions[0].shells, 1u);
  EXPECT_EQ(s.regions[0].holes, 1u);
  EXPECT_NEAR(s.regions[0].volume, 4, 1e-12);
  EXPECT_EQ(s.regions[1].inside, -1);
  EXPECT_NEAR(s.regions[1].volume, 1, 1e-12);
  EXPECT_NEAR(s.volume, 5, 1e-12);
}

TEST(Summary, OpenOrEmptyInputsDoNotFail) {
  Builder b;
  auto faces = b.box({0, 0, 0}, {1, 1, 1});
  faces.pop_back();
  b.region(faces);
  const PolySummary s = summarize(b.in);
  EXPECT_EQ(s.regions[0].shells, 0u);
  EXPECT_EQ(s.regions[0].volume, 0);
  const PolySummary e = summarize(PolyInput{});
  EXPECT_TRUE(e.regions.empty());
  EXPECT_EQ(e.volume, 0);
  // Built in code with a bad reference: an error, not a crash.
  b.in.faces[0].nodes[2] = 99;
  EXPECT_THROW(summarize(b.in), InputError);
}

TEST(Summary, SharedStlModelsHavePositiveVolume) {
  const fs::path dir = fs::path(BISECT_SHARED_DIR) / "models" / "stl";
  if (!fs::exists(dir)) GTEST_SKIP() << dir << " is missing";
  int seen = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".stl") continue;
    PolyInput in = read_stl(e.path().string());
    const double expected = raw_stl_volume(e.path());
    const PolySummary s = summarize(in);
    ASSERT_EQ(s.regions.size(), 1u);
    EXPECT_GT(s.regions[0].volume, 0) << e.path();
    EXPECT_NEAR(s.volume, expected, 1e-9 * expected) << e.path();
    EXPECT_GE(s.regions[0].shells, 1u) << e.path();
    // Orientation is the summary's own business: scrambled triangles give the same answer.
    for (std::size_t f = 0; f < in.faces.size(); f += 3) std::swap(in.faces[f].nodes[0], in.faces[f].nodes[1]);
    EXPECT_NEAR(summarize(in).volume, expected, 1e-9 * expected) << e.path();
    if (e.path().filename() == "box-cavity.stl") {
      EXPECT_EQ(s.regions[0].shells, 2u);
      EXPECT_NEAR(s.volume, 0.875, 1e-6);
    }
    ++seen;
  }
  EXPECT_GE(seen, 9);
}

TEST(Summary, SharedPolyExamples) {
  const fs::path dir = fs::path(BISECT_SHARED_DIR) / "examples";
  if (!fs::exists(dir)) GTEST_SKIP() << dir << " is missing";
  EXPECT_NEAR(summarize(read_polyhedral((dir / "cube-cavity-adjacent-cube.poly").string())).volume, 1.875, 1e-12);
  EXPECT_NEAR(summarize(read_polyhedral((dir / "reentry-box.poly").string())).volume, 0.8125, 1e-12);
}
