#include "domain/merge_facets.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <unordered_map>

#include "geom/predicates.hpp"

namespace bisect {
namespace {

std::size_t find(std::vector<std::size_t>& parent, std::size_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

Vec3 normal_of(const PolyInput& in, const std::vector<Index>& loop) {  // Newell
  Vec3 n = Vec3::Zero();
  for (std::size_t k = 0; k < loop.size(); ++k) n += in.nodes[loop[k]].cross(in.nodes[loop[(k + 1) % loop.size()]]);
  return n;
}

}  // namespace

PolyInput merge_coplanar_triangles(const PolyInput& in, std::size_t* merged_faces) {
  const std::size_t nf = in.faces.size();
  std::vector<char> has_hole(nf, 0);
  for (const PolyFace& f : in.faces)
    if (f.hole_of >= 0) has_hole[f.hole_of] = 1;
  auto triangle = [&](std::size_t f) { return in.faces[f].nodes.size() == 3 && in.faces[f].hole_of < 0 && !has_hole[f]; };
  // the regions of each face, to merge only faces between the same regions
  std::vector<std::vector<Index>> regions_of(nf);
  for (std::size_t r = 0; r < in.regions.size(); ++r)
    for (Index f : in.regions[r].faces) regions_of[f].push_back(static_cast<Index>(r));
  for (auto& r : regions_of) std::sort(r.begin(), r.end());
  // every face's edges
  std::map<std::pair<Index, Index>, std::vector<std::size_t>> edge_faces;
  for (std::size_t f = 0; f < nf; ++f) {
    const auto& l = in.faces[f].nodes;
    for (std::size_t k = 0; k < l.size(); ++k) edge_faces[std::minmax(l[k], l[(k + 1) % l.size()])].push_back(f);
  }
  std::vector<std::size_t> parent(nf);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& [e, faces] : edge_faces) {
    if (faces.size() != 2 || !triangle(faces[0]) || !triangle(faces[1]) || regions_of[faces[0]] != regions_of[faces[1]]) continue;
    const auto &a = in.faces[faces[0]].nodes, &b = in.faces[faces[1]].nodes;
    Index apex = -1;  // b's node off the shared edge
    for (Index v : b)
      if (v != e.first && v != e.second) apex = v;
    if (geom::orient3d(in.nodes[a[0]], in.nodes[a[1]], in.nodes[a[2]], in.nodes[apex]) != 0) continue;
    if (normal_of(in, a).dot(normal_of(in, b)) <= 0) continue;  // facing opposite ways, or folded
    parent[find(parent, faces[0])] = find(parent, faces[1]);
  }
  std::map<std::size_t, std::vector<std::size_t>> groups;
  for (std::size_t f = 0; f < nf; ++f) groups[find(parent, f)].push_back(f);

  PolyInput out;
  out.nodes = in.nodes;
  out.required_elements = in.required_elements;
  out.source = in.source;
  out.node_spacing = in.node_spacing;
  std::vector<std::vector<Index>> new_faces_of(nf);  // old face -> the new faces standing for it
  std::vector<Index> old_to_new(nf, -1);
  std::size_t merged = 0;
  for (const auto& [root, members] : groups) {
    std::vector<std::vector<Index>> loops;
    bool ok = members.size() > 1;
    if (ok) {
      // the patch's boundary: directed edges whose reverse is not in the patch, chained
      std::map<std::pair<Index, Index>, int> directed;
      for (std::size_t f : members) {
        const auto& l = in.faces[f].nodes;
        for (std::size_t k = 0; k < l.size(); ++k) ++directed[{l[k], l[(k + 1) % l.size()]}];
      }
      std::unordered_map<Index, Index> next;
      for (const auto& [d, n] : directed) {
        if (directed.count({d.second, d.first})) continue;
        if (n != 1 || !next.emplace(d.first, d.second).second) ok = false;  // the boundary touches itself
      }
      while (ok && !next.empty()) {
        std::vector<Index> loop{next.begin()->first};
        for (;;) {
          auto it = next.find(loop.back());
          if (it == next.end()) {
            ok = false;
            break;
          }
          const Index to = it->second;
          next.erase(it);
          if (to == loop.front()) break;
          loop.push_back(to);
        }
        loops.push_back(std::move(loop));
      }
    }
    if (ok) {  // one outer loop (facing as the triangles do), the others holes
      const Vec3 n = normal_of(in, in.faces[members.front()].nodes);
      std::size_t outer = loops.size(), outers = 0;
      for (std::size_t k = 0; k < loops.size(); ++k)
        if (normal_of(in, loops[k]).dot(n) > 0) outer = k, ++outers;
      ok = outers == 1;
      if (ok) {
        const Index id = static_cast<Index>(out.faces.size());
        out.faces.push_back({loops[outer], -1});
        std::vector<Index> ids{id};
        for (std::size_t k = 0; k < loops.size(); ++k)
          if (k != outer) {
            ids.push_back(static_cast<Index>(out.faces.size()));
            out.faces.push_back({loops[k], id});
          }
        for (std::size_t f : members) new_faces_of[f] = ids;
        new_faces_of[members.front()] = ids;
        ++merged;
        continue;
      }
    }
    for (std::size_t f : members) {
      new_faces_of[f] = {static_cast<Index>(out.faces.size())};
      out.faces.push_back(in.faces[f]);
      old_to_new[f] = new_faces_of[f][0];
    }
  }
  // hole links of faces kept as they were
  for (std::size_t f = 0; f < nf; ++f)
    if (old_to_new[f] >= 0 && in.faces[f].hole_of >= 0) out.faces[old_to_new[f]].hole_of = old_to_new[in.faces[f].hole_of];
  std::vector<std::size_t> listed(out.faces.size(), 0);  // region number + 1 that listed it last
  for (std::size_t r = 0; r < in.regions.size(); ++r) {
    PolyRegion nr;
    nr.cavity = in.regions[r].cavity;
    for (Index f : in.regions[r].faces)
      for (Index g : new_faces_of[f])
        if (listed[g] != r + 1) {
          listed[g] = r + 1;
          nr.faces.push_back(g);
        }
    out.regions.push_back(std::move(nr));
  }
  if (merged_faces) *merged_faces = merged;
  return out;
}

}  // namespace bisect
