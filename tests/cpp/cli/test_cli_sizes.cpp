// The B-rep size field through the command line (--min-size, --max-size, --curvature-elements,
// --chord-deviation, --size-grading): each changes the mesh the way its help says, on a box with
// a through hole that FreeCAD made (tests/data/box-hole.brep: 20 x 20 x 10 mm, hole of radius 4),
// and bad values or inputs that have no size field are refused by name before any meshing.
#include <gtest/gtest.h>

#include "cli_run.hpp"

#include <cstdlib>
#include <filesystem>
#include <string>

namespace fs = std::filesystem;

namespace {

using bisect::test::CliResult;
using bisect::test::has;
using bisect::test::slurp;

const std::string kBoxHole = "'" + std::string(BISECT_TEST_DATA) + "/box-hole.brep'";

fs::path scratch() { return bisect::test::scratch_dir("sizes"); }

// A whole-number field of the --stats JSON (`"name": 123`), -1 when absent.
long long stat(const std::string& json, const std::string& name) {
  const std::size_t at = json.find("\"" + name + "\":");
  if (at == std::string::npos) return -1;
  return std::atoll(json.c_str() + at + name.size() + 3);
}

struct SizedRun {
  CliResult r;
  long long tets = -1, nodes = -1;
};

SizedRun mesh(const std::string& flags, const std::string& name) {
  const fs::path out = scratch() / (name + ".vtu"), stats = scratch() / (name + ".json");
  SizedRun run;
  run.r = bisect::test::run_cli(kBoxHole + " -s 2 " + flags + " -o '" + out.string() + "' --stats '" + stats.string() + "'",
                                "sizes");
  if (run.r.code == 0) {
    const std::string json = slurp(stats);
    run.tets = stat(json, "tets");
    run.nodes = stat(json, "nodes");
  }
  return run;
}

}  // namespace

// The reference mesh and each bound in turn: a smaller maximum size, more elements per turn of
// the hole and a bound on the chord all make more elements; a minimum above the spacing fewer.
TEST(CliSizes, EachSizeFlagChangesTheMeshItsWay) {
  const SizedRun base = mesh("", "base");
  ASSERT_EQ(base.r.code, 0) << base.r.err;
  ASSERT_GT(base.tets, 100);

  const SizedRun capped = mesh("--max-size 1.2", "capped");
  ASSERT_EQ(capped.r.code, 0) << capped.r.err;
  EXPECT_GT(capped.tets, 3 * base.tets) << "a cap of 1.2 under a spacing of 2 is (2/1.2)^3 = 4.6 times the elements";

  // the hole's circumference is 25 mm: 12 per turn (2.1 mm) does not refine a 2 mm spacing,
  // 64 per turn (0.39 mm) does, around the hole only
  const SizedRun turned = mesh("--curvature-elements 64", "turned");
  ASSERT_EQ(turned.r.code, 0) << turned.r.err;
  EXPECT_GT(turned.tets, base.tets * 5 / 4);

  const SizedRun chord = mesh("--chord-deviation 0.005", "chord");  // sqrt(8 * 0.005 * 4) = 0.4 mm
  ASSERT_EQ(chord.r.code, 0) << chord.r.err;
  EXPECT_GT(chord.tets, base.tets * 5 / 4);

  // a steeper grading lets the fine hole's sizes reach the spacing sooner: fewer elements
  const SizedRun steep = mesh("--curvature-elements 64 --size-grading 2", "steep");
  ASSERT_EQ(steep.r.code, 0) << steep.r.err;
  EXPECT_LT(steep.tets, turned.tets);

  const SizedRun floored = mesh("--curvature-elements 64 --min-size 1.5", "floored");
  ASSERT_EQ(floored.r.code, 0) << floored.r.err;
  EXPECT_LT(floored.tets, turned.tets) << "a floor of 1.5 mm undoes most of the 0.39 mm around the hole";
}

TEST(CliSizes, BadValuesAndInputsWithoutASizeFieldAreRefusedByName) {
  const std::string out = " -o '" + (scratch() / "x.vtu").string() + "'";
  CliResult r = bisect::test::run_cli(kBoxHole + " -n 500 --min-size 3 --max-size 2" + out, "sizes");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(has(r.err, "--min-size 3 exceeds --max-size 2")) << r.err;

  r = bisect::test::run_cli(kBoxHole + " -n 500 --size-grading 0.01" + out, "sizes");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(has(r.err, "--size-grading")) << r.err;

  r = bisect::test::run_cli(kBoxHole + " -n 500 --curvature-elements 2" + out, "sizes");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(has(r.err, "--curvature-elements")) << r.err;

  r = bisect::test::run_cli(kBoxHole + " -n 500 --max-size -1" + out, "sizes");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(has(r.err, "--max-size")) << r.err;

  // a polyhedral input is meshed on its facets: the B-rep size field is refused by name
  r = bisect::test::run_cli("'" + std::string(BISECT_TEST_DATA) + "/two-cubes.stl' -n 500 --max-size 0.1" + out, "sizes");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(has(r.err, "--max-size sets the size field of B-rep inputs")) << r.err;
  EXPECT_FALSE(fs::exists(scratch() / "x.vtu"));
}
