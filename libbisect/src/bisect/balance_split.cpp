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
  // A cell is halved while it holds more than the share; the limit itself is never met exactly
  // (the share is no power of two's fraction), so ">=" in the loop is ">" here.
  const double limit = std::max(kBalanceMinElements, kBalanceShare * volume * density);
  halve_cells_while(m, opt, st, "balance_split", limit, kSlenderMinThickness, [](const CellExtents&) { return true; });
}

}  // namespace bisect
