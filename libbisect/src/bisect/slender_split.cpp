#include "bisect/slender_split.hpp"

#include <cmath>
#include <deque>
#include <vector>

#include "bisect/cell_halving.hpp"

namespace bisect {

void split_slender_cells(PolyhedralModel& m, const DecomposeOptions& opt, DecomposeStats& st) {
  std::deque<Index> work;
  for (std::size_t r = 0; r < m.regions.size(); ++r)
    if (m.regions[r].alive) work.push_back(static_cast<Index>(r));
  const double density = nominal_density(m, opt);
  if (!(density > 0)) return;
  const double spacing = std::cbrt(8 / density);  // the nominal spacing: 8 V / s^3 elements
  std::vector<Index> halves;
  while (!work.empty()) {
    const Index r = work.front();
    work.pop_front();
    if (!m.regions[r].alive || m.region_volume(r) * density < kSlenderMinElements) continue;
    const CellExtents e = principal_extents(m, r);
    const double shortest = e.shortest();
    if (!(e.length(e.longest()) > kSlenderAspect * shortest) || shortest < kSlenderMinThickness * spacing) continue;
    halves.clear();
    if (!halve_cell(m, r, e, opt, halves)) continue;
    ++st.bisections["slender_split"];
    work.insert(work.end(), halves.begin(), halves.end());
  }
}

}  // namespace bisect
