#include "bisect/edge_wedges.hpp"

#include <algorithm>
#include <cmath>

namespace bisect {

RegionEdges region_edges(const PolyhedralModel& m, Index r) {
  RegionEdges edges;
  for (Index f : m.live_faces(r))
    for (const auto& loop : m.faces[f].loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Index a = loop[i], b = loop[(i + 1) % loop.size()];
        edges[edge_key(a, b)].push_back({f, a < b ? 1 : -1});
      }
  return edges;
}

EdgeFrame::EdgeFrame(const Vec3& pa, const Vec3& pb) : d((pb - pa).normalized()) {
  const Vec3 t = std::abs(d.x()) < 0.6 ? Vec3::UnitX() : (std::abs(d.y()) < 0.6 ? Vec3::UnitY() : Vec3::UnitZ());
  e1 = (t - t.dot(d) * d).normalized();
  e2 = d.cross(e1);
}

double EdgeFrame::angle_of(const Vec3& w) const {
  double a = std::atan2(w.dot(e2), w.dot(e1));
  return a < 0 ? a + 2 * M_PI : a;
}

Vec3 EdgeFrame::direction(double angle) const { return std::cos(angle) * e1 + std::sin(angle) * e2; }

std::vector<Wedge> interior_wedges(const PolyhedralModel& m, Index r, Index a, Index b, const std::vector<FaceUse>& uses) {
  const EdgeFrame fr(m.nodes[a], m.nodes[b]);
  struct Around { double angle; Index face; int inc_side; };
  std::vector<Around> around;
  for (const FaceUse& u : uses) {
    const ModelFace& F = m.faces[u.face];
    // The face lies left of its loop: from the edge it extends along normal x loop direction.
    const Vec3 w = static_cast<double>(u.dir) * F.normal.cross(fr.d);
    // n · (d x w) = dir: the +normal side faces increasing angle when the loop runs a -> b.
    around.push_back({fr.angle_of(w), u.face, u.dir > 0 ? 0 : 1});
  }
  std::sort(around.begin(), around.end(), [](const Around& x, const Around& y) { return x.angle < y.angle; });
  std::vector<Wedge> out;
  const std::size_t n = around.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Around& p = around[i];
    const Around& q = around[(i + 1) % n];
    const int s0 = p.inc_side, s1 = 1 - q.inc_side;
    const int side0 = m.side_of(p.face, r), side1 = m.side_of(q.face, r);
    const bool in0 = side0 == 2 || side0 == s0, in1 = side1 == 2 || side1 == s1;
    if (!in0 || !in1) continue;
    double open = q.angle - p.angle;
    if (i + 1 == n) open += 2 * M_PI;
    out.push_back({p.face, q.face, s0, s1, p.angle, open});
  }
  return out;
}

}  // namespace bisect
