// STL (ASCII and binary, told apart by content) and OFF: the models read as one closed region,
// and each kind of bad input gets one line naming the triangle, node or byte count at fault.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "bisect/errors.hpp"
#include "bisect/io.hpp"
#include "input_error.hpp"

using namespace bisect;
namespace fs = std::filesystem;

namespace {

using Tri = std::array<Vec3, 3>;

// A unit cube, 12 outward triangles. Merged in order of first use its corners become nodes
// 1 (0,0,0), 2 (0,1,0), 3 (1,1,0), 4 (1,0,0), 5 (0,0,1), 6 (1,0,1), 7 (1,1,1), 8 (0,1,1).
std::vector<Tri> cube() {
  auto p = [](double x, double y, double z) { return Vec3(x, y, z); };
  return {
      {p(0, 0, 0), p(0, 1, 0), p(1, 1, 0)}, {p(0, 0, 0), p(1, 1, 0), p(1, 0, 0)},  // z = 0
      {p(0, 0, 1), p(1, 0, 1), p(1, 1, 1)}, {p(0, 0, 1), p(1, 1, 1), p(0, 1, 1)},  // z = 1
      {p(0, 0, 0), p(1, 0, 0), p(1, 0, 1)}, {p(0, 0, 0), p(1, 0, 1), p(0, 0, 1)},  // y = 0
      {p(0, 1, 0), p(0, 1, 1), p(1, 1, 1)}, {p(0, 1, 0), p(1, 1, 1), p(1, 1, 0)},  // y = 1
      {p(0, 0, 0), p(0, 0, 1), p(0, 1, 1)}, {p(0, 0, 0), p(0, 1, 1), p(0, 1, 0)},  // x = 0
      {p(1, 0, 0), p(1, 1, 0), p(1, 1, 1)}, {p(1, 0, 0), p(1, 1, 1), p(1, 0, 1)},  // x = 1
  };
}

// Facet k (1-based) starts on line 2 + 7 (k - 1).
std::string ascii_stl(const std::vector<Tri>& tris) {
  std::ostringstream s;
  s << "solid cube made in a test\n";
  for (const Tri& t : tris) {
    const Vec3 n = (t[1] - t[0]).cross(t[2] - t[0]).normalized();
    s << "  facet normal " << n.x() << " " << n.y() << " " << n.z() << "\n    outer loop\n";
    for (const Vec3& v : t) s << "      vertex " << v.x() << " " << v.y() << " " << v.z() << "\n";
    s << "    endloop\n  endfacet\n";
  }
  s << "endsolid cube made in a test\n";
  return s.str();
}

std::string binary_stl(const std::vector<Tri>& tris, const std::string& header = "binary STL from a test") {
  std::string out(80, ' ');
  out.replace(0, header.size(), header);
  auto put32 = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out += char((v >> (8 * i)) & 0xff);
  };
  auto putf = [&](double d) {
    const float f = float(d);
    std::uint32_t bits;
    std::memcpy(&bits, &f, 4);
    put32(bits);
  };
  put32(std::uint32_t(tris.size()));
  for (const Tri& t : tris) {
    for (int i = 0; i < 3; ++i) putf(0);  // normal: readers ignore it, so may we
    for (const Vec3& v : t)
      for (int i = 0; i < 3; ++i) putf(v[i]);
    out += std::string(2, '\0');
  }
  return out;
}

PolyInput stl(const std::string& bytes) {
  std::istringstream in(bytes);
  return read_stl(in, "cube.stl");
}

PolyInput off(const std::string& text) {
  std::istringstream in(text);
  return read_off(in, "test.off");
}

using bisect::test::error_of;

std::string stl_error(const std::string& bytes) { return error_of([&] { stl(bytes); }); }
std::string off_error(const std::string& text) { return error_of([&] { off(text); }); }

void expect_cube(const PolyInput& in) {
  ASSERT_EQ(in.nodes.size(), 8u);
  ASSERT_EQ(in.faces.size(), 12u);
  ASSERT_EQ(in.regions.size(), 1u);
  EXPECT_EQ(in.regions[0].faces.size(), 12u);
  EXPECT_FALSE(in.regions[0].cavity);
  EXPECT_EQ(in.nodes[1], Vec3(0, 1, 0));
  EXPECT_EQ(in.faces[2].nodes, (std::vector<Index>{4, 5, 6}));
}

std::string replace_line(const std::string& text, int line, const char* with) {
  std::istringstream in(text);
  std::string out, l;
  for (int n = 1; std::getline(in, l); ++n) {
    if (n != line) out += l + "\n";
    else if (with) out += std::string(with) + "\n";
  }
  return out;
}

}  // namespace

// ---- STL ----

TEST(StlReader, AsciiCubeRoundTripThroughAFile) {
  const fs::path path = fs::temp_directory_path() / ("bisect-test-cube-" + std::to_string(::getpid()) + ".stl");
  {
    std::ofstream f(path);
    f << ascii_stl(cube());
  }
  const PolyInput ascii = read_stl(path.string());
  fs::remove(path);
  expect_cube(ascii);
  const PolyInput binary = stl(binary_stl(cube()));
  expect_cube(binary);
  EXPECT_EQ(ascii.nodes, binary.nodes);
  for (std::size_t i = 0; i < ascii.faces.size(); ++i) EXPECT_EQ(ascii.faces[i].nodes, binary.faces[i].nodes);
  EXPECT_EQ(ascii.source, path.string());
}

TEST(StlReader, AsciiKeywordsInAnyCaseAndSeveralSolids) {
  std::string text = ascii_stl(cube());
  for (const char* w : {"facet", "vertex", "endloop"}) {
    std::string up = w;
    for (char& c : up) c = char(std::toupper(c));
    for (std::size_t at = text.find(w); at != std::string::npos; at = text.find(w, at + 1)) text.replace(at, up.size(), up);
  }
  // The cube split over two solids in one file.
  const std::size_t cut = text.find("  FACET", text.find("endFACET") + 1);
  text.insert(cut, "endsolid first\nsolid second\n");
  expect_cube(stl(text));
}

TEST(StlReader, BinaryFileThatStartsWithSolid) {
  expect_cube(stl(binary_stl(cube(), "solid cube exported by a CAD system")));
}

TEST(StlReader, BinaryTruncated) {
  const std::string bytes = binary_stl(cube());
  EXPECT_EQ(stl_error(bytes.substr(0, bytes.size() - 10)),
            "cube.stl: truncated binary STL: its header announces 12 triangles, which take 84 + 50 x 12 = 684 bytes, "
            "but the file has 674 bytes");
  // The same with a header starting with "solid": still binary, still truncated.
  const std::string solid = binary_stl(cube(), "solid cube");
  EXPECT_HAS(stl_error(solid.substr(0, 300)), "cube.stl: truncated binary STL: its header announces 12 triangles");
  EXPECT_HAS(stl_error(bytes + "xx"), "binary STL with trailing data");
  EXPECT_HAS(stl_error(bytes.substr(0, 40)), "too short for a binary STL");
  EXPECT_HAS(stl_error(""), "cube.stl: the file is empty");
}

TEST(StlReader, AsciiNotClosedNamesAnOpenEdge) {
  std::vector<Tri> tris = cube();
  tris.pop_back();  // (1,0,0) (1,1,1) (1,0,1): its edge 6-7 is left to triangle 3 alone
  EXPECT_EQ(stl_error(ascii_stl(tris)),
            "cube.stl:16: not closed: edge between nodes 6 (1, 0, 1) and 7 (1, 1, 1) belongs to only one triangle "
            "(triangle 3)");
}

TEST(StlReader, BinaryNotClosedNamesAnOpenEdge) {
  std::vector<Tri> tris = cube();
  tris.pop_back();
  EXPECT_EQ(stl_error(binary_stl(tris)),
            "cube.stl: not closed: edge between nodes 6 (1, 0, 1) and 7 (1, 1, 1) belongs to only one triangle "
            "(triangle 3)");
}

TEST(StlReader, EdgeOfThreeTrianglesIsOpen) {
  std::vector<Tri> tris = cube();
  tris.push_back({Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0.5, 0.5)});  // a fin on edge 1-2
  EXPECT_HAS(stl_error(binary_stl(tris)), "belongs to 3 triangles (triangles 1, 10 and 13), an odd number");
}

TEST(StlReader, DegenerateTriangleAfterWelding) {
  std::vector<Tri> tris = cube();
  tris.push_back({Vec3(0, 0, 0), Vec3(-0.0, 0, 0), Vec3(1, 1, 1)});  // -0 welds with 0
  EXPECT_EQ(stl_error(binary_stl(tris)),
            "cube.stl: triangle 13 is degenerate: its corners 1 and 2 are the same point (0, 0, 0)");
  EXPECT_HAS(stl_error(ascii_stl(tris)), "cube.stl:86: triangle 13 is degenerate");
}

TEST(StlReader, ZeroAreaTriangle) {
  std::vector<Tri> tris = cube();
  tris.push_back({Vec3(0, 0, 0), Vec3(0.5, 0.5, 0.5), Vec3(1, 1, 1)});
  EXPECT_EQ(stl_error(binary_stl(tris)), "cube.stl: triangle 13 has zero area (its nodes are collinear or coincide)");
}

TEST(StlReader, NaNCoordinates) {
  std::vector<Tri> tris = cube();
  tris[0][0].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(stl_error(ascii_stl(tris)), "cube.stl:4: the x coordinate of vertex 1 of triangle 1 is not a finite number ('nan')");
  EXPECT_EQ(stl_error(binary_stl(tris)),
            "cube.stl: triangle 1: corner 1 has a coordinate that is not a finite number (nan, 0, 0)");
  tris[0][0].x() = HUGE_VAL;
  EXPECT_HAS(stl_error(binary_stl(tris)), "cube.stl: triangle 1: corner 1 has a coordinate that is not a finite number");
}

TEST(StlReader, AsciiSyntaxErrors) {
  const std::string text = ascii_stl(cube());
  EXPECT_EQ(stl_error(replace_line(text, 6, "      vertex 1 1 0\n      vertex 1 1 1")),
            "cube.stl:7: expected 'endloop' in triangle 1 (a facet has exactly 3 vertices), found 'vertex'");
  EXPECT_EQ(stl_error(replace_line(text, 86, nullptr)), "cube.stl:85: the file ends before 'endsolid'");
  EXPECT_EQ(stl_error(replace_line(text, 4, "      vertex 0 0")),
            "cube.stl:5: expected a number for the z coordinate of vertex 1 of triangle 1, found 'vertex'");
  EXPECT_EQ(stl_error("solid empty\nendsolid empty\n"), "cube.stl: the STL holds no triangles");
}

TEST(StlReader, ReadsTheSharedModels) {
  const fs::path dir = fs::path(BISECT_SHARED_DIR) / "models" / "stl";
  if (!fs::exists(dir)) GTEST_SKIP() << dir << " is missing";
  int read = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".stl") continue;
    const PolyInput in = read_polyhedral(e.path().string());
    EXPECT_EQ(in.regions.size(), 1u) << e.path();
    EXPECT_EQ(in.regions[0].faces.size(), in.faces.size()) << e.path();
    EXPECT_EQ(in.faces.size() * 50 + 84, fs::file_size(e.path())) << e.path();
    EXPECT_GE(in.nodes.size(), 4u) << e.path();
    ++read;
  }
  EXPECT_GE(read, 9);
}

// ---- OFF ----

namespace {
const char* const kCubeOff =
    "OFF\n"              // 1
    "# a unit cube\n"    // 2
    "8 6 12\n"           // 3
    "0 0 0\n"            // 4  vertex 0
    "1 0 0\n"            // 5
    "1 1 0\n"            // 6
    "0 1 0\n"            // 7
    "0 0 1\n"            // 8
    "1 0 1\n"            // 9
    "1 1 1\n"            // 10
    "0 1 1\n"            // 11 vertex 7
    "4 0 3 2 1\n"        // 12 face 0
    "4 4 5 6 7\n"        // 13 face 1
    "4 0 1 5 4\n"        // 14 face 2
    "4 1 2 6 5\n"        // 15 face 3
    "4 2 3 7 6\n"        // 16 face 4
    "4 3 0 4 7\n";       // 17 face 5
}  // namespace

TEST(OffReader, ReadsACube) {
  const PolyInput in = off(kCubeOff);
  EXPECT_EQ(in.nodes.size(), 8u);
  ASSERT_EQ(in.faces.size(), 6u);
  EXPECT_EQ(in.faces[1].nodes, (std::vector<Index>{4, 5, 6, 7}));
  ASSERT_EQ(in.regions.size(), 1u);
  EXPECT_EQ(in.regions[0].faces.size(), 6u);
}

TEST(OffReader, CountsOnTheHeaderLineColoursAndComments) {
  std::string text = replace_line(kCubeOff, 3, nullptr);
  text = replace_line(text, 1, "OFF 8 6 12 # counts on the keyword's line");
  text = replace_line(text, 11, "4 0 3 2 1 255 0 0");   // face 0 with an RGB colour
  text = replace_line(text, 12, "4 4 5 6 7 0.5 0.5 0.5 1");  // RGBA
  text = replace_line(text, 13, "4 0 1 5 4 3");        // a colour index
  EXPECT_EQ(off(text).faces.size(), 6u);
}

TEST(OffReader, VertexIndexOutOfRangeIsReportedFromZero) {
  EXPECT_EQ(off_error(replace_line(kCubeOff, 12, "4 0 3 2 8")),
            "test.off:12: face 0 refers to vertex 8, but there are 8 vertices (OFF numbers vertices and faces from 0)");
}

TEST(OffReader, NaNCoordinate) {
  EXPECT_EQ(off_error(replace_line(kCubeOff, 10, "1 1 NaN")),
            "test.off:10: the z coordinate of vertex 6 (OFF numbers vertices and faces from 0) is not a finite number "
            "('NaN')");
}

TEST(OffReader, FaceWithFewerThanThreeVertices) {
  EXPECT_EQ(off_error(replace_line(kCubeOff, 13, "2 4 5")),
            "test.off:13: face 1 has 2 vertices; a face needs at least 3 (OFF numbers vertices and faces from 0)");
}

TEST(OffReader, RepeatedVertexInAFace) {
  EXPECT_EQ(off_error(replace_line(kCubeOff, 13, "4 4 5 5 7")),
            "test.off:13: face 1 lists vertex 5 twice (OFF numbers vertices and faces from 0)");
}

TEST(OffReader, NonPlanarFace) {
  EXPECT_HAS(off_error(replace_line(kCubeOff, 10, "1 1 1.05")), "test.off:13: face 1 is not planar: vertex ");
}

TEST(OffReader, ZeroAreaFace) {
  EXPECT_HAS(off_error(replace_line(kCubeOff, 13, "3 4 5 4")), "face 1 lists vertex 4 twice");
  EXPECT_EQ(off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n"),
            "test.off:6: face 0 has zero area (its vertices are collinear or coincide) (OFF numbers vertices and faces "
            "from 0)");
}

TEST(OffReader, NotClosed) {
  std::string text = replace_line(kCubeOff, 17, nullptr);
  text = replace_line(text, 3, "8 5 12");
  EXPECT_EQ(off_error(text),
            "test.off:12: not closed: edge between vertices 0 (0, 0, 0) and 3 (0, 1, 0) belongs to only one face "
            "(face 0) (OFF numbers vertices and faces from 0)");
}

TEST(OffReader, WrongCounts) {
  EXPECT_EQ(off_error(replace_line(kCubeOff, 13, "4 4 5 6")),
            "test.off:13: face 1 says it has 4 vertices but lists 3 (OFF numbers vertices and faces from 0)");
  EXPECT_HAS(off_error(replace_line(kCubeOff, 3, "9 6 12")), "test.off:12: vertex 8 has 5 numbers");
  EXPECT_HAS(off_error(replace_line(kCubeOff, 3, "8 7 12")), "test.off:17: the file ends before face 6");
  EXPECT_HAS(off_error(std::string(kCubeOff) + "3 0 1 2\n"), "test.off:18: extra data after the last face: '3 0 1 2'");
  EXPECT_HAS(off_error(replace_line(kCubeOff, 13, "4 4 5 6 7 1 1")), "face 1 has 2 numbers after its 4 vertices");
}

TEST(OffReader, HeaderVariantsAreRefusedByName) {
  EXPECT_EQ(off_error(replace_line(kCubeOff, 1, "COFF")), "test.off:1: unsupported OFF variant 'COFF'; only plain 'OFF' is read");
  EXPECT_HAS(off_error(replace_line(kCubeOff, 1, "PLY")), "test.off:1: expected the header 'OFF', found 'PLY'");
  EXPECT_HAS(off_error(replace_line(kCubeOff, 1, "OFF BINARY")), "binary OFF is not supported");
}

TEST(OffReader, DispatchAndMissingFile) {
  EXPECT_HAS(error_of([] { read_polyhedral("/nonexistent/model.OFF"); }), "/nonexistent/model.OFF: cannot open the file");
}
