// Thesis 7.2 operation (3), the last step: after a face is inserted into a region, find whether
// the region now falls apart. Each face side facing into the region is joined to the face side
// across the same wedge at every edge; the connected groups of face sides are the new regions. A
// cut face whose two sides stay in one group is a double-occurring face (6.7).
#pragma once
#include <vector>

#include "bisect/polyhedral_model.hpp"

namespace bisect {

// Reassigns the faces of region r to r and new regions; returns them all (r first).
std::vector<Index> split_region_by_connectivity(PolyhedralModel& m, Index r);

}  // namespace bisect
