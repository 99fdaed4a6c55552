#include "optimize/optimize_mesh.hpp"

#include <algorithm>
#include <chrono>
#include <limits>

#include "bisect/errors.hpp"
#include "optimize/inverted_refill.hpp"
#include "optimize/mean_shape.hpp"
#include "optimize/node_stars.hpp"
#include "optimize/sliver_repair.hpp"
#include "optimize/smooth.hpp"
#include "util/progress_poll.hpp"

namespace bisect::optimize {

namespace {

// The first pass of transformations and smoothing goes over the whole mesh; the later ones work
// from the tetrahedra whose key (tet_angle_key) is below this (smallest solid angle under 0.30
// sr) and from what their changes make. Lower is cheaper: at 0.10 the mean alpha fell by 0.6%
// (lug.stl, 10^5), at 0.12 by 0.05%; at 0.15 it held (lug, flange).
constexpr double kWorkBelowKey = 0.15;

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

OptimizeCounts optimize_mesh(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed, const OptimizeOptions& opt,
                             const std::function<bool(double)>& progress) {
  OptimizeCounts n;
  // Stop within a pass: the loops poll cx.cancelled, which calls progress now and then
  util::ProgressPoll poll(progress);
  const std::function<bool()> outer_cancelled = cx.cancelled;
  struct Restore {  // the complex outlives this call: its hook is put back on every way out
    tet::TetComplex& cx;
    const std::function<bool()>& outer;
    ~Restore() { cx.cancelled = outer; }
  } restore{cx, outer_cancelled};
  if (progress) cx.cancelled = [&poll] { return poll.cancelled(); };
  const int passes = std::max(opt.passes, opt.smooth_passes);
  const double steps = 2.0 * passes + 2;
  double step = 0;
  const auto next_step = [&] {
    if (progress && poll.report(step / steps)) throw Cancelled();
    ++step;
  };
  const double sliver_below = sliver_key(kSliverBelowDeg);
  // every change (flip, node move, insertion) goes on a log, from which the lists follow
  std::vector<Index> changed;
  std::vector<Index>* const outer_log = cx.changed;
  cx.changed = &changed;
  // once `listed`: every tetrahedron under kWorkBelowKey, and every one under the sliver
  // repair's key (the only ones that can have a dihedral angle under kSliverBelowDeg)
  std::vector<Index> poor, sliver_list;
  bool listed = false;
  const auto relist = [&] {
    if (!listed) {  // once, after the first pass: one look at each stored key
      poor = all_below_key(cx, kWorkBelowKey);
      sliver_list = all_below_key(cx, sliver_below);
      listed = true;
    } else {  // the lists and what changed since
      poor.insert(poor.end(), changed.begin(), changed.end());
      poor = below_key(cx, std::move(poor), kWorkBelowKey);
      sliver_list.insert(sliver_list.end(), changed.begin(), changed.end());
      sliver_list = below_key(cx, std::move(sliver_list), sliver_below);
    }
    changed.clear();
  };
  for (int pass = 0; pass < passes; ++pass) {
    next_step();
    auto t0 = Clock::now();
    if (pass < opt.passes) {
      if (pass == 0) {
        n.flips += cx.improve_all(std::numeric_limits<std::int64_t>::max());
      } else {  // from the faces of the poor tetrahedra, and on from every tetrahedron made
        relist();
        n.flips += cx.improve_around(poor);
      }
    }
    n.times.flips += seconds_since(t0);
    next_step();
    t0 = Clock::now();
    if (pass < opt.smooth_passes) {
      if (pass == 0) {
        std::vector<Index> all;
        all.reserve(cx.live_count());
        for (std::size_t t = 0; t < cx.tet.size(); ++t)
          if (cx.alive[t]) all.push_back(static_cast<Index>(t));
        smooth_nodes(cx, X, fixed, all);
      } else {  // the free nodes of the poor tetrahedra
        relist();
        smooth_nodes(cx, X, fixed, poor);
      }
    }
    n.times.smooth += seconds_since(t0);
  }
  next_step();
  auto t0 = Clock::now();
  // a fold the passes left (a proxy cell's, inverted_refill.hpp) is cut out and filled again
  // before the sliver repair, which then sees what the refill made
  const RefillCounts refill = refill_inverted(cx, X, fixed);
  n.refilled_folds = static_cast<std::int64_t>(refill.refilled);
  n.folds_left = static_cast<std::int64_t>(refill.remaining);
  relist();
  n.times.refill = seconds_since(t0);
  t0 = Clock::now();
  // no sliver repair over a fold: its Delaunay insertions take the tetrahedra as not
  // overlapping, and over one they broke the complex (FreeCAD's constraint_tie at 6,044, order
  // 2, first proxy: "a replacement does not fill the space it replaces"); the mesh is refused
  // anyway, by the caller, naming the fold's place
  if (opt.sliver_rounds > 0 && n.folds_left == 0)
    n.sliver_moves = static_cast<std::int64_t>(repair_slivers(cx, X, fixed, kSliverBelowDeg, opt.sliver_rounds, std::move(sliver_list)));
  n.times.slivers = seconds_since(t0);
  t0 = Clock::now();
  // the mean shape last: its changes keep what the repair won (mean_shape.hpp), whereas with
  // the repair after them it worked from a different start and left more slivers (plate-hole
  // at 10^5: 179 tetrahedra under 10 degrees for 8)
  next_step();
  if (opt.mean_rounds > 0 && n.folds_left == 0) {
    const MeanCounts mean = improve_mean(cx, X, fixed, opt.mean_rounds);
    n.mean_changes = mean.flips + mean.moves;
  }
  n.times.mean = seconds_since(t0);
  if (outer_log) outer_log->insert(outer_log->end(), changed.begin(), changed.end());
  cx.changed = outer_log;
  return n;
}

}  // namespace bisect::optimize
