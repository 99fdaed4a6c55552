#include "bisect/balance_split.hpp"

#include <algorithm>

#include "bisect/cell_halving.hpp"
#include "bisect/slender_split.hpp"

namespace bisect {

void split_large_cells(PolyhedralModel& m, const DecomposeOptions& opt, DecomposeStats& st) {
  if (!opt.balance_cells) return;
  double volume = 0;
  const double density = nominal_density(m, opt, &volume);
  if (!(density > 0)) return;
  // The loop halves a cell holding at least the limit: at least kBalanceMinElements, as the
  // header says, and "more than the share" where the share is the larger, since the share is
  // no power of two's fraction and no cell's volume meets it exactly.
  const double limit = std::max(kBalanceMinElements, kBalanceShare * volume * density);
  halve_cells_while(m, opt, st, "balance_split", limit, kSlenderMinThickness, [](const CellExtents&) { return true; });
}

}  // namespace bisect
