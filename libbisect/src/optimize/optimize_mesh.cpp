#include "optimize/optimize_mesh.hpp"

#include <algorithm>
#include <limits>

#include "optimize/sliver_repair.hpp"
#include "optimize/smooth.hpp"

namespace bisect::optimize {

OptimizeCounts optimize_mesh(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed, const OptimizeOptions& opt) {
  OptimizeCounts n;
  for (int pass = 0; pass < std::max(opt.passes, opt.smooth_passes); ++pass) {
    if (pass < opt.passes) n.flips += cx.improve_all(std::numeric_limits<std::int64_t>::max());
    if (pass < opt.smooth_passes) {
      smooth_interior(X, cx.tets(), fixed, 1);
      cx.refresh_quality();
    }
  }
  if (opt.sliver_rounds > 0) n.sliver_moves = static_cast<std::int64_t>(repair_slivers(cx, X, fixed, kSliverBelowDeg, opt.sliver_rounds));
  return n;
}

}  // namespace bisect::optimize
