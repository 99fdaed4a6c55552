// Stop inside the long loops (issue 19: Stop within 0.5 s at any stage): the optimisation calls
// its progress callback at every step and, through TetComplex::cancelled, every 50 ms within
// one; the cell fill polls the same hook between insertions. util::ProgressPoll spaces the calls.
#include <gtest/gtest.h>

#include <chrono>
#include <random>
#include <thread>
#include <vector>

#include "bisect/errors.hpp"
#include "optimize/optimize_mesh.hpp"
#include "tet/cell_fill.hpp"
#include "tet/tet_complex.hpp"
#include "util/progress_poll.hpp"

namespace bisect::optimize {
namespace {

// The unit cube around a jittered n x n x n grid of free nodes, Delaunay filled.
struct Cube {
  std::vector<Vec3> X;
  std::vector<char> fixed;
  std::vector<Index> inside;
  std::vector<std::array<Index, 3>> boundary{{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                             {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  explicit Cube(int n) {
    for (int i = 0; i < 8; ++i) X.push_back(Vec3(i & 1, i >> 1 & 1, i >> 2 & 1));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1);
    for (int i = 1; i <= n; ++i)
      for (int j = 1; j <= n; ++j)
        for (int k = 1; k <= n; ++k) {
          inside.push_back(static_cast<Index>(X.size()));
          X.push_back(Vec3((i + jitter(rng)) / (n + 1), (j + jitter(rng)) / (n + 1), (k + jitter(rng)) / (n + 1)));
        }
    fixed.assign(X.size(), 0);
    std::fill(fixed.begin(), fixed.begin() + 8, 1);
  }
};

TEST(Stop, OptimisationReportsEveryStepAndStopsWhenAsked) {
  Cube c(8);
  const std::vector<tet::Tet> tets = tet::fill_convex_cell(c.X, c.boundary, c.inside, Vec3(0.5, 0.5, 0.5), true);
  const Cube fresh = c;
  {
    tet::TetComplex cx(c.X);
    cx.build(tets);
    std::vector<double> seen;
    optimize_mesh(cx, c.X, c.fixed, OptimizeOptions{}, [&](double x) {
      seen.push_back(x);
      return true;
    });
    ASSERT_GE(seen.size(), 7u);  // 3 passes of flips and smoothing, then the sliver repair
    EXPECT_EQ(seen.front(), 0.0);
    for (std::size_t i = 1; i < seen.size(); ++i) EXPECT_GE(seen[i], seen[i - 1]);
    EXPECT_LT(seen.back(), 1.0);
    EXPECT_FALSE(cx.cancelled) << "the hook is put back as it was";
  }
  // the fill's tetrahedra on the fill's nodes (the run above moved c.X)
  std::vector<Vec3> X = fresh.X;
  tet::TetComplex cx(X);
  cx.build(tets);
  int calls = 0;
  EXPECT_THROW(optimize_mesh(cx, X, c.fixed, OptimizeOptions{}, [&](double) { return ++calls < 3; }), Cancelled);
  EXPECT_EQ(calls, 3);
  EXPECT_FALSE(cx.cancelled);
}

TEST(Stop, TheFlipQueueAndTheCellFillPollTheHook) {
  Cube c(14);  // 2,744 nodes: more insertions than one poll interval
  int asked = 0;
  EXPECT_THROW(tet::fill_convex_cell(c.X, c.boundary, c.inside, Vec3(0.5, 0.5, 0.5), false, nullptr,
                                     [&] {
                                       ++asked;
                                       return true;
                                     }),
               Cancelled);
  EXPECT_EQ(asked, 1);  // the first poll stops it
  Cube d(8);
  const std::vector<tet::Tet> tets = tet::fill_convex_cell(d.X, d.boundary, d.inside, Vec3(0.5, 0.5, 0.5), true);
  tet::TetComplex cx(d.X);
  cx.build(tets);
  cx.cancelled = [] { return true; };
  EXPECT_THROW(cx.improve_all(1 << 30), Cancelled);  // over 2,048 faces queued
}

TEST(Stop, ProgressPollCallsAtMostEvery50Milliseconds) {
  int calls = 0;
  const std::function<bool(double)> progress = [&](double) { return ++calls < 3; };
  util::ProgressPoll poll(progress);
  for (int i = 0; i < 100000; ++i) EXPECT_FALSE(poll.cancelled());  // well within 50 ms
  EXPECT_EQ(calls, 0);
  EXPECT_FALSE(poll.report(0.5));
  EXPECT_EQ(calls, 1);
  std::this_thread::sleep_for(std::chrono::milliseconds(60));
  EXPECT_FALSE(poll.cancelled());
  EXPECT_EQ(calls, 2);
  std::this_thread::sleep_for(std::chrono::milliseconds(60));
  EXPECT_TRUE(poll.cancelled());  // the third call says stop, and it stays so
  EXPECT_TRUE(poll.cancelled());
  EXPECT_EQ(calls, 3);
}

TEST(Stop, ParallelPollAsksOnlyOnTheCallingThread) {
  int calls = 0;
  const std::function<bool(double)> progress = [&](double) {
    ++calls;
    return false;
  };
  util::ParallelPoll poll(progress);
  bool elsewhere = true;
  std::this_thread::sleep_for(std::chrono::milliseconds(60));
  std::thread([&] { elsewhere = poll.cancelled(); }).join();
  EXPECT_FALSE(elsewhere);
  EXPECT_EQ(calls, 0);
  EXPECT_TRUE(poll.cancelled());  // here: asked, and the answer is stop
  EXPECT_EQ(calls, 1);
  std::thread([&] { elsewhere = poll.cancelled(); }).join();
  EXPECT_TRUE(elsewhere);  // the other threads read it
  EXPECT_EQ(calls, 1);
}

}  // namespace
}  // namespace bisect::optimize
