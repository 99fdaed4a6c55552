#include "nodes/polytope.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "bisect/polyhedral_model.hpp"

namespace bisect::nodes {

Vec3 Polytope::face_centre(std::size_t f) const {
  Vec3 c = Vec3::Zero();
  for (int k : faces[f]) c += v[k];
  return c / static_cast<double>(faces[f].size());
}

double Polytope::face_area(std::size_t f) const {
  const auto& l = faces[f];
  Vec3 s = Vec3::Zero();
  for (std::size_t k = 0; k < l.size(); ++k) s += v[l[k]].cross(v[l[(k + 1) % l.size()]]);
  return 0.5 * std::abs(s.dot(normal[f]));
}

double Polytope::area() const {
  double a = 0;
  for (std::size_t f = 0; f < faces.size(); ++f) a += face_area(f);
  return a;
}

double Polytope::volume() const {
  if (faces.empty()) return 0;
  const Vec3 o = v.empty() ? Vec3::Zero() : v[0];
  double vol = 0;
  for (std::size_t f = 0; f < faces.size(); ++f) vol += face_area(f) * (normal[f].dot(face_centre(f) - o)) / 3;
  return vol;
}

Vec3 Polytope::centroid() const {
  // tetrahedra from an inside point (the mean corner) to each face's fan
  Vec3 m = Vec3::Zero();
  for (const Vec3& q : v) m += q / static_cast<double>(v.size());
  Vec3 c = Vec3::Zero();
  double total = 0;
  for (const auto& l : faces)
    for (std::size_t k = 1; k + 1 < l.size(); ++k) {
      const Vec3 &a = v[l[0]], &b = v[l[k]], &d = v[l[k + 1]];
      const double w = std::abs((a - m).dot((b - m).cross(d - m)));
      c += w * (m + a + b + d) / 4;
      total += w;
    }
  return total > 0 ? Vec3(c / total) : m;
}

Polytope clip(const Polytope& p, const Vec3& n, double d, double scale) {
  const double eps = 1e-12 * scale;
  std::vector<double> s(p.v.size());
  bool any_out = false, any_in = false;
  for (std::size_t i = 0; i < p.v.size(); ++i) {
    s[i] = n.dot(p.v[i]) - d;
    (s[i] > eps ? any_out : any_in) = true;
  }
  if (!any_out) return p;
  Polytope out;
  if (!any_in) return out;
  std::vector<int> id(p.v.size(), -1);
  std::vector<int> on_plane;
  for (std::size_t i = 0; i < p.v.size(); ++i)
    if (s[i] <= eps) {
      id[i] = static_cast<int>(out.v.size());
      out.v.push_back(p.v[i]);
      if (s[i] >= -eps) on_plane.push_back(id[i]);
    }
  std::map<std::pair<int, int>, int> cut;
  auto cut_point = [&](int a, int b) {
    auto key = std::minmax(a, b);
    auto it = cut.find(key);
    if (it != cut.end()) return it->second;
    const double t = s[a] / (s[a] - s[b]);
    out.v.push_back(p.v[a] + (p.v[b] - p.v[a]) * t);
    const int k = static_cast<int>(out.v.size() - 1);
    on_plane.push_back(k);
    cut.emplace(key, k);
    return k;
  };
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    const auto& l = p.faces[f];
    std::vector<int> nl;
    for (std::size_t k = 0; k < l.size(); ++k) {
      const int a = l[k], b = l[(k + 1) % l.size()];
      const bool ia = s[a] <= eps, ib = s[b] <= eps;
      if (ia) nl.push_back(id[a]);
      if (ia != ib && std::abs(s[a]) > eps && std::abs(s[b]) > eps) nl.push_back(cut_point(a, b));
    }
    if (nl.size() < 3) continue;
    out.faces.push_back(std::move(nl));
    out.normal.push_back(p.normal[f]);
    out.offset.push_back(p.offset[f]);
  }
  // the cap: the points on the plane, in order round their centre
  std::sort(on_plane.begin(), on_plane.end());
  on_plane.erase(std::unique(on_plane.begin(), on_plane.end()), on_plane.end());
  if (on_plane.size() >= 3) {
    Vec3 c = Vec3::Zero();
    for (int k : on_plane) c += out.v[k] / static_cast<double>(on_plane.size());
    const PlaneFrame frame(n, c);
    std::sort(on_plane.begin(), on_plane.end(), [&](int a, int b) {
      const Vec2 pa = frame.to2d(out.v[a]), pb = frame.to2d(out.v[b]);
      return std::atan2(pa.y(), pa.x()) < std::atan2(pb.y(), pb.x());
    });
    std::vector<int> cap;
    for (int k : on_plane)
      if (cap.empty() || (out.v[k] - out.v[cap.back()]).norm() > eps) cap.push_back(k);
    if (cap.size() >= 3) {
      out.faces.push_back(cap);
      out.normal.push_back(n);
      out.offset.push_back(d);
    }
  }
  return out;
}

}  // namespace bisect::nodes
