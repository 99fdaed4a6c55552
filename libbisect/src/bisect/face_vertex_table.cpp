#include "bisect/face_vertex_table.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "bisect/edge_wedges.hpp"

namespace bisect {

double FaceVertexTable::edge_angle(Index e) const {
  const FaceVertex& fv = entries[e];
  if (!std::isnan(fv.angle)) return fv.angle;
  // another entry of the same edge holds it: walk around the edge
  for (Index probe = fv.adj_ccw; probe >= 0 && probe != e; probe = entries[probe].adj_ccw)
    if (!std::isnan(entries[probe].angle)) return entries[probe].angle;
  return std::numeric_limits<double>::quiet_NaN();
}

FaceVertexTable build_face_vertex_table(const PolyhedralModel& m, Index r) {
  FaceVertexTable t;
  t.region = r;
  // every live face of the model, so that an interface face finds its neighbours in both regions
  std::vector<Index> faces;
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    if (m.faces[f].alive) faces.push_back(static_cast<Index>(f));
  std::unordered_map<std::uint64_t, std::vector<Index>> by_edge;  // edge -> entries
  for (Index f : faces)
    for (int l = 0; l < static_cast<int>(m.faces[f].loops.size()); ++l) {
      const auto& loop = m.faces[f].loops[l];
      const Index first = static_cast<Index>(t.entries.size()), n = static_cast<Index>(loop.size());
      for (Index i = 0; i < n; ++i) {
        FaceVertex fv;
        fv.node = loop[i], fv.face = f, fv.loop = l;
        fv.succ = first + (i + 1) % n, fv.pred = first + (i + n - 1) % n;
        t.entries.push_back(fv);
        by_edge[edge_key(loop[i], loop[(i + 1) % n])].push_back(first + i);
      }
    }
  for (const auto& [key, es] : by_edge) {
    const Index a = key_lo(key), b = key_hi(key);
    const EdgeFrame fr(m.nodes[a], m.nodes[b]);
    // entries sorted by the angle of their face about the edge
    std::vector<std::pair<double, Index>> around;
    for (Index e : es) {
      const FaceVertex& fv = t.entries[e];
      const int dir = fv.node == a ? 1 : -1;
      around.push_back({fr.angle_of(static_cast<double>(dir) * m.faces[fv.face].normal.cross(fr.d)), e});
    }
    std::sort(around.begin(), around.end());
    const std::size_t n = around.size();
    for (std::size_t i = 0; n > 1 && i < n; ++i) {
      t.entries[around[i].second].adj_ccw = around[(i + 1) % n].second;
      t.entries[around[i].second].adj_cw = around[(i + n - 1) % n].second;
    }
    // the region's angle, stored in the entry with (J - I) * alpha > 0
    std::vector<FaceUse> uses;  // the region's faces at the edge
    for (Index e : es)
      if (m.side_of(t.entries[e].face, r) >= 0) uses.push_back({t.entries[e].face, t.entries[e].node == a ? 1 : -1});
    const std::vector<Wedge> wedges = interior_wedges(m, r, a, b, uses);
    if (wedges.empty()) continue;
    double angle = 0;
    for (const Wedge& w : wedges) angle = std::max(angle, w.angle);
    for (Index e : es) {
      const FaceVertex& fv = t.entries[e];
      const Index J = fv.node, I = t.entries[fv.succ].node;
      const int side = m.side_of(fv.face, r);
      if (side < 0) continue;
      const int alpha = side == 1 ? 1 : -1;  // side 1: the region is behind the normal
      if (static_cast<long long>(J - I) * alpha > 0) {
        t.entries[e].angle = angle;
        break;
      }
    }
  }
  return t;
}

}  // namespace bisect
