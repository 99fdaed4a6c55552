// Planar meshing failures name the place (issue 20): the file, the input's polygon (and the hole
// or sub-domain polygon it concerns) and a point in the input's own coordinates, also for a part
// meshed as a copy moved near the origin.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "bisect/errors.hpp"
#include "bisect/io.hpp"
#include "mesh2d/bisect2d.hpp"
#include "mesh2d/planar_failure.hpp"
#include "mesh2d/planar_mesher.hpp"

namespace bisect::mesh2d {
namespace {

// No input known now makes a planar step fail (the corner sub-domain that did is meshed in
// test_touching_holes, self-crossing polygons are refused by the reader), so the wording is
// checked on a step's failure as mesh_planar words it: file, polygon, the hole or sub-domain it
// concerns, and the point in the input's own coordinates, also for a part moved near the origin.
TEST(PlanarFailures, TheMessageNamesFilePolygonAndPlace) {
  const std::string path = std::string(BISECT_TEST_DATA) + "/square-corner-subdomain.poly2";
  const Poly2Input in = read_poly2(path);
  const std::string e = placed_failure(in, 0, PlanarFailure("recursive bisection: a flat triangle", Vec2(1.5, 0.5), 1), Vec2::Zero()).what();
  EXPECT_EQ(e, path + ": polygon 1 around polygon 2 (a sub-domain): recursive bisection: a flat triangle, near (1.5, 0.5)");
  // the same input at 1e8 is meshed as a copy moved near the origin (by -shift): the steps see
  // the copy, the point is given where the input has it, with the digits of the part's size
  const std::string f =
      placed_failure(in, 0, PlanarFailure("recursive bisection: a flat triangle", Vec2(1.5, 0.5), 1), Vec2(1e8, 1e8)).what();
  const std::size_t at = e.find(", near ("), fat = f.find(", near (");
  ASSERT_NE(fat, std::string::npos) << f;
  EXPECT_EQ(f.substr(0, fat), e.substr(0, at));
  double fx = 0, fy = 0;
  ASSERT_EQ(std::sscanf(f.c_str() + fat, ", near (%lf, %lf)", &fx, &fy), 2) << f;
  EXPECT_NEAR(fx - 1e8, 1.5, 1e-6);
  EXPECT_NEAR(fy - 1e8, 0.5, 1e-6);
  EXPECT_NE(f.find("100000001.5"), std::string::npos) << f;
  // a failure of the outer loop names no hole
  const std::string g = placed_failure(in, 1, PlanarFailure("convex decomposition: x", Vec2(0.5, 0.5)), Vec2::Zero()).what();
  EXPECT_EQ(g, path + ": polygon 2: convex decomposition: x, near (0.5, 0.5)");
}

// Each step's failure carries a place (a PlanarFailure), so the message above can name it: the
// recursive bisection on a loop that is not a polygon (three collinear nodes).
TEST(PlanarFailures, BisectionFailuresCarryAPlace) {
  const std::vector<Vec2> X = {{0, 0}, {1, 0}, {2, 0}};
  std::vector<std::array<Index, 3>> tris;
  try {
    bisection_triangulate(X, {0, 1, 2}, {}, tris);
    FAIL() << "a flat triangle was accepted";
  } catch (const PlanarFailure& f) {
    EXPECT_NEAR(f.where.x(), 1.0, 1e-12);
    EXPECT_NEAR(f.where.y(), 0.0, 1e-12);
  }
}

}  // namespace
}  // namespace bisect::mesh2d
