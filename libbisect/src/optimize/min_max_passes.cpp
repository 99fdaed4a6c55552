#include "optimize/min_max_passes.hpp"

#include <algorithm>
#include <chrono>
#include <limits>

#include "optimize/node_stars.hpp"
#include "optimize/smooth.hpp"

namespace bisect::optimize {

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
}  // namespace

PassCounts min_max_passes(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed, int passes, int smooth_passes,
                          const std::vector<Index>* from, const std::function<void()>& step) {
  PassCounts n;
  // every change (flip, node move) goes on a log, from which the lists follow; the caller's log,
  // if any, gets it all (as the lists take it, and the rest at the end)
  std::vector<Index> changed;
  std::vector<Index>* const outer_log = cx.changed;
  cx.changed = &changed;
  struct Restore {
    tet::TetComplex& cx;
    std::vector<Index>* outer;
    std::vector<Index>& changed;
    ~Restore() {
      if (outer) outer->insert(outer->end(), changed.begin(), changed.end());
      cx.changed = outer;
    }
  } restore{cx, outer_log, changed};
  std::vector<Index> poor;  // the work list of the passes after the first
  bool listed = false;
  const auto relist = [&] {
    if (!listed && !from) {  // once, after the first pass over everything: one look at each key
      poor = all_below_key(cx, kWorkBelowKey);
    } else {  // the list (at first: where the pass started) and what changed since
      if (!listed) poor = *from;
      poor.insert(poor.end(), changed.begin(), changed.end());
      poor = below_key(cx, std::move(poor), kWorkBelowKey);
    }
    listed = true;
    // the caller's log gets every change: what is cleared here too
    if (outer_log) outer_log->insert(outer_log->end(), changed.begin(), changed.end());
    changed.clear();
  };
  const int rounds = std::max(passes, smooth_passes);
  for (int pass = 0; pass < rounds; ++pass) {
    if (step) step();
    auto t0 = Clock::now();
    if (pass < passes) {
      if (pass > 0) {
        relist();
        n.flips += cx.improve_around(poor);
      } else if (from) {
        n.flips += cx.improve_around(*from);
      } else {
        n.flips += cx.improve_all(std::numeric_limits<std::int64_t>::max());
      }
    }
    n.flip_seconds += seconds_since(t0);
    if (step) step();
    t0 = Clock::now();
    if (pass < smooth_passes) {
      if (pass > 0) {
        relist();
        n.moves += static_cast<std::int64_t>(smooth_nodes(cx, X, fixed, poor));
      } else if (from) {  // where the pass started, and what its transformations made
        std::vector<Index> around = *from;
        around.insert(around.end(), changed.begin(), changed.end());
        std::sort(around.begin(), around.end());
        around.erase(std::unique(around.begin(), around.end()), around.end());
        n.moves += static_cast<std::int64_t>(smooth_nodes(cx, X, fixed, around));
      } else {
        std::vector<Index> all;
        all.reserve(cx.live_count());
        for (std::size_t t = 0; t < cx.tet.size(); ++t)
          if (cx.alive[t]) all.push_back(static_cast<Index>(t));
        n.moves += static_cast<std::int64_t>(smooth_nodes(cx, X, fixed, all));
      }
    }
    n.smooth_seconds += seconds_since(t0);
  }
  return n;
}

}  // namespace bisect::optimize
