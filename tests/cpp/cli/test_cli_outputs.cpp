// Every file bisect-mesh writes reaches the disk whole, or the run says which one did not (exit 2,
// one line) and leaves no partial file behind: a full device (/dev/full), a folder that does not
// exist, and a write cut off midway by the file size limit (RLIMIT_FSIZE, as a quota would).
#include <gtest/gtest.h>

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

struct Result {
  int code = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

fs::path scratch() {
  fs::path d = fs::temp_directory_path() / ("bisect_cli_outputs_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

// bisect-mesh with `args`, its output in files; in the child the file size limit is `fsize`
// bytes when > 0 (SIGXFSZ ignored, so that an oversized write fails with EFBIG, as on a quota).
Result run(const std::vector<std::string>& args, rlim_t fsize = 0) {
  const fs::path out = scratch() / "stdout", err = scratch() / "stderr";
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(o, 1);
    ::dup2(e, 2);
    if (fsize > 0) {
      ::signal(SIGXFSZ, SIG_IGN);
      const rlimit lim{fsize, fsize};
      ::setrlimit(RLIMIT_FSIZE, &lim);
    }
    std::vector<char*> argv{const_cast<char*>(BISECT_CLI)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(BISECT_CLI, argv.data());
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  Result r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

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
