#include "bisect/slender_split.hpp"

#include "bisect/cell_halving.hpp"

namespace bisect {

void split_slender_cells(PolyhedralModel& m, const DecomposeOptions& opt, DecomposeStats& st) {
  halve_cells_while(m, opt, st, "slender_split", kSlenderMinElements, kSlenderMinThickness,
                    [](const CellExtents& e) { return e.length(e.longest()) > kSlenderAspect * e.shortest(); });
}

}  // namespace bisect
