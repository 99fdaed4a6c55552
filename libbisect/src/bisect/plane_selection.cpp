#include "bisect/plane_selection.hpp"

#include <cmath>

namespace bisect {

std::vector<CutPlane> candidate_planes(const PolyhedralModel& m, const ReflexEdge& e, int max_planes) {
  const EdgeFrame fr(m.nodes[e.a], m.nodes[e.b]);
  const double theta = e.wedge.angle;
  // Half-plane directions at angle alpha from face0 in [theta - pi, pi] keep the other half of
  // the plane outside the region (or along a face), and split the wedge into two angles <= pi.
  const double lo = theta - M_PI, width = 2 * M_PI - theta;
  static const double kFractions[] = {0.0, 1.0, 0.5, 0.25, 0.75, 0.125, 0.875};
  const double min_gap = 10.0 * M_PI / 180.0;
  std::vector<double> taken;
  std::vector<CutPlane> out;
  for (double f : kFractions) {
    if (static_cast<int>(out.size()) >= max_planes) break;
    bool clash = false;
    for (double g : taken) clash |= std::abs(f - g) * width < min_gap;
    if (clash) continue;
    taken.push_back(f);
    // fraction 0: the plane holds face1 (alpha = theta - pi); 1: it holds face0 (alpha = pi)
    const Index along = f == 0.0 ? e.wedge.face1 : (f == 1.0 ? e.wedge.face0 : -1);
    if (along >= 0) {  // exactly the face's own plane, so its nodes are exactly on it
      const ModelFace& F = m.faces[along];
      out.push_back({F.normal, F.offset});
      continue;
    }
    const Vec3 u = fr.direction(e.wedge.start + lo + f * width);
    const Vec3 n = fr.d.cross(u).normalized();
    out.push_back({n, n.dot(m.nodes[e.a])});
  }
  return out;
}

}  // namespace bisect
