// The passes of the global improvement (thesis 6.9.2): the local min-max transformations of 7.5
// in turn with Laplace smoothing, each opening moves for the other. The first pass covers every
// face and free node of what it is given; the later ones work from the tetrahedra whose key
// (tet_angle_key) is below kWorkBelowKey among those the earlier passes listed or changed. The
// whole mesh's optimisation runs them (optimize_mesh.hpp), and so does each block of the
// parallel pass (block_pass.hpp).
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "tet/tet_complex.hpp"

namespace bisect::optimize {

// smallest solid angle under 0.30 sr. Lower is cheaper: at 0.10 the mean alpha fell by 0.6%
// (lug.stl, 10^5), at 0.12 by 0.05%; at 0.15 it held (lug, flange).
inline constexpr double kWorkBelowKey = 0.15;

struct PassCounts {
  std::int64_t flips = 0, moves = 0;
  double flip_seconds = 0, smooth_seconds = 0;
};

// `passes` transformation passes and `smooth_passes` smoothing passes (in turn, transformations
// first). from: the first pass starts at these tetrahedra (their faces, their free nodes, and for
// the smoothing what the transformations made), or at every tetrahedron when null. step() is
// called before each transformation and each smoothing pass (progress). fixed[v]: v never moves.
PassCounts min_max_passes(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed, int passes, int smooth_passes,
                          const std::vector<Index>* from, const std::function<void()>& step = {});

}  // namespace bisect::optimize
