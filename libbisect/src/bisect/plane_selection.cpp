#include "bisect/plane_selection.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace bisect {

namespace {

// An angle wrapped into (-pi, pi].
double wrapped(double a) {
  a = std::remainder(a, 2 * M_PI);
  return a <= -M_PI ? a + 2 * M_PI : a;
}

// The planes through the edge and a region node within max_dev of the bisector's angle `mid`
// (a plane through the edge holds both directions u and -u about it), nearest first, at most two,
// at least half a degree apart.
std::vector<double> vertex_angles(const PolyhedralModel& m, const ReflexEdge& e, const EdgeFrame& fr, double mid,
                                  double max_dev, const std::vector<Index>& nodes) {
  const Vec3& pa = m.nodes[e.a];
  const double len = (m.nodes[e.b] - pa).norm();
  std::vector<std::pair<double, double>> found;  // (|deviation|, angle)
  for (Index v : nodes) {
    if (v == e.a || v == e.b) continue;
    Vec3 w = m.nodes[v] - pa;
    w -= fr.d * fr.d.dot(w);
    if (w.norm() < 1e-6 * len) continue;  // on the edge's line
    const double phi = fr.angle_of(w);
    for (double alt : {phi, phi + M_PI}) {
      const double dev = wrapped(alt - mid);
      if (std::abs(dev) < max_dev && std::abs(dev) > 1e-9) found.push_back({std::abs(dev), mid + dev});
    }
  }
  std::sort(found.begin(), found.end());
  std::vector<double> out;
  for (const auto& [dev, ang] : found) {
    bool near = false;
    for (double o : out) near |= std::abs(wrapped(o - ang)) < 0.5 * M_PI / 180.0;
    if (!near) out.push_back(ang);
    if (out.size() == 2) break;
  }
  return out;
}

}  // namespace

bool bisector_first(const PolyhedralModel& m, const ReflexEdge& e, const std::vector<char>& curved_faces) {
  if (e.wedge.angle - M_PI >= kFlatEdge) return false;
  auto curved = [&](Index f) {
    const Index s = m.faces[f].source;
    return s >= 0 && static_cast<std::size_t>(s) < curved_faces.size() && curved_faces[s];
  };
  return curved(e.wedge.face0) || curved(e.wedge.face1);
}

std::vector<CutPlane> candidate_planes(const PolyhedralModel& m, const ReflexEdge& e, int max_planes,
                                       const std::vector<Index>& region_nodes, const std::vector<char>& curved_faces) {
  const EdgeFrame fr(m.nodes[e.a], m.nodes[e.b]);
  const double theta = e.wedge.angle;
  // Half-plane directions at angle alpha from face0 in [theta - pi, pi] keep the other half of
  // the plane outside the region (or along a face), and split the wedge into two angles <= pi.
  const double lo = theta - M_PI, width = 2 * M_PI - theta;
  const bool flat = bisector_first(m, e, curved_faces);
  static const double kSharp[] = {0.0, 1.0, 0.5, 0.25, 0.75, 0.125, 0.875};
  static const double kFlat[] = {0.5, -1.0, 0.25, 0.75, 0.0, 1.0, 0.125, 0.875};  // -1: through vertices
  const double min_gap = 10.0 * M_PI / 180.0;
  std::vector<double> taken;
  std::vector<CutPlane> out;
  int counted = 0;  // the wedge's own planes, at most max_planes
  auto plane_at = [&](double angle) {
    const Vec3 n = fr.d.cross(fr.direction(angle)).normalized();
    return CutPlane{n, n.dot(m.nodes[e.a])};
  };
  const double* order = flat ? kFlat : kSharp;
  const std::size_t n_order = flat ? std::size(kFlat) : std::size(kSharp);
  for (std::size_t k = 0; k < n_order; ++k) {
    const double f = order[k];
    if (counted >= max_planes) break;
    if (f < 0) {  // beside the bisector, through a node it nearly met (not counted in max_planes)
      for (double ang : vertex_angles(m, e, fr, e.wedge.start + lo + 0.5 * width, width / 8, region_nodes))
        out.push_back(plane_at(ang));
      continue;
    }
    bool clash = false;
    for (double g : taken) clash |= std::abs(f - g) * width < min_gap;
    if (clash) continue;
    taken.push_back(f);
    ++counted;
    // fraction 0: the plane holds face1 (alpha = theta - pi); 1: it holds face0 (alpha = pi)
    const Index along = f == 0.0 ? e.wedge.face1 : (f == 1.0 ? e.wedge.face0 : -1);
    if (along >= 0) {  // exactly the face's own plane, so its nodes are exactly on it
      const ModelFace& F = m.faces[along];
      out.push_back({F.normal, F.offset});
      continue;
    }
    out.push_back(plane_at(e.wedge.start + lo + f * width));
  }
  return out;
}

}  // namespace bisect
