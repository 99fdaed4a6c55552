// Bounded work: numbers on the command line are read strictly (no overflow clamped, no NaN), a
// job whose estimated memory exceeds --max-memory (default half of the physical memory) is
// refused before meshing, and --grading stays in the range the graded nodes handle.
#include <gtest/gtest.h>

#include "cli_run.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

using Result = bisect::test::CliResult;
using bisect::test::has;
using bisect::test::slurp;

fs::path scratch() { return bisect::test::scratch_dir("bounds"); }

Result run(const std::string& args) { return bisect::test::run_cli(args, "bounds"); }

int lines(const std::string& s) { return bisect::test::count_lines(s); }

const std::string kCubes = "'" + std::string(BISECT_TEST_DATA) + "/cube-cavity-adjacent-cube.poly'";
const std::string kSquares = "'" + std::string(BISECT_TEST_DATA) + "/square-subdomain-adjacent-square.poly2'";

std::string out_vtu() { return " -o '" + (scratch() / "m.vtu").string() + "'"; }

}  // namespace

// -n 1e9 used to take 1.7 GB and 20 s before "out of memory": now refused before any meshing.
TEST(CliBounds, ABillionElementsIsRefusedUpFrontNamingMaxMemory) {
  fs::remove(scratch() / "m.vtu");
  const Result r = run(kCubes + " -n 1e9" + out_vtu());
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_TRUE(has(r.err, "-n 1000000000: an estimated 1e+09 tetrahedra")) << r.err;
  EXPECT_TRUE(has(r.err, "--max-memory")) << r.err;
  // the estimate is in the message, in GB, and far over any half of a machine's memory here
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.err, m, std::regex("need about ([0-9.]+) GB"))) << r.err;
  EXPECT_GT(std::stod(m[1]), 100.0) << r.err;
  EXPECT_LT(r.seconds, 10.0);  // refused, not attempted (a generous bound on a loaded machine)
  EXPECT_FALSE(fs::exists(scratch() / "m.vtu"));
  // the same for the 2D mesher and for a spacing far below the part's size
  Result t = run(kSquares + " -n 1e9" + out_vtu());
  EXPECT_EQ(t.code, 2) << t.err;
  EXPECT_TRUE(has(t.err, "triangles")) << t.err;
  EXPECT_TRUE(has(t.err, "--max-memory")) << t.err;
  t = run(kCubes + " -s 1e-6" + out_vtu());
  EXPECT_EQ(t.code, 2) << t.err;
  EXPECT_TRUE(has(t.err, "-s 1e-06: an estimated")) << t.err;
}

TEST(CliBounds, MaxMemorySetsTheLimit) {
  Result r = run(kCubes + " -n 100000 --max-memory 40" + out_vtu());
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(has(r.err, "-n 100000: an estimated 100000 tetrahedra")) << r.err;
  EXPECT_TRUE(has(r.err, "over the limit of 40 MB set by --max-memory")) << r.err;
  r = run(kCubes + " -n 300 --max-memory 100" + out_vtu());
  EXPECT_EQ(r.code, 0) << r.err;
  // the input's own R is what asks for the elements when -n is not given: the file is named
  const fs::path big = scratch() / "big-r.poly";
  std::string text = slurp(std::string(BISECT_TEST_DATA) + "/cube-cavity-adjacent-cube.poly");
  const std::size_t header = text.find("17 20 3 26");
  ASSERT_NE(header, std::string::npos);
  text.replace(header, 10, "17 20 3 900000000");
  std::ofstream(big) << text;
  r = run("'" + big.string() + "'" + out_vtu());
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(has(r.err, big.string() + ": its required element count R = 900000000")) << r.err;
  for (const char* bad : {"0", "-5", "nan", "inf", "lots"}) {
    r = run(kCubes + " -n 300 --max-memory " + bad + out_vtu());
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_TRUE(has(r.err, std::string("--max-memory needs")) && has(r.err, std::string("'") + bad + "'")) << r.err;
  }
}

// Numbers are never clamped or wrapped: each bad value is refused naming the flag and the value.
TEST(CliBounds, NumbersOutOfRangeAreRefusedNamingFlagAndValue) {
  struct Case {
    const char* flag;
    const char* value;
    const char* why;
  };
  for (const Case& c : {Case{"-n", "99999999999999999999", "too large"}, Case{"-n", "3e9", "too large"},
                        Case{"-n", "2147483648", "too large"}, Case{"-n", "nan", "not a number"},
                        Case{"-n", "inf", "too large"}, Case{"-n", "-5", "negative"}, Case{"-n", "0", "too small"},
                        Case{"-n", "2.5", "not a whole number"}, Case{"-s", "nan", "not a number"},
                        Case{"-s", "inf", "not finite"}, Case{"-s", "1e999", "not finite"}, Case{"-s", "0", "zero"},
                        Case{"-s", "-1", "negative"}, Case{"--threads", "99999999999999999999", "too large"},
                        Case{"--optimize", "-1", "negative"}, Case{"--slivers", "1e9", "too large"}}) {
    const Result r = run(kCubes + " " + c.flag + " " + c.value + out_vtu());
    EXPECT_EQ(r.code, 2) << c.flag << " " << c.value;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_TRUE(has(r.err, std::string(c.flag) + " needs")) << r.err;
    EXPECT_TRUE(has(r.err, std::string("'") + c.value + "' (" + c.why + ")")) << r.err;
  }
  // counts written in exponent notation are whole numbers too
  const Result r = run(kCubes + " -n 3e2" + out_vtu());
  EXPECT_EQ(r.code, 0) << r.err;
}

// --grading 1e-300 never ended (graded_nodes.cpp's shells grow as 1/G^3): refused at parse time.
TEST(CliBounds, GradingOutsideItsRangeIsRefused) {
  for (const char* g : {"1e-300", "0.01", "0.19", "-1", "nan", "11", "inf"}) {
    const Result r = run(kCubes + " -n 300 --grading " + g + out_vtu());
    EXPECT_EQ(r.code, 2) << g;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_TRUE(has(r.err, std::string("--grading needs 0 (off) or a number from 0.2 to 10, not '") + g + "'")) << r.err;
  }
}

TEST(CliBounds, GradingInItsRangeFinishes) {
  for (const char* g : {"0.3", "0.2", "10"}) {
    const Result r = run(kCubes + " -n 2000 --grading " + g + out_vtu());
    EXPECT_EQ(r.code, 0) << g << ": " << r.err;
    EXPECT_TRUE(has(r.out, "tetrahedra")) << r.out;
  }
}

// A thin sheet at a coarse count: the walls' cap keeps its elements 0.8 thick, some 1.2e7 of them
// for 10,000 asked, which the estimate from R cannot see; refused at once once the cells are known,
// naming the walls and the limit, and meshed at a count the limit holds.
TEST(CliBounds, AThinSheetsWallsAreBoundedByTheMemoryLimitToo) {
  const fs::path sheet = scratch() / "sheet.off";
  std::ofstream(sheet) << "OFF\n8 6 0\n0 0 0\n1000 0 0\n1000 1000 0\n0 1000 0\n0 0 1\n1000 0 1\n1000 1000 1\n0 1000 1\n"
                          "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
  fs::remove(scratch() / "m.vtu");
  const Result r = run("'" + sheet.string() + "' -n 10000 --max-memory 200" + out_vtu());
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_TRUE(has(r.err, "sheet.off: the cells' volumes at their spacings predict about 1.15e+07 tetrahedra")) << r.err;
  EXPECT_TRUE(has(r.err, "walls down to 1 thick get elements no larger than 0.8")) << r.err;
  EXPECT_TRUE(has(r.err, "the memory limit of 200 MB set by --max-memory")) << r.err;
  EXPECT_LT(r.seconds, 10.0);
  EXPECT_FALSE(fs::exists(scratch() / "m.vtu"));
}
