#include "mesh2d/tri_adjacency.hpp"

#include <map>

namespace bisect::mesh2d {

TriAcross triangle_neighbours(const TriMesh2& m) {
  TriAcross nb(m.tris.size());
  std::map<std::pair<Index, Index>, std::pair<int, int>> open;  // directed edge a -> b of a triangle
  for (std::size_t t = 0; t < m.tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      nb[t][k] = {-1, -1};
      const Index a = m.tris[t][(k + 1) % 3], b = m.tris[t][(k + 2) % 3];
      auto it = open.find({b, a});
      if (it != open.end()) {
        nb[t][k] = it->second;
        nb[it->second.first][it->second.second] = {static_cast<int>(t), k};
        open.erase(it);
      } else {
        open[{a, b}] = {static_cast<int>(t), k};
      }
    }
  return nb;
}

}  // namespace bisect::mesh2d
