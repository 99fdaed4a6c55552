// ordered_parallel: jobs anywhere, results taken up in index order on the calling thread, the
// first failure in order reported, a cancelled commit stopping the rest.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "util/ordered_parallel.hpp"

namespace bisect::util {
namespace {

// Job i sleeps a little, longer for small i, so that later jobs finish first.
void busy(std::size_t i, std::size_t n) { std::this_thread::sleep_for(std::chrono::microseconds(50 * (n - i))); }

TEST(OrderedParallel, CommitsInIndexOrderOnTheCallingThread) {
  const std::thread::id caller = std::this_thread::get_id();
  for (int threads : {1, 2, 4, 8}) {
    const std::size_t n = 40;
    std::vector<int> result(n, -1);
    std::vector<std::size_t> committed;
    std::atomic<int> off_caller{0};
    ordered_parallel(
        n, threads,
        [&](std::size_t i) {
          busy(i, n);
          if (std::this_thread::get_id() != caller) ++off_caller;
          result[i] = static_cast<int>(i * i);
        },
        [&](std::size_t i) {
          EXPECT_EQ(std::this_thread::get_id(), caller);
          EXPECT_EQ(result[i], static_cast<int>(i * i));  // its job is done before its commit
          committed.push_back(i);
        });
    ASSERT_EQ(committed.size(), n) << threads;
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(committed[i], i) << threads;
    if (threads == 1) EXPECT_EQ(off_caller.load(), 0);
    else EXPECT_GT(off_caller.load(), 0) << threads;  // the helpers did work
  }
}

TEST(OrderedParallel, TakesJobsInTheGivenSequence) {
  const std::vector<std::size_t> sequence{3, 1, 0, 2};
  std::vector<std::size_t> started, committed;
  ordered_parallel(
      4, 1, [&](std::size_t i) { started.push_back(i); }, [&](std::size_t i) { committed.push_back(i); }, sequence);
  EXPECT_EQ(started, sequence);
  EXPECT_EQ(committed, (std::vector<std::size_t>{0, 1, 2, 3}));
}

TEST(OrderedParallel, ReportsTheFirstFailureInOrder) {
  for (int threads : {1, 2, 4}) {
    const std::size_t n = 30;
    std::vector<std::size_t> committed;
    try {
      ordered_parallel(
          n, threads,
          [&](std::size_t i) {
            busy(i, n);
            if (i == 7 || i == 20) throw std::runtime_error("job " + std::to_string(i));
          },
          [&](std::size_t i) { committed.push_back(i); });
      ADD_FAILURE() << "no exception, threads " << threads;
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "job 7") << threads;
    }
    EXPECT_EQ(committed.size(), 7u) << threads;  // 0..6, nothing after the failure
  }
}

TEST(OrderedParallel, AFailingCommitStopsTheOtherJobs) {
  for (int threads : {1, 2, 4}) {
    const std::size_t n = 200;
    std::atomic<int> ran{0}, after{0};
    std::atomic<bool> failed{false};
    EXPECT_THROW(ordered_parallel(
                     n, threads,
                     [&](std::size_t) {
                       ++ran;
                       if (failed.load()) ++after;
                       std::this_thread::sleep_for(std::chrono::microseconds(200));
                     },
                     [&](std::size_t i) {
                       if (i == 2) {
                         failed.store(true);
                         throw std::runtime_error("cancelled");
                       }
                     }),
                 std::runtime_error);
    // the jobs under way when it failed finish, and no new one starts: at most one job per
    // thread may have begun between the failure and the stop (a generous bound, as a loaded
    // machine may pause the committing thread there), far below the 200 there are. How many
    // ran before the failure depends on the scheduler, not on the code: not asserted.
    EXPECT_LE(after.load(), 2 * threads) << threads;
    EXPECT_LT(ran.load(), static_cast<int>(n)) << threads;
  }
}

TEST(OrderedParallel, ThreadCountOfZeroIsOnePerCore) {
  EXPECT_EQ(thread_count(3), 3);
  EXPECT_GE(thread_count(0), 1);
  EXPECT_EQ(thread_count(0), std::max(1, static_cast<int>(std::thread::hardware_concurrency())));
}

}  // namespace
}  // namespace bisect::util

namespace bisect::util {
namespace {

TEST(OrderedParallel, IdleAsksWhileTheNextJobRunsElsewhere) {
  // the first job a helper thread takes runs until idle has been called three times (or 5 s);
  // the calling thread, done with its own jobs, waits for it and calls idle meanwhile
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> idles{0};
  std::atomic<bool> claimed{false};
  std::vector<std::size_t> committed;
  ordered_parallel(
      8, 2,
      [&](std::size_t) {
        if (std::this_thread::get_id() != caller && !claimed.exchange(true)) {
          const auto start = std::chrono::steady_clock::now();
          while (idles.load() < 3 && std::chrono::steady_clock::now() - start < std::chrono::seconds(5))
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        } else {
          std::this_thread::sleep_for(std::chrono::milliseconds(10));  // the helper surely gets a job
        }
      },
      [&](std::size_t i) { committed.push_back(i); }, {}, [&] { ++idles; });
  ASSERT_TRUE(claimed.load());
  EXPECT_GE(idles.load(), 3);
  EXPECT_EQ(committed, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6, 7}));
}

TEST(OrderedParallel, AnIdleThatThrowsStopsTheRun) {
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<bool> claimed{false}, thrown{false};
  EXPECT_THROW(ordered_parallel(
                   8, 2,
                   [&](std::size_t) {
                     if (std::this_thread::get_id() != caller && !claimed.exchange(true)) {
                       const auto start = std::chrono::steady_clock::now();
                       while (!thrown.load() && std::chrono::steady_clock::now() - start < std::chrono::seconds(5))
                         std::this_thread::sleep_for(std::chrono::milliseconds(5));
                     } else {
                       std::this_thread::sleep_for(std::chrono::milliseconds(10));
                     }
                   },
                   [](std::size_t) {}, {},
                   [&] {
                     thrown.store(true);
                     throw std::runtime_error("stop");
                   }),
               std::runtime_error);
  EXPECT_TRUE(thrown.load());
}

}  // namespace
}  // namespace bisect::util
