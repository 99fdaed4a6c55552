// A progress callback polled from inside a long loop: the loop asks "cancelled?" thousands of
// times a second, the callback (a Python function, a GUI's Stop button) is called at most every
// 50 ms with the stage's current fraction. Stop takes effect within a pass of the optimisation
// or a face's grid, not at the end of the stage (at 2e5 elements the optimisation ran 2.8 s
// without a progress call).
#pragma once
#include <atomic>
#include <chrono>
#include <functional>
#include <thread>

namespace bisect::util {

class ProgressPoll {
 public:
  explicit ProgressPoll(const std::function<bool(double)>& progress) : progress_(progress) {}
  // The fraction reported from now on (the stage's start, say).
  void at(double fraction) { fraction_ = fraction; }
  // Calls progress now; true when it asked to cancel (it stays so).
  bool report(double fraction) {
    fraction_ = fraction;
    last_ = Clock::now();
    if (progress_ && !stop_ && !progress_(fraction)) stop_ = true;
    return stop_;
  }
  // true when cancelled: calls progress when 50 ms have passed since the last call.
  bool cancelled() {
    if (!progress_ || stop_) return stop_;
    if (Clock::now() - last_ < std::chrono::milliseconds(50)) return false;
    return report(fraction_);
  }

 private:
  using Clock = std::chrono::steady_clock;
  const std::function<bool(double)>& progress_;
  double fraction_ = 0;
  Clock::time_point last_ = Clock::now();
  bool stop_ = false;
};

// The same for jobs on several threads (util::ordered_parallel) whose callback must run on the
// calling thread: there cancelled() asks the callback (at most every 50 ms); on the other threads
// it reads the flag that answer set. idle() is ordered_parallel's idle: the calling thread, while
// it waits for a job done elsewhere, keeps asking.
class ParallelPoll {
 public:
  explicit ParallelPoll(const std::function<bool(double)>& progress) : poll_(progress), caller_(std::this_thread::get_id()) {}
  void at(double fraction) { poll_.at(fraction); }  // on the calling thread
  bool cancelled() {
    if (std::this_thread::get_id() == caller_ && poll_.cancelled()) stop_.store(true);
    return stop_.load();
  }
  void idle() {
    if (poll_.cancelled()) stop_.store(true);
  }
  std::function<bool()> hook() {
    return [this] { return cancelled(); };
  }

 private:
  ProgressPoll poll_;
  const std::thread::id caller_;
  std::atomic<bool> stop_{false};
};

}  // namespace bisect::util
