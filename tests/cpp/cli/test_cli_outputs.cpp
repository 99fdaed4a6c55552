// Every file bisect-mesh writes reaches the disk whole, or the run says which one did not (exit 2,
// one line) and leaves no partial file behind: a full device (/dev/full), a folder that does not
// exist, and a write cut off midway by the file size limit (RLIMIT_FSIZE, as a quota would).
#include <gtest/gtest.h>

#include "cli_run.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Result = bisect::test::CliResult;
using bisect::test::has;
using bisect::test::slurp;

fs::path scratch() { return bisect::test::scratch_dir("outputs"); }

// bisect-mesh with `args`; in the child the file size limit is `fsize` bytes when > 0.
Result run(const std::vector<std::string>& args, rlim_t fsize = 0) {
  bisect::test::ChildSetup setup;
  setup.fsize = fsize;
  return bisect::test::run_cli_argv(args, "outputs", setup);
}

int lines(const std::string& s) { return bisect::test::count_lines(s); }

const std::string kCubes = std::string(BISECT_TEST_DATA) + "/cube-cavity-adjacent-cube.poly";
const std::string kSquares = std::string(BISECT_TEST_DATA) + "/square-subdomain-adjacent-square.poly2";

// A name with the extension the CLI asks for, that leads to /dev/full.
fs::path full_device_as(const std::string& name) {
  const fs::path link = scratch() / name;
  fs::remove(link);
  fs::create_symlink("/dev/full", link);
  return link;
}

}  // namespace

TEST(CliOutputs, EveryMeshFormatOnAFullDeviceExitsTwoNamingIt) {
  for (const char* ext : {".vtu", ".msh", ".inp", ".unv"}) {
    const fs::path out = full_device_as(std::string("full") + ext);
    const Result r = run({kCubes, "-n", "300", "-o", out.string()});
    EXPECT_EQ(r.code, 2) << ext << ": " << r.out << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_TRUE(has(r.err, out.string() + ": write failed: No space left on device")) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;  // no success line
    EXPECT_TRUE(fs::is_symlink(out));     // not a regular file: left alone
  }
}

TEST(CliOutputs, TwoDMeshCellsAndStatsOnAFullDeviceExitTwoNamingThem) {
  const fs::path vtu = full_device_as("full2d.vtu");
  Result r = run({kSquares, "-n", "200", "-o", vtu.string()});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(has(r.err, vtu.string() + ": write failed")) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;

  const fs::path cells = full_device_as("full.poly");
  r = run({kCubes, "--cells-only", "-o", cells.string()});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(has(r.err, cells.string() + ": write failed")) << r.err;

  // --stats of each job: the mesh itself is written, the statistics are not
  const fs::path good3 = scratch() / "ok.vtu", good2 = scratch() / "ok2.vtu", goodc = scratch() / "ok.poly";
  const std::vector<std::vector<std::string>> jobs = {
      {kCubes, "-n", "300", "-o", good3.string(), "--stats", "/dev/full"},
      {kSquares, "-n", "200", "-o", good2.string(), "--stats", "/dev/full"},
      {kCubes, "--cells-only", "-o", goodc.string(), "--stats", "/dev/full"}};
  for (const auto& job : jobs) {
    r = run(job);
    EXPECT_EQ(r.code, 2) << job[1] << ": " << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_TRUE(has(r.err, "/dev/full: write failed: No space left on device")) << r.err;
  }
  EXPECT_GT(fs::file_size(good3), 0u);
  EXPECT_GT(fs::file_size(good2), 0u);
  EXPECT_GT(fs::file_size(goodc), 0u);
}

TEST(CliOutputs, StandardOutputOnAFullDeviceExitsTwo) {
  const fs::path full = full_device_as("stdout-full");
  const std::string cmd = std::string("'") + BISECT_CLI + "' info '" + kCubes + "' > '" + full.string() + "' 2> '" +
                          (scratch() / "err").string() + "'";
  const int status = std::system(cmd.c_str());
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 2);
  EXPECT_TRUE(has(slurp(scratch() / "err"), "standard output: write failed")) << slurp(scratch() / "err");
}

TEST(CliOutputs, AFolderThatDoesNotExistExitsTwoNamingIt) {
  const std::string missing = (scratch() / "no-such-folder").string();
  const std::vector<std::vector<std::string>> jobs = {
      {kCubes, "-n", "300", "-o", missing + "/m.vtu"},
      {kSquares, "-n", "200", "-o", missing + "/m.vtu"},
      {kCubes, "--cells-only", "-o", missing + "/c.poly"},
      {kCubes, "--cells-only", "-o", (scratch() / "c.poly").string(), "--stats", missing + "/s.json"}};
  for (const auto& job : jobs) {
    const Result r = run(job);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_TRUE(has(r.err, "the directory " + missing + " does not exist")) << r.err;
  }
  EXPECT_FALSE(fs::exists(missing));
}

// A write that fails after the first kilobyte: the file size limit cuts each kind of output
// midway (each is checked to be larger than the limit when written freely); the run exits 2
// naming the file and leaves none of it.
TEST(CliOutputs, AWriteCutOffMidwayLeavesNoPartialFile) {
  constexpr rlim_t kLimit = 1024;
  struct Job {
    std::vector<std::string> args;
    fs::path file;
  };
  const fs::path d = scratch();
  const std::vector<Job> jobs = {
      {{kCubes, "-n", "300", "-o", (d / "cut.vtu").string()}, d / "cut.vtu"},
      {{kCubes, "-n", "300", "-o", (d / "cut.msh").string()}, d / "cut.msh"},
      {{kCubes, "-n", "300", "-o", (d / "cut.inp").string()}, d / "cut.inp"},
      {{kCubes, "-n", "300", "-o", (d / "cut.unv").string()}, d / "cut.unv"},
      {{kSquares, "-n", "200", "-o", (d / "cut2.vtu").string()}, d / "cut2.vtu"},
      {{kCubes, "--cells-only", "-o", (d / "cut.poly").string()}, d / "cut.poly"}};
  for (const Job& job : jobs) {
    fs::remove(job.file);
    const Result whole = run(job.args);
    ASSERT_EQ(whole.code, 0) << whole.err;
    ASSERT_GT(fs::file_size(job.file), kLimit) << job.file;  // else the limit would not cut it
    fs::remove(job.file);
    const Result cut = run(job.args, kLimit);
    EXPECT_EQ(cut.code, 2) << job.file << ": " << cut.err;
    EXPECT_EQ(lines(cut.err), 1) << cut.err;
    EXPECT_TRUE(has(cut.err, job.file.string() + ": write failed: File too large; the partial file was removed")) << cut.err;
    EXPECT_FALSE(fs::exists(job.file)) << job.file;
  }
}
