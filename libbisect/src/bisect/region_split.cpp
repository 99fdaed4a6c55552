#include "bisect/region_split.hpp"

#include <numeric>
#include <unordered_map>

#include "bisect/edge_wedges.hpp"

namespace bisect {
namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

}  // namespace

std::vector<Index> split_region_by_connectivity(PolyhedralModel& m, Index r) {
  const std::vector<Index> F = m.live_faces(r);
  std::unordered_map<Index, int> slot;
  for (std::size_t k = 0; k < F.size(); ++k) slot[F[k]] = static_cast<int>(k);
  auto id = [&](Index f, int side) { return 2 * slot.at(f) + side; };
  UnionFind uf(2 * F.size());
  const RegionEdges edges = region_edges(m, r);
  for (const auto& [key, uses] : edges) {
    std::vector<int> sides;
    for (const FaceUse& u : uses) {
      const int s = m.side_of(u.face, r);
      if (s == 2) sides.push_back(id(u.face, 0)), sides.push_back(id(u.face, 1));
      else sides.push_back(id(u.face, s));
    }
    if (sides.size() == 2) {
      uf.unite(sides[0], sides[1]);
      continue;
    }
    for (const Wedge& w : interior_wedges(m, r, key_lo(key), key_hi(key), uses)) uf.unite(id(w.face0, w.side0), id(w.face1, w.side1));
  }
  std::unordered_map<int, Index> region_of_root;
  std::vector<Index> out;
  const Index source = m.regions[r].source;
  std::vector<std::vector<Index>> lists;
  for (std::size_t k = 0; k < F.size(); ++k) {
    const int s = m.side_of(F[k], r);
    for (int side = 0; side < 2; ++side) {
      if (s != 2 && s != side) continue;
      const int root = uf.find(2 * static_cast<int>(k) + side);
      auto it = region_of_root.find(root);
      if (it == region_of_root.end()) {
        Index reg = r;
        if (!out.empty()) {
          reg = static_cast<Index>(m.regions.size());
          ModelRegion nr;
          nr.source = source;
          m.regions.push_back(nr);
        }
        out.push_back(reg);
        lists.emplace_back();
        it = region_of_root.emplace(root, reg).first;
      }
      // record; sides are rewritten after all lookups (side_of reads the old assignment)
      lists[std::find(out.begin(), out.end(), it->second) - out.begin()].push_back(F[k] * 2 + side);
    }
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    std::vector<Index> faces;
    for (Index code : lists[i]) {
      const Index f = code / 2;
      (code % 2 == 0 ? m.faces[f].front : m.faces[f].back) = out[i];
      if (faces.empty() || faces.back() != f) faces.push_back(f);
    }
    m.regions[out[i]].faces = std::move(faces);
  }
  return out;
}

}  // namespace bisect
