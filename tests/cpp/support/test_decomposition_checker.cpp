// The independent decomposition checker must accept valid decompositions and name each defect of
// invalid ones; the cells files here are written by hand.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "bisect/io.hpp"
#include "decomposition_checker.hpp"
#include "poly_shapes.hpp"

namespace bisect::testing {
namespace {

using test::poly;

// Boxes [x0,x1] x [0,1] x [0,1] as cells; `split` lists the x planes. Faces between cells are
// shared; `t_junction` lists the middle face twice (one side whole, other side in two halves).
std::string boxes(const std::vector<double>& xs, bool t_junction = false) {
  std::ostringstream s;
  const std::size_t n = xs.size();
  std::vector<std::string> faces;
  auto id = [&](std::size_t i, int y, int z) { return 4 * i + 2 * y + z + 1; };
  auto face = [&](std::vector<std::size_t> v) {
    std::ostringstream f;
    f << v.size();
    for (std::size_t x : v) f << ' ' << x;
    faces.push_back(f.str());
    return faces.size();
  };
  std::vector<std::size_t> wall(n);
  for (std::size_t i = 0; i < n; ++i) wall[i] = face({id(i, 0, 0), id(i, 1, 0), id(i, 1, 1), id(i, 0, 1)});
  std::vector<std::vector<std::size_t>> cell(n - 1);
  std::size_t extra = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    cell[i] = {wall[i], wall[i + 1], face({id(i, 0, 0), id(i + 1, 0, 0), id(i + 1, 1, 0), id(i, 1, 0)}),
               face({id(i, 0, 1), id(i + 1, 0, 1), id(i + 1, 1, 1), id(i, 1, 1)}),
               face({id(i, 0, 0), id(i + 1, 0, 0), id(i + 1, 0, 1), id(i, 0, 1)}),
               face({id(i, 1, 0), id(i + 1, 1, 0), id(i + 1, 1, 1), id(i, 1, 1)})};
  }
  std::size_t nodes = 4 * n;
  std::ostringstream extra_nodes;
  if (t_junction && n == 3) {  // the second cell's left side in two halves at z = 0.5
    extra_nodes << xs[1] << " 0 0.5\n" << xs[1] << " 1 0.5\n";
    const std::size_t a = nodes + 1, b = nodes + 2;
    nodes += 2;
    const std::size_t lower = face({id(1, 0, 0), id(1, 1, 0), b, a}), upper = face({a, b, id(1, 1, 1), id(1, 0, 1)});
    cell[1][0] = lower;
    cell[1].push_back(upper);
    // the second cell's side faces take the new nodes too, so each cell is closed on its own
    auto text = [](std::vector<std::size_t> v) {
      std::ostringstream f;
      f << v.size();
      for (std::size_t x : v) f << ' ' << x;
      return f.str();
    };
    faces[cell[1][4] - 1] = text({id(1, 0, 0), id(2, 0, 0), id(2, 0, 1), id(1, 0, 1), a});
    faces[cell[1][5] - 1] = text({id(1, 1, 0), id(2, 1, 0), id(2, 1, 1), id(1, 1, 1), b});
    extra = 2;
  }
  (void)extra;
  s << faces.size() << ' ' << nodes << ' ' << n - 1 << " 0\n";
  for (std::size_t i = 0; i < n; ++i)
    for (int y = 0; y < 2; ++y)
      for (int z = 0; z < 2; ++z) s << xs[i] << ' ' << y << ' ' << z << '\n';
  s << extra_nodes.str();
  for (const auto& f : faces) s << f << '\n';
  for (std::size_t i = 0; i + 1 < n; ++i) {
    s << "-- cell " << i + 1 << " of input region 1\n" << cell[i].size();
    for (std::size_t f : cell[i]) s << ' ' << f;
    s << '\n';
  }
  return s.str();
}

TEST(DecompositionChecker, AcceptsValidBoxes) {
  const PolyInput cube = poly(boxes({0, 1}));
  CellCheck c = check_decomposition(cube, cube, {0});
  EXPECT_TRUE(c.problems.empty()) << c.problems[0];
  c = check_decomposition(cube, poly(boxes({0, 0.25, 1})), {0, 0});
  EXPECT_TRUE(c.problems.empty()) << c.problems[0];
  EXPECT_EQ(c.shared_faces, 1u);
  EXPECT_EQ(c.boundary_faces, 10u);
  EXPECT_LT(c.max_volume_rel_error, 1e-15);
}

TEST(DecompositionChecker, FindsAMissingCell) {
  const PolyInput cube = poly(boxes({0, 1}));
  PolyInput cells = poly(boxes({0, 0.25, 1}));
  cells.regions.pop_back();
  const CellCheck c = check_decomposition(cube, cells, {0});
  ASSERT_FALSE(c.problems.empty());
  std::string all;
  for (const auto& p : c.problems) all += p + "\n";
  EXPECT_NE(all.find("hold volume"), std::string::npos) << all;
  EXPECT_NE(all.find("is covered by cell faces of area"), std::string::npos) << all;
  EXPECT_NE(all.find("matched by no other cell"), std::string::npos) << all;  // the cut face
}

TEST(DecompositionChecker, FindsOverlappingCells) {
  const PolyInput cube = poly(boxes({0, 1}));
  PolyInput cells = poly(boxes({0, 0.25, 1}));
  cells.regions.push_back(cells.regions[0]);  // the first box twice
  const CellCheck c = check_decomposition(cube, cells, {0, 0, 0});
  std::string all;
  for (const auto& p : c.problems) all += p + "\n";
  EXPECT_NE(all.find("hold volume"), std::string::npos) << all;
  EXPECT_NE(all.find("belongs to 3 cells"), std::string::npos) << all;
}

TEST(DecompositionChecker, FindsATJunction) {
  const PolyInput cube = poly(boxes({0, 1}));
  const std::string text = boxes({0, 0.5, 1}, true);
  const CellCheck c = check_decomposition(cube, poly(text), {0, 0});
  std::string all;
  for (const auto& p : c.problems) all += p + "\n";
  EXPECT_NE(all.find("matched by no other cell"), std::string::npos) << all;
}

TEST(DecompositionChecker, FindsANonConvexCell) {
  // an L-shaped prism given as one cell
  const PolyInput l = poly(test::l_prism());
  const CellCheck c = check_decomposition(l, l, {0});
  std::string all;
  for (const auto& p : c.problems) all += p + "\n";
  EXPECT_NE(all.find("is not convex"), std::string::npos) << all;
}

TEST(DecompositionChecker, ReadsTheCellRegionsFromTheComments) {
  const std::string path = ::testing::TempDir() + "/cells_regions.poly";
  {
    std::ofstream f(path);
    f << boxes({0, 0.5, 1});
  }
  EXPECT_EQ(cell_regions_of_file(path), (std::vector<Index>{0, 0}));
}

}  // namespace
}  // namespace bisect::testing
