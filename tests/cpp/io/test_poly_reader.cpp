// The thesis formats: .poly (6.13) and .poly2 (4.6.1). Good files read into what the thesis
// describes; each kind of bad input gets one line naming the file, the line and the face, node or
// region by its number in the file.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "bisect/errors.hpp"
#include "bisect/io.hpp"
#include "input_error.hpp"

using namespace bisect;
namespace fs = std::filesystem;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

// `text` with its 1-based line `line` replaced (or removed when `with` is null).
std::string replace_line(const std::string& text, int line, const char* with) {
  std::istringstream in(text);
  std::string out, l;
  for (int n = 1; std::getline(in, l); ++n) {
    if (n != line) out += l + "\n";
    else if (with) out += std::string(with) + "\n";
  }
  return out;
}

std::string line_of(const std::string& text, int line) {
  std::istringstream in(text);
  std::string l;
  for (int n = 1; n <= line; ++n) std::getline(in, l);
  return l;
}

// A unit cube, faces in mixed directions. Line numbers matter to the tests below.
const char* const kCube =
    "-- a unit cube\n"       // 1
    "6 8 1 0\n"              // 2
    "0 0 0\n"                // 3  node 1
    "1 0 0\n"                // 4  node 2
    "1 1 0\n"                // 5  node 3
    "0 1 0\n"                // 6  node 4
    "0 0 1\n"                // 7  node 5
    "1 0 1\n"                // 8  node 6
    "1 1 1\n"                // 9  node 7
    "0 1 1\n"                // 10 node 8
    "4 1 2 3 4\n"            // 11 face 1 (z = 0)
    "4 5 6 7 8\n"            // 12 face 2 (z = 1)
    "4 1 2 6 5\n"            // 13 face 3 (y = 0)
    "4 2 3 7 6\n"            // 14 face 4 (x = 1)
    "4 3 4 8 7\n"            // 15 face 5 (y = 1)
    "4 4 1 5 8\n"            // 16 face 6 (x = 0)
    "6 1 2 3 4 5 6\n";       // 17 region 1

PolyInput poly(const std::string& text) {
  std::istringstream in(text);
  return read_poly(in, "test.poly");
}

Poly2Input poly2(const std::string& text) {
  std::istringstream in(text);
  return read_poly2(in, "test.poly2");
}

using bisect::test::error_of;

std::string poly_error(const std::string& text) { return error_of([&] { poly(text); }); }
std::string poly2_error(const std::string& text) { return error_of([&] { poly2(text); }); }

const std::string kData = BISECT_TEST_DATA;

}  // namespace

// ---- good .poly files ----

TEST(PolyReader, ReadsTheCubeWithACavity) {
  const PolyInput in = read_poly(kData + "/cube-cavity-adjacent-cube.poly");
  EXPECT_EQ(in.faces.size(), 17u);
  EXPECT_EQ(in.nodes.size(), 20u);
  ASSERT_EQ(in.regions.size(), 3u);
  EXPECT_EQ(in.required_elements, 26);
  EXPECT_EQ(in.nodes[12], Vec3(0.25, 0.25, 0.75));
  EXPECT_EQ(in.faces[5].nodes, (std::vector<Index>{1, 11, 8, 2}));  // "4 2 12 9 3", 0-based
  EXPECT_FALSE(in.regions[0].cavity);
  EXPECT_FALSE(in.regions[1].cavity);
  EXPECT_TRUE(in.regions[2].cavity);
  EXPECT_EQ(in.regions[0].faces, (std::vector<Index>{0, 1, 2, 3, 4, 10}));
  EXPECT_EQ(in.regions[2].faces.size(), 6u);
  for (const PolyFace& f : in.faces) EXPECT_EQ(f.hole_of, -1);
  EXPECT_NE(in.source.find("cube-cavity-adjacent-cube.poly"), std::string::npos);
}

TEST(PolyReader, ReentryBoxFace12IsTheHoleOfFace6) {
  const PolyInput in = read_poly(kData + "/reentry-box.poly");
  ASSERT_EQ(in.faces.size(), 12u);
  EXPECT_EQ(in.nodes.size(), 16u);
  ASSERT_EQ(in.regions.size(), 1u);
  for (std::size_t f = 0; f < in.faces.size(); ++f) EXPECT_EQ(in.faces[f].hole_of, f == 11 ? 5 : -1) << f;
}

TEST(PolyReader, ReadsTheSharedExamples) {
  const fs::path dir = fs::path(BISECT_SHARED_DIR) / "examples";
  if (!fs::exists(dir)) GTEST_SKIP() << dir << " is missing";
  int read = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".poly") continue;
    const PolyInput in = read_polyhedral(e.path().string());
    EXPECT_FALSE(in.regions.empty()) << e.path();
    ++read;
  }
  EXPECT_GE(read, 2);
}

TEST(PolyReader, CommentsAnywhereATitleLineAndCrlf) {
  std::string text = "Re-entry box\n";  // the thesis's second listing starts with a title
  text += replace_line(kCube, 2, "6 8 1 26 -- faces, nodes, regions, required elements");
  text = replace_line(text, 12, "4 1 2 3 4--the bottom, comment without a space");
  text = replace_line(text, 6, "-- a comment line between nodes\n1 1 0");
  std::string crlf;
  for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const PolyInput in = poly(crlf);
  EXPECT_EQ(in.required_elements, 26);
  EXPECT_EQ(in.nodes.size(), 8u);
  EXPECT_EQ(in.faces[0].nodes, (std::vector<Index>{0, 1, 2, 3}));
}

TEST(PolyReader, HeaderWithoutRequiredElements) {
  EXPECT_EQ(poly(replace_line(kCube, 2, "6 8 1")).required_elements, 0);
}

// Planarity is judged relative to the face and to the round-off of its coordinates: a rotated
// cube printed to 17 digits, far from the origin, reads whatever its size.
TEST(PolyReader, RotatedCubesFarFromTheOriginRead) {
  const Eigen::Matrix3d rot =
      (Eigen::AngleAxisd(0.3, Vec3::UnitZ()) * Eigen::AngleAxisd(0.7, Vec3(1, 1, 0).normalized())).toRotationMatrix();
  for (double size : {1e-3, 1.0, 1e3}) {
    for (double offset : {0.0, 1e4, 1e8}) {
      std::string text = kCube;
      for (int line = 3; line <= 10; ++line) {
        std::istringstream xyz(line_of(kCube, line));
        Vec3 p;
        xyz >> p.x() >> p.y() >> p.z();
        const Vec3 q = rot * (size * p) + Vec3::Constant(offset);
        char buf[128];
        std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g", q.x(), q.y(), q.z());
        text = replace_line(text, line, buf);
      }
      EXPECT_NO_THROW(poly(text)) << size << " " << offset;
    }
  }
}

// Thesis 6.12 (B): a face of one region lying inside a larger coplanar face of the same region
// is a hole of it, even when nothing else of that region closes it (it is the interface with the
// region sitting on it).
TEST(PolyReader, InterfaceFaceInsideALargerFaceIsItsHole) {
  const char* text =
      "12 16 2 0\n"
      "0 0 0\n2 0 0\n2 2 0\n0 2 0\n0 0 1\n2 0 1\n2 2 1\n0 2 1\n"
      "0.5 0.5 1\n1.5 0.5 1\n1.5 1.5 1\n0.5 1.5 1\n0.5 0.5 2\n1.5 0.5 2\n1.5 1.5 2\n0.5 1.5 2\n"
      "4 1 2 3 4\n4 5 6 7 8\n4 1 2 6 5\n4 2 3 7 6\n4 3 4 8 7\n4 4 1 5 8\n"
      "4 9 10 11 12\n"  // face 7: the interface, inside face 2
      "4 13 14 15 16\n4 9 10 14 13\n4 10 11 15 14\n4 11 12 16 15\n4 12 9 13 16\n"
      "7 1 2 3 4 5 6 7\n"
      "6 7 8 9 10 11 12\n";
  const PolyInput in = poly(text);
  for (std::size_t f = 0; f < in.faces.size(); ++f) EXPECT_EQ(in.faces[f].hole_of, f == 6 ? 1 : -1) << f;
}

TEST(PolyReader, DispatchesOnTheExtension) {
  EXPECT_EQ(read_polyhedral(kData + "/reentry-box.poly").faces.size(), 12u);
  EXPECT_HAS(error_of([&] { read_polyhedral(kData + "/square-hole-adjacent-square.poly2"); }), "2D input");
  EXPECT_HAS(error_of([&] { read_polyhedral("model.obj"); }), "model.obj: unknown polyhedral format '.obj'");
  EXPECT_HAS(error_of([&] { read_poly("/nonexistent/cube.poly"); }), "/nonexistent/cube.poly: cannot open the file");
}

// ---- bad .poly files, one per kind ----

TEST(PolyReader, NodeIndexOutOfRange) {
  EXPECT_EQ(poly_error(replace_line(kCube, 16, "4 4 1 5 41")),
            "test.poly:16: face 6 refers to node 41, but there are 8 nodes (numbered from 1)");
  EXPECT_HAS(poly_error(replace_line(kCube, 16, "4 4 1 5 0")), "test.poly:16: face 6 refers to node 0");
}

TEST(PolyReader, NaNAndInfiniteCoordinates) {
  EXPECT_EQ(poly_error(replace_line(kCube, 9, "1 nan 1")),
            "test.poly:9: the y coordinate of node 7 is not a finite number ('nan')");
  EXPECT_HAS(poly_error(replace_line(kCube, 4, "inf 0 0")), "test.poly:4: the x coordinate of node 2 is not a finite");
  EXPECT_HAS(poly_error(replace_line(kCube, 4, "1 0 -1e999")), "test.poly:4: the z coordinate of node 2 is not a finite");
  EXPECT_HAS(poly_error(replace_line(kCube, 4, "1 zero 0")),
             "test.poly:4: expected a number for the y coordinate of node 2, found 'zero'");
}

TEST(PolyReader, FaceWithFewerThanThreeNodes) {
  EXPECT_EQ(poly_error(replace_line(kCube, 13, "2 1 2")), "test.poly:13: face 3 has 2 nodes; a face needs at least 3");
}

TEST(PolyReader, RepeatedNodeInAFace) {
  EXPECT_EQ(poly_error(replace_line(kCube, 13, "4 1 2 6 1")), "test.poly:13: face 3 lists node 1 twice");
}

TEST(PolyReader, NonPlanarFaceGivesTheDistance) {
  const double h = 0.05;  // lift node 7 out of the planes of faces 2, 4 and 5
  const std::string m = poly_error(replace_line(kCube, 9, "1 1 1.05"));
  EXPECT_HAS(m, "test.poly:12: face 2 is not planar: node ");
  EXPECT_HAS(m, " from the face's plane (tolerance 1.4151e-09)");  // 1e-9 x the longer diagonal
  // For a quad with one corner lifted by h, every corner lies (h/2)/sqrt(4 + 2h^2) from the
  // Newell plane through the centroid.
  const std::size_t at = m.find(" lies ");
  ASSERT_NE(at, std::string::npos) << m;
  EXPECT_NEAR(std::stod(m.substr(at + 6)), (h / 2) / std::sqrt(4 + 2 * h * h), 1e-6) << m;
}

TEST(PolyReader, ZeroAreaFace) {
  const char* text = "1 3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 1 2 3\n1 1\n";
  EXPECT_EQ(poly_error(text), "test.poly:5: face 1 has zero area (its nodes are collinear or coincide)");
}

TEST(PolyReader, FewerNodesThanTheHeaderSays) {
  EXPECT_EQ(poly_error(replace_line(kCube, 2, "6 9 1 0")),
            "test.poly:11: node 9 has 5 numbers ('4 1 2 3 4'); a node is 3 coordinates x y z; does the header "
            "(6 faces, 9 nodes, 1 region) match the file?");
}

TEST(PolyReader, FaceListsFewerNodesThanItsCount) {
  EXPECT_EQ(poly_error(replace_line(kCube, 13, "4 1 2 6")), "test.poly:13: face 3 says it has 4 nodes but lists 3");
}

TEST(PolyReader, MoreFacesThanTheHeaderSays) {
  // Face 6 is read as the region, and the real region line is left over.
  const std::string m = poly_error(replace_line(kCube, 2, "5 8 1 0"));
  EXPECT_HAS(m, "test.poly:");
  EXPECT_HAS(m, "does the header (5 faces, 8 nodes, 1 region) match the file?");
}

TEST(PolyReader, FewerFacesThanTheHeaderSays) {
  EXPECT_EQ(poly_error(replace_line(kCube, 2, "7 8 1 0")),
            "test.poly:17: the file ends before region 1; does the header (7 faces, 8 nodes, 1 region) match the "
            "file?");
}

TEST(PolyReader, ExtraDataAfterTheLastRegion) {
  EXPECT_EQ(poly_error(std::string(kCube) + "6 1 2 3 4 5 6\n"),
            "test.poly:18: extra data after the last region: '6 1 2 3 4 5 6'; does the header (6 faces, 8 nodes, 1 "
            "region) match the file?");
}

TEST(PolyReader, BadHeader) {
  EXPECT_HAS(poly_error(replace_line(kCube, 2, "6 8")), "test.poly:2: the header must hold 4 numbers");
  EXPECT_HAS(poly_error(replace_line(kCube, 2, "6 8 0 0")), "test.poly:2: the region count is 0");
  EXPECT_HAS(poly_error(replace_line(kCube, 2, "6.5 8 1 0")), "test.poly:2: the face count must be a whole number");
  EXPECT_EQ(poly_error(""), "test.poly: the file is empty: expected the header 'faces nodes regions required_elements'");
  EXPECT_EQ(poly_error("-- nothing but a comment\n\n"),
            "test.poly:2: the file holds only comments and blank lines: expected the header 'faces nodes regions "
            "required_elements'");
  // Bytes of a binary file read as text are not echoed to the terminal.
  EXPECT_EQ(poly_error("6 8 1 \x01\x1b[2J\n"),
            "test.poly:1: expected a whole number for the required number of elements, found '??[2J'");
}

TEST(PolyReader, RegionRefersToAFaceOutOfRange) {
  EXPECT_HAS(poly_error(replace_line(kCube, 17, "6 1 2 3 4 5 9")),
             "test.poly:17: region 1 refers to face 9, but there are 6 faces (numbered from 1)");
}

TEST(PolyReader, FaceListedTwiceInARegion) {
  EXPECT_EQ(poly_error(replace_line(kCube, 17, "6 1 2 3 4 5 5")), "test.poly:17: region 1 lists face 5 twice");
}

TEST(PolyReader, RegionCountDoesNotMatchItsList) {
  EXPECT_EQ(poly_error(replace_line(kCube, 17, "6 1 2 3 4 5")),
            "test.poly:17: region 1 says it has 6 faces but lists 5");
  EXPECT_EQ(poly_error(replace_line(kCube, 17, "0")), "test.poly:17: region 1 has no faces");
}

TEST(PolyReader, FaceInThreeRegions) {
  std::string text = replace_line(kCube, 2, "6 8 3 0");
  text += "6 1 2 3 4 5 6\n6 1 2 3 4 5 6\n";
  EXPECT_EQ(poly_error(text),
            "test.poly:19: face 1 belongs to regions 1, 2 and 3; a face can bound at most two regions");
}

TEST(PolyReader, FaceInNoRegion) {
  EXPECT_EQ(poly_error(replace_line(kCube, 17, "5 1 2 3 4 5")), "test.poly:16: face 6 belongs to no region");
}

TEST(PolyReader, RegionThatIsNotClosed) {
  std::string text = replace_line(kCube, 2, "6 8 2 0");
  text = replace_line(text, 17, "5 1 2 3 4 5\n1 6");
  EXPECT_EQ(poly_error(text),
            "test.poly:17: region 1 is not closed: edge between nodes 1 (0, 0, 0) and 4 (0, 1, 0) belongs to only "
            "one face (face 1) of the region");
}

// ---- .poly2 ----

TEST(Poly2Reader, ReadsTheThesisExamples) {
  const Poly2Input a = read_poly2(kData + "/square-hole-adjacent-square.poly2");
  EXPECT_EQ(a.required_elements, 50);
  EXPECT_EQ(a.nodes.size(), 10u);
  ASSERT_EQ(a.polygons.size(), 3u);
  EXPECT_EQ(a.polygons[1].nodes, (std::vector<Index>{1, 4, 5, 2}));
  EXPECT_FALSE(a.polygons[0].hole);
  EXPECT_FALSE(a.polygons[1].hole);
  EXPECT_TRUE(a.polygons[2].hole);
  EXPECT_EQ(a.nodes[6], Vec2(0.25, 0.25));
  const Poly2Input b = read_poly2(kData + "/square-subdomain-adjacent-square.poly2");
  ASSERT_EQ(b.polygons.size(), 3u);
  for (const auto& p : b.polygons) EXPECT_FALSE(p.hole);
}

TEST(Poly2Reader, ReadsTheSharedExamples) {
  const fs::path dir = fs::path(BISECT_SHARED_DIR) / "examples" / "2d";
  if (!fs::exists(dir)) GTEST_SKIP() << dir << " is missing";
  int read = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".poly2") continue;
    EXPECT_EQ(read_poly2(e.path().string()).polygons.size(), 3u) << e.path();
    ++read;
  }
  EXPECT_EQ(read, 2);
}

namespace {
std::string square_with_hole() { return slurp(kData + "/square-hole-adjacent-square.poly2"); }
}  // namespace

TEST(Poly2Reader, NodeIndexOutOfRange) {
  EXPECT_EQ(poly2_error(replace_line(square_with_hole(), 17, "7 8 9 11")),
            "test.poly2:17: polygon 3 refers to node 11, but there are 10 nodes (numbered from 1)");
}

TEST(Poly2Reader, NaNCoordinate) {
  EXPECT_EQ(poly2_error(replace_line(square_with_hole(), 11, "nan 0.25")),
            "test.poly2:11: the x coordinate of node 7 is not a finite number ('nan')");
}

TEST(Poly2Reader, WrongCounts) {
  EXPECT_EQ(poly2_error(replace_line(square_with_hole(), 4, "4 4")),
            "test.poly2:4: expected 3 node counts (one per polygon), found 2 ('4 4')");
  EXPECT_HAS(poly2_error(replace_line(square_with_hole(), 16, "2 5 6")),
             "test.poly2:16: polygon 2 should list 4 nodes (its count on the third line) but lists 3");
  EXPECT_HAS(poly2_error(replace_line(square_with_hole(), 17, nullptr)), "test.poly2:16: the file ends before polygon 3");
  EXPECT_HAS(poly2_error(square_with_hole() + "1 2 3\n"), "test.poly2:18: extra data after the last polygon: '1 2 3'");
  EXPECT_HAS(poly2_error(replace_line(square_with_hole(), 2, "50 3")), "test.poly2:2: the first line must hold one number");
}

TEST(Poly2Reader, PolygonWithFewerThanThreeNodes) {
  EXPECT_EQ(poly2_error(replace_line(square_with_hole(), 4, "4 2 -4")),
            "test.poly2:4: polygon 2 has 2 nodes; a polygon needs at least 3");
}

TEST(Poly2Reader, RepeatedNode) {
  EXPECT_EQ(poly2_error(replace_line(square_with_hole(), 16, "2 5 5 3")), "test.poly2:16: polygon 2 lists node 5 twice");
}

TEST(Poly2Reader, ZeroAreaPolygon) {
  std::string text = replace_line(square_with_hole(), 4, "4 4 3");
  text = replace_line(text, 17, "1 2 5");
  EXPECT_HAS(poly2_error(text), "test.poly2:17: polygon 3 has zero area");
}

TEST(Poly2Reader, HoleInsideNoRegion) {
  std::string text = square_with_hole();
  for (int line = 11; line <= 14; ++line) {
    static const char* moved[] = {"5.25 0.25", "5.75 0.25", "5.75 0.75", "5.25 0.75"};
    text = replace_line(text, line, moved[line - 11]);
  }
  EXPECT_EQ(poly2_error(text),
            "test.poly2:17: polygon 3 is a hole (negative node count) but lies inside no region polygon");
}
