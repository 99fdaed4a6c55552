// Planar meshing failures name the place (issue 20): the file, the input's polygon (and the hole
// or sub-domain polygon it concerns) and a point in the input's own coordinates, also for a part
// meshed as a copy moved near the origin.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "bisect/errors.hpp"
#include "bisect/io.hpp"
#include "mesh2d/planar_mesher.hpp"

namespace bisect::mesh2d {
namespace {

std::string failure(const Poly2Input& in) {
  try {
    mesh_planar(in, {});
  } catch (const MeshingError& e) {
    return e.what();
  }
  return "";
}

// A sub-domain in the corner of its square (sharing two edges) is an honest input the planar
// mesher cannot finish today: the L around it is cut as a region with a hole that touches its
// boundary. When that is fixed, this test must find another failure or go.
TEST(PlanarFailures, TheMessageNamesFilePolygonAndPlace) {
  const std::string path = std::string(BISECT_TEST_DATA) + "/square-corner-subdomain.poly2";
  const Poly2Input in = read_poly2(path);
  const std::string e = failure(in);
  ASSERT_FALSE(e.empty()) << "meshed: see the comment above";
  EXPECT_EQ(e.rfind(path + ": polygon 1", 0), 0u) << e;
  EXPECT_NE(e.find(", near ("), std::string::npos) << e;
  // the same input moved to 1e8 fails at the same place, given in the input's coordinates
  Poly2Input far = in;
  for (Vec2& p : far.nodes) p += Vec2(1e8, 1e8);
  const std::string f = failure(far);
  const std::size_t at = e.find(", near ("), fat = f.find(", near (");
  ASSERT_NE(fat, std::string::npos) << f;
  EXPECT_EQ(f.substr(0, fat), e.substr(0, at));
  double x = 0, y = 0, fx = 0, fy = 0;
  ASSERT_EQ(std::sscanf(e.c_str() + at, ", near (%lf, %lf)", &x, &y), 2) << e;
  ASSERT_EQ(std::sscanf(f.c_str() + fat, ", near (%lf, %lf)", &fx, &fy), 2) << f;
  EXPECT_NEAR(fx - 1e8, x, 1e-6);
  EXPECT_NEAR(fy - 1e8, y, 1e-6);
  EXPECT_GE(x, 0.0);
  EXPECT_LE(x, 2.0);
  EXPECT_GE(y, 0.0);
  EXPECT_LE(y, 2.0);
}

}  // namespace
}  // namespace bisect::mesh2d
