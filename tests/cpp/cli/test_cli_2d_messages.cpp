// Every 2D failure the CLI prints names the input file: the planar mesher's deeper stages
// (recursive bisection, the convex decomposition) say what failed but not in which file.
#include <gtest/gtest.h>

#include "cli_run.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

fs::path scratch() { return bisect::test::scratch_dir("2d"); }

using Result = bisect::test::CliResult;

Result mesh(const fs::path& in, const fs::path& out) {
  return bisect::test::run_cli("'" + in.string() + "' -o '" + out.string() + "'", "2d");
}

}  // namespace

// Holes that touch their polygon's boundary (at a vertex, along an edge) and a hole outside
// every polygon: each either meshes or fails with one line that begins with the file's name.
TEST(Cli2dMessages, EveryFailureNamesTheInputFile) {
  const char* inputs[][2] = {
      {"hole-at-a-vertex.poly2", "50\n7 2\n4 -3\n0 0\n1 0\n1 1\n0 1\n0.5 0.5\n0.8 0.3\n0.8 0.7\n1 2 3 4\n3 5 7\n"},
      {"hole-on-an-edge.poly2",
       "50\n8 2\n4 -4\n0 0\n1 0\n1 1\n0 1\n0.25 0\n0.75 0\n0.75 0.5\n0.25 0.5\n1 2 3 4\n5 6 7 8\n"},
      {"hole-across-the-boundary.poly2",
       "50\n8 2\n4 -4\n0 0\n1 0\n1 1\n0 1\n0.5 0.25\n1.5 0.25\n1.5 0.75\n0.5 0.75\n1 2 3 4\n5 6 7 8\n"},
      {"no-count.poly2", "0\n4 1\n4\n0 0\n1 0\n1 1\n0 1\n1 2 3 4\n"}};
  int failures = 0;
  for (const auto& [name, text] : inputs) {
    const fs::path in = scratch() / name, out = scratch() / "out.vtu";
    std::ofstream(in) << text;
    fs::remove(out);
    const Result r = mesh(in, out);
    if (r.code == 0) {
      EXPECT_TRUE(fs::exists(out)) << name;
      continue;
    }
    ++failures;
    EXPECT_TRUE(r.code == 2 || r.code == 3) << name << ": " << r.code;
    EXPECT_EQ(r.err.find("bisect-mesh: " + in.string() + ":"), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_GT(failures, 0);  // the inputs are not all meshable: at least the hole outside every polygon
}

// Notches mesh (issue 20): a sub-domain in a corner of its square, a hole touching the boundary
// at a vertex, a hole whose side runs along part of the bottom edge (its nodes not in the outer
// polygon). A polygon that crosses itself is refused up front (exit 2) with the file's line, the
// polygon, both edges by their nodes and the crossing point, where it used to fail deep inside
// the recursive bisection (exit 3, "a flat triangle").
TEST(Cli2dMessages, NotchesMeshAndSelfCrossingPolygonsAreRefused) {
  const char* meshable[][2] = {
      {"corner.poly2", "100\n7 2\n6 4\n0 0\n2 0\n2 2\n0 2\n1 0\n1 1\n0 1\n1 5 2 3 4 7\n1 5 6 7\n"},
      {"hole-at-a-vertex.poly2", "50\n7 2\n4 -3\n0 0\n1 0\n1 1\n0 1\n0.5 0.5\n0.8 0.3\n0.8 0.7\n1 2 3 4\n3 5 7\n"},
      {"hole-on-an-edge.poly2",
       "50\n8 2\n4 -4\n0 0\n1 0\n1 1\n0 1\n0.25 0\n0.75 0\n0.75 0.5\n0.25 0.5\n1 2 3 4\n5 6 7 8\n"}};
  for (const auto& [name, text] : meshable) {
    const fs::path in = scratch() / name, out = scratch() / "out.vtu";
    std::ofstream(in) << text;
    fs::remove(out);
    const Result r = mesh(in, out);
    EXPECT_EQ(r.code, 0) << name << ": " << r.err;
    EXPECT_TRUE(fs::exists(out)) << name;
  }
  const fs::path in = scratch() / "bow-tie.poly2", out = scratch() / "out.vtu";
  std::ofstream(in) << "50\n4 1\n4\n0 0\n2 2\n2 0\n0 1\n1 2 3 4\n";
  fs::remove(out);
  const Result r = mesh(in, out);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(r.err, "bisect-mesh: " + in.string() +
                       ":8: polygon 1 crosses itself (its edges from node 1 to 2 and from node 3 to 4), at (0.666666667, 0.666666667); a polygon "
                       "must be simple\n");
  EXPECT_FALSE(fs::exists(out));
}
