#include "fill/cell_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>

#include "bisect/polyhedral_model.hpp"
#include "mesh2d/shrink_nodes.hpp"

namespace bisect::fill {
namespace {

Vec3 face_centre(const Polytope& p, std::size_t f) {
  Vec3 c = Vec3::Zero();
  for (int k : p.faces[f]) c += p.v[k];
  return c / static_cast<double>(p.faces[f].size());
}

double face_area(const Polytope& p, std::size_t f) {
  const auto& l = p.faces[f];
  Vec3 s = Vec3::Zero();
  for (std::size_t k = 0; k < l.size(); ++k) s += p.v[l[k]].cross(p.v[l[(k + 1) % l.size()]]);
  return 0.5 * std::abs(s.dot(p.normal[f]));
}

// Points closer than `gap` to an earlier one are dropped (a hash grid of cell size gap).
std::vector<Vec3> merge_close(const std::vector<Vec3>& pts, double gap) {
  std::unordered_map<long long, std::vector<int>> grid;
  auto cell = [&](const Vec3& p, int dx, int dy, int dz) {
    const long long x = static_cast<long long>(std::floor(p.x() / gap)) + dx, y = static_cast<long long>(std::floor(p.y() / gap)) + dy,
                    z = static_cast<long long>(std::floor(p.z() / gap)) + dz;
    return (x * 73856093LL) ^ (y * 19349663LL) ^ (z * 83492791LL);
  };
  std::vector<Vec3> out;
  for (const Vec3& p : pts) {
    bool near = false;
    for (int dx = -1; dx <= 1 && !near; ++dx)
      for (int dy = -1; dy <= 1 && !near; ++dy)
        for (int dz = -1; dz <= 1 && !near; ++dz) {
          auto it = grid.find(cell(p, dx, dy, dz));
          if (it == grid.end()) continue;
          for (int q : it->second) near = near || (out[q] - p).norm() < gap;
        }
    if (near) continue;
    grid[cell(p, 0, 0, 0)].push_back(static_cast<int>(out.size()));
    out.push_back(p);
  }
  return out;
}

// Nodes on the surface of the layer: its edges at spacing np (each once), its faces' interiors
// by 2D shrinking; `shift` moves every node (the mid-sheet of a thin layer).
void surface_nodes(const Polytope& p, double np, const Vec3& shift, std::vector<Vec3>& out, const std::vector<std::size_t>& faces) {
  std::map<std::pair<int, int>, bool> done;
  for (std::size_t f : faces) {
    const auto& l = p.faces[f];
    for (std::size_t k = 0; k < l.size(); ++k) {
      const int a = l[k], b = l[(k + 1) % l.size()];
      out.push_back(p.v[a] + shift);
      if (!done.emplace(std::minmax(a, b), true).second) continue;
      const int steps = static_cast<int>(std::lround((p.v[b] - p.v[a]).norm() / np));
      for (int s = 1; s < steps; ++s) out.push_back(p.v[a] + (p.v[b] - p.v[a]) * (static_cast<double>(s) / steps) + shift);
    }
    const PlaneFrame frame(p.normal[f], p.v[l[0]]);
    std::vector<Vec2> poly;
    for (int k : l) poly.push_back(frame.to2d(p.v[k]));
    for (const Vec2& q : mesh2d::shrink_nodes(poly, np, std::sqrt(3.0) / 4 * np * np))
      out.push_back(frame.origin + q.x() * frame.e1 + q.y() * frame.e2 + shift);
  }
}

}  // namespace

double Polytope::area() const {
  double a = 0;
  for (std::size_t f = 0; f < faces.size(); ++f) a += face_area(*this, f);
  return a;
}

double Polytope::volume() const {
  if (faces.empty()) return 0;
  const Vec3 o = v.empty() ? Vec3::Zero() : v[0];
  double vol = 0;
  for (std::size_t f = 0; f < faces.size(); ++f) vol += face_area(*this, f) * (normal[f].dot(face_centre(*this, f) - o)) / 3;
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

std::vector<Vec3> shrink_cell_nodes(const Polytope& cell, double np) {
  std::vector<Vec3> nodes;
  double scale = 0;
  for (const Vec3& q : cell.v) scale = std::max(scale, q.cwiseAbs().maxCoeff());
  scale = std::max(scale, np);
  const double sharp = 30.0 * M_PI / 180.0;
  for (int k = 1;; ++k) {
    Polytope layer = cell;
    for (std::size_t f = 0; f < cell.faces.size() && !layer.faces.empty(); ++f)
      layer = clip(layer, cell.normal[f], cell.offset[f] - k * np, scale);
    if (layer.faces.size() < 4 || layer.volume() <= 1e-12 * np * np * np) break;
    // sharp edges (7.4, Figure 7.4.2): cut by a plane np / (2 tan(phi / 2)) in from the edge
    std::vector<std::pair<Vec3, double>> cuts;
    for (std::size_t f = 0; f < layer.faces.size(); ++f)
      for (std::size_t g = f + 1; g < layer.faces.size(); ++g) {
        int shared = 0;
        Vec3 mid = Vec3::Zero();
        for (int a : layer.faces[f])
          if (std::find(layer.faces[g].begin(), layer.faces[g].end(), a) != layer.faces[g].end()) ++shared, mid += layer.v[a];
        if (shared < 2) continue;
        mid /= shared;
        const Vec3 &n1 = layer.normal[f], &n2 = layer.normal[g];
        const double phi = M_PI - std::atan2(n1.cross(n2).norm(), n1.dot(n2));
        if (phi >= sharp || phi <= 0) continue;
        const Vec3 in = -(n1 + n2).normalized();
        const double alpha = np / (2 * std::tan(phi / 2));
        cuts.push_back({-in, (-in).dot(mid + alpha * in)});
      }
    for (const auto& [n, d] : cuts) layer = clip(layer, n, d, scale);
    if (layer.faces.size() < 4) break;
    const double vol = layer.volume(), thickness = 2 * vol / layer.area();
    std::vector<std::size_t> faces;
    if (thickness < 0.5 * np) {  // one sheet through the middle of the thin layer, then stop
      std::size_t big = 0;
      for (std::size_t f = 1; f < layer.faces.size(); ++f)
        if (face_area(layer, f) > face_area(layer, big)) big = f;
      const double t = vol / std::max(face_area(layer, big), 1e-300);
      surface_nodes(layer, np, -0.5 * t * layer.normal[big], nodes, {big});
      break;
    }
    for (std::size_t f = 0; f < layer.faces.size(); ++f) faces.push_back(f);
    surface_nodes(layer, np, Vec3::Zero(), nodes, faces);
  }
  // The layers put nodes on planes and regular grids, whose many co-spherical sets of five
  // leave the insertion slivers that no flip removes (a cube at R = 1e5: 5% of tetrahedra under
  // 10 degrees). A small deterministic jitter of each node breaks those ties.
  std::vector<Vec3> out = merge_close(nodes, 0.5 * np);
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  auto next = [&] {
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5;  // in [-0.5, 0.5)
  };
  for (Vec3& p : out) p += kNodeJitter * np * Vec3(next(), next(), next());
  return out;
}

}  // namespace bisect::fill
