// PolyhedralModel's storage operations (thesis 7.2.1: insert a vertex into an edge, an edge into
// a face, a face into a region) and its measures.
#include "bisect/polyhedral_model.hpp"

#include <algorithm>
#include <cmath>

#include "bisect/errors.hpp"
#include "domain/face_split.hpp"

namespace bisect {

PlaneFrame::PlaneFrame(const Vec3& normal, const Vec3& o) : origin(o), n(normal.normalized()) {
  // e1 along the axis least aligned with n, so the frame is well conditioned
  const Vec3 a = std::abs(n.x()) < 0.6 ? Vec3::UnitX() : (std::abs(n.y()) < 0.6 ? Vec3::UnitY() : Vec3::UnitZ());
  e1 = (a - a.dot(n) * n).normalized();
  e2 = n.cross(e1);
}

Index PolyhedralModel::add_node(const Vec3& p) {
  nodes.push_back(p);
  node_faces_.emplace_back();
  return static_cast<Index>(nodes.size() - 1);
}

Index PolyhedralModel::add_face(ModelFace f) {
  const Index id = static_cast<Index>(faces.size());
  if (node_faces_.size() < nodes.size()) node_faces_.resize(nodes.size());
  for (const auto& loop : f.loops)
    for (Index v : loop) node_faces_[v].push_back(id);
  faces.push_back(std::move(f));
  return id;
}

std::vector<Index> PolyhedralModel::faces_of_node(Index v) const {
  std::vector<Index> out;
  if (v >= static_cast<Index>(node_faces_.size())) return out;
  for (Index f : node_faces_[v])
    if (faces[f].alive && std::find(out.begin(), out.end(), f) == out.end()) out.push_back(f);
  return out;
}

Index PolyhedralModel::insert_vertex_in_edge(Index a, Index b, const Vec3& p) {
  const Index v = add_node(p);
  for (Index f : faces_of_node(a)) {
    bool touched = false;
    for (auto& loop : faces[f].loops) {
      const std::size_t n = loop.size();
      for (std::size_t i = 0; i < n; ++i) {
        const Index x = loop[i], y = loop[(i + 1) % n];
        if ((x == a && y == b) || (x == b && y == a)) {
          loop.insert(loop.begin() + static_cast<std::ptrdiff_t>(i + 1), v);
          touched = true;
          break;  // a simple loop uses an edge once
        }
      }
    }
    if (touched) node_faces_[v].push_back(f);
  }
  return v;
}

std::vector<Index> PolyhedralModel::split_face(Index f, const std::vector<std::array<Index, 2>>& chords) {
  if (chords.empty()) return {f};
  const ModelFace old = faces[f];
  const PlaneFrame frame(old.normal, nodes[old.loops[0][0]]);
  std::vector<std::vector<std::vector<Index>>> pieces =
      split_polygon_by_chords(old.loops, chords, [&](Index v) { return frame.to2d(nodes[v]); });
  faces[f].alive = false;
  std::vector<Index> out;
  for (auto& loops : pieces) {
    ModelFace nf = old;
    nf.loops = std::move(loops);
    nf.alive = true;
    out.push_back(add_face(std::move(nf)));
  }
  for (Index r : {old.front, old.back})
    if (r >= 0) {
      auto& rf = regions[r].faces;
      if (std::find(rf.begin(), rf.end(), out[0]) == rf.end()) rf.insert(rf.end(), out.begin(), out.end());
    }
  return out;
}

int PolyhedralModel::side_of(Index f, Index r) const {
  const ModelFace& F = faces[f];
  if (F.front == r && F.back == r) return 2;
  if (F.front == r) return 0;
  if (F.back == r) return 1;
  return -1;
}

double PolyhedralModel::face_area(Index f) const {
  const ModelFace& F = faces[f];
  double a = 0;
  for (const auto& loop : F.loops) {
    Vec3 s = Vec3::Zero();
    for (std::size_t i = 0; i < loop.size(); ++i)
      s += nodes[loop[i]].cross(nodes[loop[(i + 1) % loop.size()]]);
    a += 0.5 * s.dot(F.normal);  // outer loop positive, holes negative
  }
  return a;
}

double PolyhedralModel::region_volume(Index r) const {
  // Divergence theorem, about a point of the region for less cancellation.
  double v = 0;
  bool have_origin = false;
  Vec3 o = Vec3::Zero();
  for (Index f : regions[r].faces) {
    const ModelFace& F = faces[f];
    if (!F.alive) continue;
    const int side = side_of(f, r);
    if (side == 2 || side < 0) continue;  // both sides cancel
    if (!have_origin) o = nodes[F.loops[0][0]], have_origin = true;
    const double sgn = side == 1 ? 1.0 : -1.0;  // back side: the normal points out of r
    for (const auto& loop : F.loops) {
      Vec3 s = Vec3::Zero();
      for (std::size_t i = 0; i < loop.size(); ++i)
        s += (nodes[loop[i]] - o).cross(nodes[loop[(i + 1) % loop.size()]] - o);
      v += sgn * (nodes[loop[0]] - o).dot(F.normal) * 0.5 * s.dot(F.normal) / 3.0;
    }
  }
  return v;
}

std::vector<Index> PolyhedralModel::live_faces(Index r) const {
  std::vector<Index> out;
  for (Index f : regions[r].faces)
    if (faces[f].alive && side_of(f, r) >= 0) out.push_back(f);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

void PolyhedralModel::drop_dead_faces(Index r) { regions[r].faces = live_faces(r); }

}  // namespace bisect
