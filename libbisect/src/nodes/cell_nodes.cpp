#include "nodes/cell_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>

#include "bisect/polyhedral_model.hpp"
#include "mesh2d/shrink_nodes.hpp"

namespace bisect::nodes {
namespace {

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

// Layer `depth` of the cell: every face plane moved inwards by depth, then its edges sharper
// than 30 degrees cut off by a plane np / (2 tan(phi / 2)) in from the edge (7.4, Figure 7.4.2).
// Fewer than 4 faces: empty.
Polytope layer_at(const Polytope& cell, double depth, double np, double scale) {
  Polytope layer = cell;
  for (std::size_t f = 0; f < cell.faces.size() && !layer.faces.empty(); ++f)
    layer = clip(layer, cell.normal[f], cell.offset[f] - depth, scale);
  if (layer.faces.size() < 4 || layer.volume() <= 1e-12 * np * np * np) return {};
  const double sharp = 30.0 * M_PI / 180.0;
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
  if (layer.faces.size() < 4) return {};
  return layer;
}

// The nodes of a layer thinner than the spacing, the shrinking's last: a sheet through its
// middle (its largest face moved in by half the layer's thickness) with the 2D placement. Where
// that sheet is itself narrower than np / 2 (the core of a bar), a line of nodes at spacing np
// through the sheet's middle along its longest extent instead, or one node at its centre when
// that extent is shorter than np: the 2D placement would put two rows there, and the merge of
// nodes closer than np / 2 would keep the one along a side.
void middle_nodes(const Polytope& layer, double np, std::vector<Vec3>& out) {
  std::size_t big = 0;
  for (std::size_t f = 1; f < layer.faces.size(); ++f)
    if (layer.face_area(f) > layer.face_area(big)) big = f;
  const double area = std::max(layer.face_area(big), 1e-300);
  const Vec3 shift = -0.5 * (layer.volume() / area) * layer.normal[big];
  const auto& loop = layer.faces[big];
  double perimeter = 0;
  for (std::size_t k = 0; k < loop.size(); ++k) perimeter += (layer.v[loop[(k + 1) % loop.size()]] - layer.v[loop[k]]).norm();
  if (2 * area / perimeter >= 0.5 * np) {
    surface_nodes(layer, np, shift, out, {big});
    return;
  }
  // the sheet's long direction: its longest edge's (the sheet is convex and thin), and its
  // extent along it
  Vec3 dir = Vec3::UnitX();
  double longest = 0;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Vec3 e = layer.v[loop[(k + 1) % loop.size()]] - layer.v[loop[k]];
    if (e.norm() > longest) longest = e.norm(), dir = e / e.norm();
  }
  const Vec3 a = layer.v[loop[0]];
  double s0 = 0, s1 = 0;
  for (int i : loop) s0 = std::min(s0, (layer.v[i] - a).dot(dir)), s1 = std::max(s1, (layer.v[i] - a).dot(dir));
  const double len = s1 - s0;
  if (len < np) {
    Vec3 c = Vec3::Zero();
    for (int i : loop) c += layer.v[i];
    out.push_back(c / static_cast<double>(loop.size()) + shift);
    return;
  }
  const Vec3 across = layer.normal[big].cross(dir);
  const int steps = std::max(1, static_cast<int>(std::lround(len / np)));
  const double eps = 1e-9 * len;
  for (int s = 0; s <= steps; ++s) {
    // the chord of the sheet across `dir` at this station: its middle
    const double at = s == steps ? s1 : s0 + len * s / steps;  // the ends exactly: their chords are edges
    double lo = 1e300, hi = -1e300;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Vec3 &p = layer.v[loop[k]], &q = layer.v[loop[(k + 1) % loop.size()]];
      const double sp = (p - a).dot(dir), sq = (q - a).dot(dir);
      if ((sp > at + eps && sq > at + eps) || (sp < at - eps && sq < at - eps)) continue;  // rounding: an end edge counts
      const double t = std::abs(sq - sp) > 1e-300 ? std::clamp((at - sp) / (sq - sp), 0.0, 1.0) : 0.0;
      const double w = (p + t * (q - p) - a).dot(across);
      lo = std::min(lo, w), hi = std::max(hi, w);
    }
    if (lo > hi) lo = hi = 0;
    out.push_back(a + at * dir + 0.5 * (lo + hi) * across + shift);
  }
}

}  // namespace

std::vector<Vec3> shrink_cell_nodes(const Polytope& cell, double np) {
  std::vector<Vec3> nodes;
  double scale = 0;
  for (const Vec3& q : cell.v) scale = std::max(scale, q.cwiseAbs().maxCoeff());
  scale = std::max(scale, np);
  for (int k = 1;; ++k) {
    const Polytope layer = layer_at(cell, k * np, np, scale);
    if (layer.faces.empty()) {
      // Between the last layer's two sides (or the cell's, for k = 1) a gap of np to 2 np is
      // left with no node in it: a 10 x 10 bar at spacing 6.9 had none, and tetrahedra spanning
      // it joined its faces' grids with 4 degree angles. Where the layer half a spacing deeper
      // than the last exists, the gap is wider than np: one sheet (or line) through its middle.
      const Polytope half = layer_at(cell, (k - 0.5) * np, np, scale);
      if (!half.faces.empty()) middle_nodes(half, np, nodes);
      break;
    }
    const double vol = layer.volume(), thickness = 2 * vol / layer.area();
    if (thickness < 0.5 * np) {  // one sheet through the middle of the thin layer, then stop
      middle_nodes(layer, np, nodes);
      break;
    }
    std::vector<std::size_t> faces;
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

}  // namespace bisect::nodes
