#include "optimize/optimize_mesh.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "bisect/errors.hpp"
#include "optimize/inverted_refill.hpp"
#include "optimize/mean_shape.hpp"
#include "optimize/min_max_passes.hpp"
#include "optimize/node_stars.hpp"
#include "optimize/sliver_repair.hpp"
#include "optimize/surface_angles.hpp"
#include "util/progress_poll.hpp"

namespace bisect::optimize {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Times the passes and the sliver repair may run again round what the repair left.
constexpr int kRepairCycles = 2;

// Rounds of the surface angles' moves (surface_angles.hpp).
constexpr int kSurfaceRounds = 2;

// The slivers among `ids` (any order, repeats and dead ones allowed): the live tetrahedra with a
// dihedral angle under kSliverBelowDeg, in id order, and the cosine of the smallest angle among
// them (1 for a flat one, 2 for one inside out; -1 when there are none). Among every tetrahedron
// under the repair's key, that is every sliver; among those and what changed since, every one
// again, without a look at the whole mesh (a twentieth of a second at 10^6, each time).
struct Slivers {
  std::vector<Index> tets;
  double worst = -1;
  Slivers(const tet::TetComplex& cx, const std::vector<Vec3>& X, std::vector<Index> ids) {
    const double limit = std::cos(kSliverBelowDeg * 3.14159265358979323846 / 180);
    for (Index t : below_key(cx, std::move(ids), sliver_key(kSliverBelowDeg))) {
      const tet::Tet& u = cx.tet[t];
      const double c = worst_dihedral_cos(X[u[0]], X[u[1]], X[u[2]], X[u[3]]);
      if (c <= limit) continue;
      tets.push_back(t);
      worst = std::max(worst, c);
    }
  }
  // fewer and none worse, or none more and the worst better
  bool better_than(const Slivers& o) const {
    return (tets.size() < o.tets.size() && worst <= o.worst) || (tets.size() <= o.tets.size() && worst < o.worst);
  }
  // with the tetrahedra at their nodes
  std::vector<Index> around(const tet::TetComplex& cx) const {
    std::vector<Index> out;
    for (Index t : tets)
      for (Index v : cx.tet[t]) {
        const std::vector<Index> s = star(cx, v, t);
        out.insert(out.end(), s.begin(), s.end());
      }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }
};

// Both entries. With `filled`, cx (empty) is built here from it, after the passes in blocks when
// it is large enough to cut; without, cx comes built. Passes not made in blocks run here, on this
// thread, over the whole mesh.
OptimizeCounts optimise(tet::TetComplex& cx, FilledMesh* filled, std::vector<Vec3>& X, const std::vector<char>& fixed,
                        const OptimizeOptions& opt, const std::function<bool(double)>& progress, int threads) {
  OptimizeCounts n;
  FaceSlides slides;
  if (filled) slides = std::move(filled->slides);
  const bool trades = filled && filled->surface_trades;
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
  // the fraction of the bar at each step, roughly as the time goes: the passes three quarters
  // (in blocks: the blocks to kBlocksEnd, then the complex's build), the refill and the sliver
  // repair an eighth, the mean shape an eighth
  constexpr double kBlocksEnd = 0.6, kPassesEnd = 0.75, kMeanStart = 0.875;
  const auto at = [&](double fraction) {
    if (progress && poll.report(fraction)) throw Cancelled();
  };
  int step = 0;
  const auto next_step = [&] { at(kPassesEnd * step++ / (2.0 * passes)); };
  at(0);
  BlockPassCounts blocks;
  if (filled) {
    auto t0 = Clock::now();
    if (passes > 0) {
      BlockOptions bo;
      bo.passes = opt.passes, bo.smooth_passes = opt.smooth_passes;
      bo.boundary_flips = opt.boundary_flips;
      bo.edge_removal_below = cx.edge_removal_below;
      bo.threads = threads;
      std::function<bool(double)> block_progress;
      if (progress) block_progress = [&](double x) {
        poll.at(kBlocksEnd * x);
        return !poll.cancelled();
      };
      blocks = block_pass(filled->tets, filled->tags, X, fixed, filled->held, filled->surface_tag, bo, block_progress);
      n.flips += blocks.flips;
      n.blocks = static_cast<std::int64_t>(blocks.blocks);
    }
    n.times.blocks = seconds_since(t0);
    t0 = Clock::now();
    if (blocks.blocks > 0) at(kBlocksEnd);
    cx.build(std::move(filled->tets), std::move(filled->tags), threads);
    cx.constrain(filled->held, threads);
    cx.surface_tag = std::move(filled->surface_tag);
    cx.boundary_flips = opt.boundary_flips;
    n.times.build = seconds_since(t0);
  }
  if (blocks.blocks > 0) {
    // the passes were made in blocks but where the walls of all three grids meet: from there
    std::vector<Index> from;
    for (std::size_t t = 0; t < cx.tet.size(); ++t)
      for (Index v : cx.tet[t])
        if (blocks.held_throughout[v]) {
          from.push_back(static_cast<Index>(t));
          break;
        }
    const PassCounts pc = min_max_passes(cx, X, fixed, opt.passes, opt.smooth_passes, &from);
    n.flips += pc.flips;
    n.times.flips = pc.flip_seconds, n.times.smooth = pc.smooth_seconds;
  } else {
    const PassCounts pc = min_max_passes(cx, X, fixed, opt.passes, opt.smooth_passes, nullptr, next_step);
    n.flips += pc.flips;
    n.times.flips = pc.flip_seconds, n.times.smooth = pc.smooth_seconds;
  }
  // every change (the refill's, the repair's, the mean shape's) goes on the caller's log, if any
  std::vector<Index> changed;
  std::vector<Index>* const outer_log = cx.changed;
  cx.changed = &changed;
  at(kPassesEnd);
  auto t0 = Clock::now();
  // a fold the passes left (a proxy cell's, inverted_refill.hpp) is cut out and filled again
  // before the sliver repair, which then sees what the refill made
  const RefillCounts refill = refill_inverted(cx, X, fixed);
  n.refilled_folds = static_cast<std::int64_t>(refill.refilled);
  n.folds_left = static_cast<std::int64_t>(refill.remaining);
  n.times.refill = seconds_since(t0);
  t0 = Clock::now();
  // no sliver repair over a fold: its Delaunay insertions take the tetrahedra as not
  // overlapping, and over one they broke the complex (FreeCAD's constraint_tie at 6,044, order
  // 2, first proxy: "a replacement does not fill the space it replaces"); the mesh is refused
  // anyway, by the caller, naming the fold's place. It starts from every tetrahedron under its
  // key (the only ones that can have a dihedral angle under kSliverBelowDeg).
  if (opt.sliver_rounds > 0 && n.folds_left == 0) {
    n.sliver_moves = static_cast<std::int64_t>(
        repair_slivers(cx, X, fixed, kSliverBelowDeg, opt.sliver_rounds, all_below_key(cx, sliver_key(kSliverBelowDeg))));
    // What the rounds left (a cluster of slivers where a cell's nodes lie near spheres, a flat
    // tetrahedron across the edge of two faces): the passes round it, which change where the
    // repair starts from, and the repair again. Its rounds are chaotic there (lug at 10^6 was
    // left with 0 to 34 tetrahedra under 10 degrees by the grid the passes' blocks were cut by),
    // and a second go can also make things worse (Angled.step at 10^5: 2.4 to 0.4 degrees), so
    // a go that does not leave fewer or better slivers is undone.
    Slivers left(cx, X, all_below_key(cx, sliver_key(kSliverBelowDeg)));
    for (int again = 0; again < kRepairCycles && !left.tets.empty(); ++again) {
      const std::vector<Vec3> X0 = X;
      const std::size_t logged = changed.size();
      const auto now = [&] {  // the slivers left and what changed since the go began
        std::vector<Index> ids = left.tets;
        ids.insert(ids.end(), changed.begin() + static_cast<std::ptrdiff_t>(logged), changed.end());
        return Slivers(cx, X, std::move(ids));
      };
      std::vector<tet::TetComplex::Replacement> journal;
      struct Journal {  // kept for this go alone, on every way out (Stop included)
        tet::TetComplex& cx;
        ~Journal() { cx.journal = nullptr; }
      } journal_on{cx};
      cx.journal = &journal;
      std::vector<char> held = fixed;
      held.resize(X.size(), 0);  // nodes the repair inserted are free (past the end of `fixed`)
      const std::vector<Index> around = left.around(cx);
      const PassCounts pc = min_max_passes(cx, X, held, opt.passes, opt.smooth_passes, &around);
      const std::size_t moves = repair_slivers(cx, X, held, kSliverBelowDeg, opt.sliver_rounds, now().around(cx));
      cx.journal = nullptr;
      Slivers after = now();
      if (after.better_than(left)) {
        n.flips += pc.flips;
        n.sliver_moves += static_cast<std::int64_t>(moves);
        left = std::move(after);
        continue;
      }
      std::copy(X0.begin(), X0.end(), X.begin());
      cx.undo(journal);
      X.resize(X0.size());
      std::vector<Index> moved;  // the keys of what the go moved, at the old places again
      for (std::size_t i = logged; i < changed.size(); ++i)
        if (cx.alive[changed[i]]) moved.push_back(changed[i]);
      cx.moved(moved);
      break;
    }
  }
  n.times.slivers = seconds_since(t0);
  t0 = Clock::now();
  // the mean shape last: its changes keep what the repair won (mean_shape.hpp), whereas with
  // the repair after them it worked from a different start and left more slivers (plate-hole
  // at 10^5: 179 tetrahedra under 10 degrees for 8)
  at(kMeanStart);
  if (opt.mean_rounds > 0 && n.folds_left == 0) {
    const MeanCounts mean = improve_mean(cx, X, fixed, opt.mean_rounds, threads, opt.face_moves ? slides : FaceSlides{});
    n.mean_changes = mean.flips + mean.moves;
  }
  // the boundary triangles' smallest angles last: the mean shape's face moves only keep them
  if (opt.face_moves && n.folds_left == 0) n.surface_moves = improve_surface_angles(cx, X, fixed, slides, kSurfaceRounds, trades);
  n.times.mean = seconds_since(t0);
  if (outer_log) outer_log->insert(outer_log->end(), changed.begin(), changed.end());
  cx.changed = outer_log;
  return n;
}

}  // namespace

OptimizeCounts optimize_mesh(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed, const OptimizeOptions& opt,
                             const std::function<bool(double)>& progress) {
  return optimise(cx, nullptr, X, fixed, opt, progress, 1);
}

OptimizeCounts optimize_filled(tet::TetComplex& cx, FilledMesh filled, std::vector<Vec3>& X, const std::vector<char>& fixed,
                               const OptimizeOptions& opt, const std::function<bool(double)>& progress, int threads) {
  return optimise(cx, &filled, X, fixed, opt, progress, threads);
}

}  // namespace bisect::optimize
