// bisect-mesh run as a user runs it, for the command-line tests: its exit code, standard output
// and standard error, through the shell (arguments as typed) or straight (argv, with a child
// set-up the shell cannot give: a file size limit, another user).
#pragma once
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace bisect::test {

namespace fs = std::filesystem;

struct CliResult {
  int code = -1;
  std::string out, err;
  double seconds = 0;  // wall time of the run
};

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A folder of this test process's own (`tag` tells the test files apart).
inline fs::path scratch_dir(const std::string& tag) {
  fs::path d = fs::temp_directory_path() / ("bisect_cli_" + tag + "_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

// The scratch folders go when the test process ends, unless a test failed: then they stay, for
// the one who looks into it (ctest runs each test in a process of its own).
class ScratchCleanup : public ::testing::Environment {
 public:
  void TearDown() override {
    if (::testing::UnitTest::GetInstance()->Failed()) return;
    const std::string mine = "_" + std::to_string(::getpid());
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(fs::temp_directory_path(), ec)) {
      const std::string name = e.path().filename().string();
      if (name.rfind("bisect_cli_", 0) == 0 && name.size() > mine.size() && name.compare(name.size() - mine.size(), mine.size(), mine) == 0)
        fs::remove_all(e.path(), ec);
    }
  }
};
inline ::testing::Environment* const kScratchCleanup = ::testing::AddGlobalTestEnvironment(new ScratchCleanup);

inline int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

inline bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// bisect-mesh with `args` as a shell reads them (quote paths), in scratch_dir(tag).
inline CliResult run_cli(const std::string& args, const std::string& tag) {
  const fs::path d = scratch_dir(tag);
  const std::string cmd = std::string("'") + BISECT_CLI + "' " + args + " >'" + (d / "out").string() + "' 2>'" +
                          (d / "err").string() + "'";
  const auto t0 = std::chrono::steady_clock::now();
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(d / "out");
  r.err = slurp(d / "err");
  return r;
}

// What the child does before it becomes bisect-mesh.
struct ChildSetup {
  rlim_t fsize = 0;   // > 0: the file size limit in bytes (SIGXFSZ ignored, so that an oversized
                      // write fails with EFBIG, as on a quota)
  uid_t as_user = 0;  // > 0 and this process root: become that user (root reads every file)
};

// bisect-mesh with `args` as its argv, no shell between, in scratch_dir(tag).
inline CliResult run_cli_argv(const std::vector<std::string>& args, const std::string& tag, const ChildSetup& setup = {}) {
  const fs::path out = scratch_dir(tag) / "stdout", err = scratch_dir(tag) / "stderr";
  fs::remove(out);
  fs::remove(err);
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (setup.as_user > 0 && ::geteuid() == 0 && (::setgid(setup.as_user) != 0 || ::setuid(setup.as_user) != 0)) ::_exit(126);
    const int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
    ::dup2(o, 1);
    ::dup2(e, 2);
    if (setup.fsize > 0) {
      ::signal(SIGXFSZ, SIG_IGN);
      const rlimit lim{setup.fsize, setup.fsize};
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
  CliResult r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

}  // namespace bisect::test
