#include "bisect/region_split.hpp"

#include <algorithm>
#include <cmath>
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

// Winding number of the surface made of the given face sides about p: the sum of the signed
// solid angles of its faces' fan triangles (Van Oosterom and Strackee), over 4 pi.
double winding_number(const PolyhedralModel& m, const std::vector<Index>& codes, const Vec3& p) {
  double total = 0;
  for (Index code : codes) {
    const ModelFace& f = m.faces[code / 2];
    const double sign = code % 2 == 1 ? 1.0 : -1.0;  // outward along the normal on side 1
    for (const auto& loop : f.loops)
      for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
        const Vec3 a = m.nodes[loop[0]] - p, b = m.nodes[loop[i]] - p, c = m.nodes[loop[i + 1]] - p;
        const double la = a.norm(), lb = b.norm(), lc = c.norm();
        const double num = a.dot(b.cross(c));
        const double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
        total += sign * 2 * std::atan2(num, den);
      }
  }
  return total / (4 * M_PI);
}

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
  // Connected groups of face sides, each with its enclosed volume: an inner shell (a cavity's or
  // a sub-domain's surface that no cut reached) encloses a negative volume and is no region of
  // its own; it goes to the group whose surface holds it.
  std::unordered_map<int, int> group_of_root;
  std::vector<std::vector<Index>> groups;  // codes face * 2 + side
  std::vector<double> volume;
  for (std::size_t k = 0; k < F.size(); ++k) {
    const int s = m.side_of(F[k], r);
    for (int side = 0; side < 2; ++side) {
      if (s != 2 && s != side) continue;
      const int root = uf.find(2 * static_cast<int>(k) + side);
      auto it = group_of_root.find(root);
      if (it == group_of_root.end()) {
        it = group_of_root.emplace(root, static_cast<int>(groups.size())).first;
        groups.emplace_back();
        volume.push_back(0);
      }
      groups[it->second].push_back(F[k] * 2 + side);
      // side 1: the region lies behind the normal, which points out of it
      volume[it->second] += (side == 1 ? 1 : -1) * m.faces[F[k]].offset * m.face_area(F[k]) / 3;
    }
  }
  std::vector<int> solid;
  for (std::size_t g = 0; g < groups.size(); ++g)
    if (volume[g] > 0) solid.push_back(static_cast<int>(g));
  for (std::size_t g = 0; g < groups.size() && !solid.empty(); ++g) {
    if (volume[g] > 0) continue;
    int host = solid.size() == 1 ? solid[0] : -1;
    if (host < 0) {
      const Vec3 p = m.nodes[m.faces[groups[g][0] / 2].loops[0][0]];
      for (int h : solid)
        if (std::abs(winding_number(m, groups[h], p)) > 0.5 && (host < 0 || volume[h] < volume[host])) host = h;
    }
    if (host < 0) continue;
    groups[host].insert(groups[host].end(), groups[g].begin(), groups[g].end());
    groups[g].clear();
  }
  std::vector<Index> out;
  const Index source = m.regions[r].source;
  std::vector<std::vector<Index>> lists;
  for (auto& g : groups) {
    if (g.empty()) continue;
    Index reg = r;
    if (!out.empty()) {
      reg = static_cast<Index>(m.regions.size());
      ModelRegion nr;
      nr.source = source;
      m.regions.push_back(nr);
    }
    out.push_back(reg);
    std::sort(g.begin(), g.end());
    lists.push_back(std::move(g));
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
