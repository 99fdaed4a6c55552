#include "bisect/balance_split.hpp"

#include <cmath>
#include <deque>
#include <vector>

#include "bisect/cell_halving.hpp"
#include "bisect/slender_split.hpp"

namespace bisect {

void split_large_cells(PolyhedralModel& m, const DecomposeOptions& opt, DecomposeStats& st) {
  if (!opt.balance_cells) return;
  double volume = 0;
  const double density = nominal_density(m, opt, &volume);
  if (!(density > 0)) return;
  const double limit = std::max(kBalanceMinElements, kBalanceShare * volume * density);
  const double spacing = std::cbrt(8 / density);
  std::deque<Index> work;
  for (std::size_t r = 0; r < m.regions.size(); ++r)
    if (m.regions[r].alive) work.push_back(static_cast<Index>(r));
  std::vector<Index> halves;
  while (!work.empty()) {
    const Index r = work.front();
    work.pop_front();
    if (!m.regions[r].alive || !(m.region_volume(r) * density > limit)) continue;
    const CellExtents e = principal_extents(m, r);
    if (e.shortest() < kSlenderMinThickness * spacing) continue;
    halves.clear();
    if (!halve_cell(m, r, e, opt, halves)) continue;
    ++st.bisections["balance_split"];
    work.insert(work.end(), halves.begin(), halves.end());
  }
}

}  // namespace bisect
