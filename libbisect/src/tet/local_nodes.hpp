// A fill's own nodes numbered locally: the cell fills (pipeline/cell_filling) and the fold refill
// (optimize/inverted_refill) work on a copy of the few nodes they need, not on the mesh's whole
// node list. The local ids follow the global ones in order, so that a fill on the copy is the
// one the global ids would give (the fills break ties by node id).
#pragma once
#include <algorithm>
#include <array>
#include <vector>

#include "bisect/types.hpp"

namespace bisect::tet {

struct LocalNodes {
  std::vector<Index> global;  // local id -> global id, increasing

  // The nodes of `boundary`'s triangles and `interior`, each once.
  LocalNodes(const std::vector<std::array<Index, 3>>& boundary, const std::vector<Index>& interior) {
    for (const auto& t : boundary) global.insert(global.end(), t.begin(), t.end());
    global.insert(global.end(), interior.begin(), interior.end());
    std::sort(global.begin(), global.end());
    global.erase(std::unique(global.begin(), global.end()), global.end());
  }

  Index local(Index v) const { return static_cast<Index>(std::lower_bound(global.begin(), global.end(), v) - global.begin()); }

  std::vector<std::array<Index, 3>> triangles(const std::vector<std::array<Index, 3>>& tris) const {
    std::vector<std::array<Index, 3>> out;
    out.reserve(tris.size());
    for (const auto& t : tris) out.push_back({local(t[0]), local(t[1]), local(t[2])});
    return out;
  }

  std::vector<Index> nodes(const std::vector<Index>& ids) const {
    std::vector<Index> out;
    out.reserve(ids.size());
    for (Index v : ids) out.push_back(local(v));
    return out;
  }

  // X's points of the local nodes, in local order (with room for a helper node the fill may add).
  std::vector<Vec3> points(const std::vector<Vec3>& X) const {
    std::vector<Vec3> out;
    out.reserve(global.size() + 1);
    for (Index v : global) out.push_back(X[v]);
    return out;
  }
};

}  // namespace bisect::tet
