// Overlapping 2D polygons (issue 20): two regions covering the same area used to be meshed twice
// (1.75 of union covered 2.0); they are refused, naming both polygons by the file's numbers and a
// point of the overlap. Polygons that share edges, holes, and sub-domains inside a polygon (also
// touching its boundary) are not overlaps.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "bisect/errors.hpp"
#include "bisect/io.hpp"
#include "domain/poly2_overlaps.hpp"
#include "mesh2d/planar_mesher.hpp"

namespace bisect {
namespace {

Poly2Input poly2(const std::string& text) {
  std::istringstream in(text);
  return read_poly2(in, "test.poly2");
}

std::string refusal(const Poly2Input& in) {
  try {
    mesh2d::mesh_planar(in, {});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(PolygonOverlap, CrossingSquaresAreRefusedNamingBoth) {
  const std::string e = refusal(read_poly2(std::string(BISECT_TEST_DATA) + "/overlapping-squares.poly2"));
  EXPECT_TRUE(contains(e, "overlapping-squares.poly2: polygons 1 and 2 overlap")) << e;
  EXPECT_TRUE(contains(e, "their edges cross")) << e;
  EXPECT_TRUE(contains(e, "(1, 0.5)") || contains(e, "(0.5, 1)")) << e;  // where the edges cross
}

TEST(PolygonOverlap, APolygonRunningInAndOutThroughVerticesIsRefused) {
  // no two edges cross properly: the diamond's corners lie on the square's edge
  const std::string e = refusal(read_poly2(std::string(BISECT_TEST_DATA) + "/squares-overlap-at-vertices.poly2"));
  EXPECT_TRUE(contains(e, "polygons 1 and 2 overlap")) << e;
  // the square's right edge runs along the diamond's diagonal, inside it, and outside it above and below
  EXPECT_TRUE(contains(e, "polygon 1 runs both inside and outside polygon 2, at (2, 1)")) << e;
}

TEST(PolygonOverlap, TheSameOutlineTwiceIsRefused) {
  // a triangle beside the square, then the square twice, started at different corners
  const std::string e = refusal(poly2("100\n5 3\n3 4 4\n0 0\n1 0\n1 1\n0 1\n3 0\n"
                                      "2 5 3\n1 2 3 4\n2 3 4 1\n"));
  EXPECT_TRUE(contains(e, "polygons 2 and 3 overlap (they have the same outline")) << e;
}

TEST(PolygonOverlap, SharedEdgesHolesAndSubDomainsAreNoOverlap) {
  for (const char* f : {"square-hole-adjacent-square.poly2", "square-subdomain-adjacent-square.poly2"})
    EXPECT_NO_THROW(reject_overlapping_polygons(read_poly2(std::string(BISECT_TEST_DATA) + "/" + f))) << f;
  // a sub-domain sharing two edges with its square, and a triangle on the square's top edge
  const Poly2Input in = poly2("100\n8 3\n6 4 3\n0 0\n2 0\n2 2\n0 2\n1 0\n1 1\n0 1\n3 3\n"
                              "1 5 2 3 4 7\n1 5 6 7\n3 8 4\n");
  EXPECT_NO_THROW(reject_overlapping_polygons(in));
}

TEST(PolygonOverlap, AHoleReachingOutOfItsPolygonIsRefused) {
  // the reader refuses a hole with a node outside every region; the library's callers may not
  Poly2Input in = read_poly2(std::string(BISECT_TEST_DATA) + "/overlapping-squares.poly2");
  in.polygons[1].hole = true;
  const std::string e = refusal(in);
  EXPECT_TRUE(contains(e, "polygons 1 and 2 overlap (their edges cross")) << e;
}

}  // namespace
}  // namespace bisect
