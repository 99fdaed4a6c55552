// Paths that cannot be used get one line naming them (exit 2): a directory as input or output,
// a file that cannot be read. Before, a directory as input gave "internal error:
// basic_filebuf::underflow ... Is a directory" (exit 3).
#include <gtest/gtest.h>

#include "cli_run.hpp"

#include <fcntl.h>
#include <sys/stat.h>
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

fs::path scratch() {
  fs::path d = bisect::test::scratch_dir("paths");
  fs::permissions(d, fs::perms::all);  // the unprivileged child below writes its output here
  return d;
}

// bisect-mesh with `args`; when `as_user` > 0 and this process is root, the child first becomes
// that user (root reads every file, so "unreadable" needs someone else).
Result run(const std::vector<std::string>& args, uid_t as_user = 0) {
  scratch();
  bisect::test::ChildSetup setup;
  setup.as_user = as_user;
  return bisect::test::run_cli_argv(args, "paths", setup);
}

int lines(const std::string& s) { return bisect::test::count_lines(s); }

const std::string kCubes = std::string(BISECT_TEST_DATA) + "/cube-cavity-adjacent-cube.poly";

fs::path directory(const std::string& name) {
  const fs::path d = scratch() / name;
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST(CliPaths, ADirectoryAsInputIsOneLine) {
  // named like each kind of input, so that every reader (and the B-rep loader) is reached
  for (const char* name : {"in.poly", "in.stl", "in.off", "in.poly2", "in.brep", "in.step"}) {
    const fs::path dir = directory(name);
    const Result r = run({dir.string(), "-n", "300", "-o", (scratch() / "m.vtu").string()});
    EXPECT_EQ(r.code, 2) << name << ": " << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_TRUE(has(r.err, dir.string() + ": is a directory")) << r.err;
    EXPECT_FALSE(has(r.err, "internal error")) << r.err;
  }
  for (const char* name : {"in.poly", "in.stl"}) {
    const Result r = run({"info", directory(name).string()});
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_TRUE(has(r.err, directory(name).string() + ": is a directory")) << r.err;
  }
  for (const char* name : {"in.vtu", "in.msh", "in.inp"}) {
    const Result r = run({"quality", directory(name).string()});
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_TRUE(has(r.err, directory(name).string() + ": is a directory")) << r.err;
  }
  const Result r = run({kCubes, "--cells-only", "-o", (scratch() / "c.poly").string()});  // the control
  EXPECT_EQ(r.code, 0) << r.err;
}

TEST(CliPaths, ADirectoryAsOutputIsOneLine) {
  const fs::path vtu = directory("out.vtu"), poly = directory("out.poly"), json = directory("stats.json");
  std::vector<std::vector<std::string>> jobs = {
      {kCubes, "-n", "300", "-o", vtu.string()},
      {kCubes, "--cells-only", "-o", poly.string()},
      {kCubes, "--cells-only", "-o", (scratch() / "c.poly").string(), "--stats", json.string()},
      {std::string(BISECT_TEST_DATA) + "/square-subdomain-adjacent-square.poly2", "-n", "200", "-o", vtu.string()}};
  for (const auto& job : jobs) {
    const Result r = run(job);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_TRUE(has(r.err, ": is a directory")) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  EXPECT_TRUE(fs::is_directory(vtu));
  EXPECT_TRUE(fs::is_directory(json));
}

TEST(CliPaths, AnUnreadableInputSaysPermissionDenied) {
  const uid_t nobody = 65534;
  const fs::path secret = scratch() / "secret.poly";
  fs::copy_file(kCubes, secret, fs::copy_options::overwrite_existing);
  ::chmod(secret.c_str(), 0);
  const uid_t user = ::geteuid() == 0 ? nobody : 0;  // root reads anything: run as nobody
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"info", secret.string()},
        std::vector<std::string>{secret.string(), "-n", "300", "-o", (scratch() / "m.vtu").string()}}) {
    const Result r = run(args, user);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_TRUE(has(r.err, secret.string() + ": cannot be read: permission denied")) << r.err;
  }
  // the same file readable: the child can run and read here (so the refusal above is the mode's)
  ::chmod(secret.c_str(), 0644);
  const Result r = run({"info", secret.string()}, user);
  EXPECT_EQ(r.code, 0) << r.err;
}
