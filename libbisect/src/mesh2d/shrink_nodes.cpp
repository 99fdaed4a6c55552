#include "mesh2d/shrink_nodes.hpp"

#include <algorithm>
#include <cmath>

namespace bisect::mesh2d {
namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

double area(const std::vector<Vec2>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) a += cross(p[i], p[(i + 1) % p.size()]);
  return 0.5 * a;
}

// Consecutive corners closer than `tiny` merged into one (the last one round too).
std::vector<Vec2> merge_close(const std::vector<Vec2>& p, double tiny) {
  std::vector<Vec2> out;
  for (const Vec2& q : p)
    if (out.empty() || (q - out.back()).norm() >= tiny) out.push_back(q);
  while (out.size() > 1 && (out.front() - out.back()).norm() < tiny) out.pop_back();
  return out;
}

// Cut corners sharper than 30 degrees, then merge corners closer than h / 2. A layer's clipping
// can leave two corners a rounding error apart, whose edge has no direction: they are one corner
// before any angle is measured (lug.stl at 10^6: such an edge measured a 5.9 degree corner on a
// convex layer, whose cut, nearly ten spacings in from it, took the whole layer away, and a
// bottom face 0.56 across got no node inside its first layer).
std::vector<Vec2> tidy(std::vector<Vec2> p, double h) {
  const double sharp = 30.0 * M_PI / 180.0;
  p = merge_close(p, 1e-9 * h);
  for (int guard = 0; guard < 8 && p.size() >= 3; ++guard) {
    bool cut = false;
    for (std::size_t i = 0; i < p.size() && !cut; ++i) {
      const Vec2 prev = p[(i + p.size() - 1) % p.size()], c = p[i], next = p[(i + 1) % p.size()];
      const Vec2 a = (prev - c).normalized(), b = (next - c).normalized();
      const double phi = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
      if (phi >= sharp || phi <= 0) continue;
      const Vec2 bis = (a + b).normalized();
      const double alpha = h / (2 * std::tan(phi / 2));
      // keep the side of the cut line (perpendicular to the bisector) away from the corner
      const Vec2 at = c + alpha * bis, dir(bis.y(), -bis.x());
      p = clip_left(p, at, dir);  // keeps the left of dir: the side the bisector points to
      cut = true;
    }
    if (!cut) break;
  }
  return merge_close(p, 0.5 * h);
}

}  // namespace

std::vector<Vec2> clip_left(const std::vector<Vec2>& polygon, const Vec2& p, const Vec2& d) {
  std::vector<Vec2> out;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a = polygon[i], &b = polygon[(i + 1) % n];
    const double sa = cross(d, a - p), sb = cross(d, b - p);
    if (sa >= 0) out.push_back(a);
    if ((sa >= 0) != (sb >= 0)) out.push_back(a + (b - a) * (sa / (sa - sb)));
  }
  return out;
}

std::vector<Vec2> shrink_nodes(const std::vector<Vec2>& polygon, double h, double element_area) {
  std::vector<Vec2> nodes;
  const std::size_t n = polygon.size();
  if (n < 3 || h <= 0) return nodes;
  for (int k = 1;; ++k) {
    std::vector<Vec2> layer = polygon;
    for (std::size_t i = 0; i < n && layer.size() >= 3; ++i) {
      const Vec2 a = polygon[i], b = polygon[(i + 1) % n], d = (b - a).normalized();
      const Vec2 inward(-d.y(), d.x());
      layer = clip_left(layer, a + k * h * inward, d);
    }
    // a layer thinner than h / 2 (width about 2 area / perimeter) would put its two long sides'
    // nodes that close together: its nodes go along its middle line instead (through the
    // centroid along the principal axis of its corners, clipped to it), and it is the last (before
    // tidying, whose merging of close corners would flatten it to one edge)
    double perimeter = 0;
    Vec2 centre = Vec2::Zero();
    for (std::size_t i = 0; i < layer.size(); ++i) {
      perimeter += (layer[(i + 1) % layer.size()] - layer[i]).norm();
      centre += layer[i] / static_cast<double>(layer.size());
    }
    if (layer.size() >= 3 && area(layer) > 1e-12 * h * h && 2 * area(layer) / perimeter < 0.5 * h) {
      double sxx = 0, sxy = 0, syy = 0;
      for (const Vec2& q : layer) sxx += (q - centre).x() * (q - centre).x(), sxy += (q - centre).x() * (q - centre).y(), syy += (q - centre).y() * (q - centre).y();
      const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);
      const Vec2 u(std::cos(angle), std::sin(angle));
      double t0 = -1e300, t1 = 1e300;  // the line centre + t u inside every edge's half-plane
      for (std::size_t i = 0; i < layer.size(); ++i) {
        const Vec2 a = layer[i], d = layer[(i + 1) % layer.size()] - a;
        const double side = cross(d, centre - a), rate = cross(d, u);  // left of the edge: inside
        if (std::abs(rate) < 1e-300) continue;
        const double t = -side / rate;
        if (rate > 0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
      }
      if (t1 < t0) t0 = t1 = 0;
      const int steps = static_cast<int>(std::lround((t1 - t0) / h));
      if (steps == 0) nodes.push_back(centre + 0.5 * (t0 + t1) * u);
      for (int s = 0; s <= steps && steps > 0; ++s) nodes.push_back(centre + (t0 + (t1 - t0) * s / steps) * u);
      break;
    }
    if (layer.size() >= 3 && area(layer) > 1e-12 * h * h) layer = tidy(layer, h);
    if (layer.size() < 3 || area(layer) <= 1e-12 * h * h) {
      // a point or a segment is left: one node in the middle when there is room for it
      if (!layer.empty()) {
        Vec2 c = Vec2::Zero();
        for (const Vec2& q : layer) c += q / static_cast<double>(layer.size());
        if (k > 1 || area(polygon) > 1.5 * (static_cast<double>(n) - 2) * element_area) nodes.push_back(c);
      } else if (k == 1 && area(polygon) > 1.5 * (static_cast<double>(n) - 2) * element_area) {
        Vec2 c = Vec2::Zero();
        for (const Vec2& q : polygon) c += q / static_cast<double>(n);
        nodes.push_back(c);
      }
      break;
    }
    // nodes round the layer at spacing h, corners included
    for (std::size_t i = 0; i < layer.size(); ++i) {
      const Vec2 a = layer[i], b = layer[(i + 1) % layer.size()];
      const int steps = std::max(1, static_cast<int>(std::lround((b - a).norm() / h)));
      for (int s = 0; s < steps; ++s) nodes.push_back(a + (b - a) * (static_cast<double>(s) / steps));
    }
  }
  return nodes;
}

}  // namespace bisect::mesh2d
