// Convex cells halved for the threads (issue 18's "big cells split"; the thesis's own tool, one
// more bisection). The cells fill in parallel, the largest first, so the fill ends no sooner than
// its largest cell: part.stl's decomposition leaves one cell with 55% of the volume, and at 10^6
// elements two threads filled it in 1.7 times one thread's time instead of 2.
#pragma once
#include "bisect/polyhedral_model.hpp"

namespace bisect {

// A cell is halved across its length (cell_halving) while it holds, by volume, more than
// kBalanceShare of the job's elements and at least kBalanceMinElements, and is at least
// kSlenderMinThickness nominal spacings thick (a thin wall's cut faces only add constraints).
// The share is fixed, never the thread count's, so that the mesh is the same for every thread
// count; a sixth leaves work for six threads, and is no power of two's fraction, so that the
// halves of a box (a half, a quarter, an eighth of it) never sit on the limit, where rounding
// would decide. Counted in st.bisections["balance_split"].
inline constexpr double kBalanceShare = 1.0 / 6;
inline constexpr double kBalanceMinElements = 20000;

void split_large_cells(PolyhedralModel& m, const DecomposeOptions& opt, DecomposeStats& st);

}  // namespace bisect
