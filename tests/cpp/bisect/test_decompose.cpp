// Convex decomposition (thesis 6.5, 6.7, 7.3) on hand-made shapes whose cells are known, on the
// thesis's examples and on the STL models.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
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

// A flange's disc as .poly text: radius 4 faceted by 48 chords, 1 thick, a bore of radius 1.2
// (24 chords) and six bolt holes of radius 0.35 at radius 3, faceted by 26 chords of 0.084 as
// FreeCAD's default angular deflection makes them. Every hole's wall edge is reflex.
std::string flange_disc() {
  struct Circle {
    double x, y, r;
    int n;
  };
  std::vector<Circle> circles = {{0, 0, 4, 48}, {0, 0, 1.2, 24}};
  for (int k = 0; k < 6; ++k) circles.push_back({3 * std::cos(k * M_PI / 3), 3 * std::sin(k * M_PI / 3), 0.35, 26});
  std::ostringstream nodes, faces;
  int node = 0, nfaces = 0;
  std::vector<int> first;  // per circle: its first node (bottom ring; the top ring follows)
  for (const Circle& c : circles) {
    first.push_back(node + 1);
    for (int z = 0; z < 2; ++z)
      for (int i = 0; i < c.n; ++i, ++node)
        nodes << c.x + c.r * std::cos(2 * M_PI * i / c.n) << ' ' << c.y + c.r * std::sin(2 * M_PI * i / c.n) << ' ' << z << '\n';
  }
  for (std::size_t k = 0; k < circles.size(); ++k) {
    const int n = circles[k].n, b = first[k];
    for (int z = 0; z < 2; ++z, ++nfaces) {  // the disc's side (k = 0) or a hole in it
      faces << n;
      for (int i = 0; i < n; ++i) faces << ' ' << b + z * n + i;
      faces << '\n';
    }
    for (int i = 0; i < n; ++i, ++nfaces)
      faces << "4 " << b + i << ' ' << b + (i + 1) % n << ' ' << b + n + (i + 1) % n << ' ' << b + n + i << '\n';
  }
  std::ostringstream s;
  s << nfaces << ' ' << node << " 1 0\n" << nodes.str() << faces.str() << nfaces;
  for (int f = 1; f <= nfaces; ++f) s << ' ' << f;
  s << '\n';
  return s.str();
}

// The cells' edges shorter than `below`, each counted once.
std::size_t cell_edges_under(const Decomposition& d, double below) {
  std::set<std::pair<Index, Index>> seen;
  for (const ConvexCell& c : d.cells)
    for (Index f : c.faces)
      for (const auto& loop : d.model.faces[f].loops)
        for (std::size_t i = 0; i < loop.size(); ++i) {
          const Index a = loop[i], b = loop[(i + 1) % loop.size()];
          if ((d.model.nodes[a] - d.model.nodes[b]).norm() < below) seen.insert({std::min(a, b), std::max(a, b)});
        }
  return seen.size();
}

// The wider vertex margin is tried first: beside finely faceted notches the cuts no longer pass
// just by a vertex, so the cells' edges stay near the facets' length, where the thesis's margin
// alone leaves edges a fraction of it (which the face grids would then grade from).
TEST(Decompose, WiderVertexMarginKeepsCutEdgesLong) {
  const PolyInput in = poly(flange_disc());
  const double chord = 2 * 0.35 * std::sin(M_PI / 26);
  const Decomposition wide = decompose(in);
  const Decomposition narrow = decompose(in, DecomposeOptions().thesis_margin_only());
  test::expect_valid_cells(wide, summarize(in).volume);
  test::expect_valid_cells(narrow, summarize(in).volume);
  EXPECT_FALSE(wide.stats.narrow_margin_retry);
  // measured: under 0.2 of a chord 0 and 4 edges, under half a chord 12 and 30, under 0.8 of a
  // chord 32 and 138, in 172 and 175 cells
  EXPECT_EQ(cell_edges_under(wide, 0.2 * chord), 0u);
  EXPECT_GT(cell_edges_under(narrow, 0.2 * chord), 0u);
  EXPECT_LT(2 * cell_edges_under(wide, 0.5 * chord), cell_edges_under(narrow, 0.5 * chord));
  EXPECT_LT(2 * cell_edges_under(wide, 0.8 * chord), cell_edges_under(narrow, 0.8 * chord));
}

// The smallest corner of the cells' faces (a vertex where a face runs straight on is no corner).
double smallest_face_corner_deg(const Decomposition& d) {
  double best = 180;
  for (const ConvexCell& c : d.cells)
    for (Index f : c.faces)
      for (const auto& loop : d.model.faces[f].loops)
        for (std::size_t i = 0; i < loop.size(); ++i) {
          const Vec3 p = d.model.nodes[loop[i]];
          const Vec3 a = d.model.nodes[loop[(i + loop.size() - 1) % loop.size()]] - p, b = d.model.nodes[loop[(i + 1) % loop.size()]] - p;
          const double deg = std::acos(std::clamp(a.dot(b) / (a.norm() * b.norm()), -1.0, 1.0)) * 180 / M_PI;
          if (deg < 179.999) best = std::min(best, deg);
        }
  return best;
}

// A prism whose reflex edge (at (4, 2)) has a face extension (y = 2) that meets the slanted
// bottom side 12 degrees from it: the thesis's limits take that plane and leave a 12-degree
// corner in the top and bottom faces; min_face_corner_deg (the B-rep route's 25) takes another.
TEST(Decompose, FaceCornerLimitKeepsSmallCornersOutOfTheFaces) {
  const PolyInput in = poly(test::prism({{-6, 3}, {8, 0}, {8, 2}, {4, 2}, {4, 5}, {-6, 5}}));
  DecomposeOptions limited;
  limited.min_face_corner_deg = 25;
  const Decomposition thesis = decompose(in), kept = decompose(in, limited);
  test::expect_valid_cells(thesis, summarize(in).volume);
  test::expect_valid_cells(kept, summarize(in).volume);
  EXPECT_LT(smallest_face_corner_deg(thesis), 15);  // measured: 12.1
  EXPECT_GE(smallest_face_corner_deg(kept), 25);    // measured: 77.9, the input's own smallest
  EXPECT_FALSE(kept.stats.face_corner_retry);
}

TEST(Decompose, CancelStopsTheWork) {
  DecomposeOptions opt;
  opt.progress = [](double) { return false; };
  EXPECT_THROW(decompose(poly(test::l_prism()), opt), Cancelled);
}

TEST(Decompose, StatsJsonNamesTheFigures) {
  const Decomposition d = decompose(poly(test::l_prism()));
  const std::string j = decompose_stats_json(d.stats);
  for (const char* key : {"\"convex_cells\": 2", "\"bisections\"", "\"cut_face\": 1", "\"rejected_planes\"",
                          "\"narrow_margin_retry\": false", "\"face_corner_retry\": false", "\"init_geom\"", "\"bisect\""})
    EXPECT_NE(j.find(key), std::string::npos) << key << " in " << j;
}

}  // namespace
}  // namespace bisect
