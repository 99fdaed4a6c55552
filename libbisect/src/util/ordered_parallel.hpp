// Independent jobs on several threads with their results taken up in order: the face grids
// (one job per face) and the cell fillings (one per convex cell) are independent of each
// other, but the nodes and tetrahedra they make are numbered in face and cell order. So `work`
// runs anywhere, and `commit` runs on the calling thread in index order, as soon as the jobs
// before it are in: the output is the same for every thread count.
//
// The calling thread works too. An exception from work(i) reaches the caller when i's turn to
// be committed comes (so the error reported is the first in order, whatever the timing); an
// exception from commit (a cancellation from a progress callback, say) stops the other
// threads after their current job and then propagates. Nothing runs after the call returns.
// While the calling thread waits for a job in progress elsewhere, it calls idle() every 50 ms
// (when given): a progress callback that must run on the calling thread keeps being asked, and
// can tell the jobs to stop (through the jobs' own flag), while one long job holds the order.
#pragma once
#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace bisect::util {

// The number of threads `requested` means: itself when positive, else the machine's cores.
inline int thread_count(int requested) {
  if (requested > 0) return requested;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

// work(i) for every i in [0, n), taken in the order of `sequence` (a permutation of 0..n-1,
// e.g. the largest jobs first; empty: 0..n-1); commit(i) for i = 0..n-1 on this thread.
template <class Work, class Commit>
void ordered_parallel(std::size_t n, int threads, Work&& work, Commit&& commit, const std::vector<std::size_t>& sequence = {},
                      const std::function<void()>& idle = {}) {
  auto job = [&](std::size_t k) { return sequence.empty() ? k : sequence[k]; };
  if (threads <= 1 || n <= 1) {
    std::vector<char> ready(n, 0);
    for (std::size_t k = 0, next = 0; k < n; ++k) {
      work(job(k));
      ready[job(k)] = 1;
      while (next < n && ready[next]) commit(next++);
    }
    return;
  }
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<char> ready(n, 0);
  std::vector<std::exception_ptr> failed(n);
  std::atomic<std::size_t> taken{0};
  std::atomic<bool> stop{false};
  // one job, if any is left; false when none is
  auto run_one = [&]() {
    const std::size_t k = taken.fetch_add(1);
    if (k >= n || stop.load()) return false;
    const std::size_t i = job(k);
    try {
      work(i);
    } catch (...) {
      failed[i] = std::current_exception();
    }
    {
      std::lock_guard<std::mutex> lock(mutex);
      ready[i] = 1;
    }
    changed.notify_all();
    return true;
  };
  std::vector<std::thread> pool;
  struct Joiner {  // the helpers are joined on every way out, exceptions included
    std::vector<std::thread>& pool;
    std::atomic<bool>& stop;
    ~Joiner() {
      stop.store(true);
      for (std::thread& t : pool) t.join();
    }
  } joiner{pool, stop};
  const int helpers = static_cast<int>(std::min<std::size_t>(n, static_cast<std::size_t>(threads))) - 1;
  for (int h = 0; h < helpers; ++h)
    pool.emplace_back([&] {
      while (run_one()) {
      }
    });
  for (std::size_t next = 0; next < n;) {
    bool is_ready;
    {
      std::lock_guard<std::mutex> lock(mutex);
      is_ready = ready[next] != 0;
    }
    if (is_ready) {
      if (failed[next]) std::rethrow_exception(failed[next]);
      try {
        commit(next++);
      } catch (...) {
        stop.store(true);  // at once: no helper starts another job while the error unwinds
        throw;
      }
      continue;
    }
    if (run_one()) continue;  // help while the next one in order is being made
    std::unique_lock<std::mutex> lock(mutex);
    if (!idle) {
      changed.wait(lock, [&] { return ready[next] != 0; });
      continue;
    }
    if (!changed.wait_for(lock, std::chrono::milliseconds(50), [&] { return ready[next] != 0; })) {
      lock.unlock();
      try {
        idle();
      } catch (...) {
        stop.store(true);
        throw;
      }
    }
  }
}

}  // namespace bisect::util
