#include "io/face_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "bisect/errors.hpp"
#include "io/text_scan.hpp"
#include "util/edge_key.hpp"

namespace bisect::io {

// Faces with more nodes get the bounding box's diagonal as their diameter (the pairwise scan is
// quadratic: 20 s for a .poly2 coastline of 10^5 nodes).
constexpr std::size_t kExactDiameterNodes = 256;

FaceShape face_shape(const std::vector<Vec3>& nodes, const std::vector<Index>& face) {
  FaceShape s;
  const std::size_t k = face.size();
  if (k == 0) return s;
  for (std::size_t i = 0; i < k; ++i) {
    const Vec3& p = nodes[face[i]];
    s.centroid += p;
    s.scale = std::max(s.scale, p.cwiseAbs().maxCoeff());
    if (k <= kExactDiameterNodes)
      for (std::size_t j = i + 1; j < k; ++j) s.diameter = std::max(s.diameter, (nodes[face[j]] - p).norm());
  }
  if (k > kExactDiameterNodes) {  // the box's diagonal: at most sqrt(3) times the diameter, in linear time
    Vec3 lo = nodes[face[0]], hi = lo;
    for (Index v : face) lo = lo.cwiseMin(nodes[v]), hi = hi.cwiseMax(nodes[v]);
    s.diameter = (hi - lo).norm();
  }
  s.centroid /= double(k);
  for (std::size_t i = 0; i < k; ++i) {
    // Newell's method: exact for planar polygons of any shape, and a least-squares-like normal
    // for slightly warped ones, so the distances below are measured from a sensible plane.
    // Relative to the centroid, so that a face far from the origin loses no digits.
    const Vec3 p = nodes[face[i]] - s.centroid;
    const Vec3 q = nodes[face[(i + 1) % k]] - s.centroid;
    s.newell.x() += (p.y() - q.y()) * (p.z() + q.z());
    s.newell.y() += (p.z() - q.z()) * (p.x() + q.x());
    s.newell.z() += (p.x() - q.x()) * (p.y() + q.y());
  }
  return s;
}

void check_face_size(const std::vector<Index>& face, Index f, const std::string& where, const Naming& n) {
  if (face.size() < 3)
    throw InputError(where + ": " + n.face_name(f) + " has " + count_of(face.size(), n.node, n.nodes) + "; a " +
                     n.face + " needs at least 3" + n.note);
}

void check_distinct_nodes(const std::vector<Index>& face, Index f, const std::string& where, const Naming& n) {
  // sorted, so a polygon of 10^5 nodes takes no quadratic time; the node named is the first in
  // the face's order that comes again, as a pairwise scan would name it
  std::vector<Index> sorted = face;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) return;
  for (Index v : face) {
    const auto range = std::equal_range(sorted.begin(), sorted.end(), v);
    if (range.second - range.first > 1)
      throw InputError(where + ": " + n.face_name(f) + " lists " + n.node_name(v) + " twice" + n.note);
  }
}

void check_face_shape(const std::vector<Vec3>& nodes, const std::vector<Index>& face, Index f,
                      const std::string& where, const Naming& n, bool planarity) {
  const FaceShape s = face_shape(nodes, face);
  const double twice_area = s.newell.norm();
  if (!(twice_area > kZeroAreaRelTol * s.diameter * s.diameter)) {
    throw InputError(where + ": " + n.face_name(f) + " has zero area (its " + n.nodes +
                     " are collinear or coincide" + (face.size() > 3 ? ", or it folds onto itself" : "") + ")" +
                     n.note);
  }
  if (!planarity || face.size() <= 3) return;
  const Vec3 unit = s.newell / twice_area;
  const double tol = std::max(kPlanarityRelTol * s.diameter, kRoundoffFloor * s.scale);
  double worst = -1;
  Index worst_node = -1;
  for (Index v : face) {
    const double d = std::abs(unit.dot(nodes[v] - s.centroid));
    if (d > worst) worst = d, worst_node = v;
  }
  if (worst > tol)
    throw InputError(where + ": " + n.face_name(f) + " is not planar: " + n.node_name(worst_node) + " lies " +
                     fmt_num(worst) + " from the " + n.face + "'s plane (tolerance " + fmt_num(tol) + ")" + n.note);
}

namespace {

struct EdgeUse {
  std::int32_t count = 0;
  bool excused = false;
};

}  // namespace

std::optional<OddEdge> first_odd_edge(const std::vector<PolyFace>& faces, const std::vector<Index>& subset,
                                      const std::vector<bool>* excused) {
  std::vector<Index> order = subset;
  if (order.empty()) {
    order.resize(faces.size());
    for (std::size_t i = 0; i < faces.size(); ++i) order[i] = Index(i);
  }
  std::unordered_map<std::uint64_t, EdgeUse> uses;
  uses.reserve(order.size() * 2);
  for (Index f : order) {
    const auto& v = faces[f].nodes;
    const bool ex = excused && (*excused)[f];
    for (std::size_t i = 0; i < v.size(); ++i) {
      EdgeUse& u = uses[edge_key(v[i], v[(i + 1) % v.size()])];
      ++u.count;
      u.excused = u.excused || ex;
    }
  }
  for (Index f : order) {
    const auto& v = faces[f].nodes;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::uint64_t key = edge_key(v[i], v[(i + 1) % v.size()]);
      const EdgeUse& u = uses[key];
      if (u.count % 2 == 0 || u.excused) continue;
      OddEdge e;
      e.a = std::min(v[i], v[(i + 1) % v.size()]);
      e.b = std::max(v[i], v[(i + 1) % v.size()]);
      for (Index g : order) {
        const auto& w = faces[g].nodes;
        for (std::size_t j = 0; j < w.size(); ++j)
          if (edge_key(w[j], w[(j + 1) % w.size()]) == key) {
            e.faces.push_back(g);
            break;
          }
      }
      return e;
    }
  }
  return std::nullopt;
}

std::string describe(const OddEdge& e, const std::vector<Vec3>& nodes, const Naming& n) {
  std::string s = "edge between " + n.nodes + " " + std::to_string(std::int64_t(e.a) + n.base) + " " +
                  fmt_point(nodes[e.a]) + " and " + std::to_string(std::int64_t(e.b) + n.base) + " " +
                  fmt_point(nodes[e.b]) + " belongs to ";
  if (e.faces.size() == 1) return s + "only one " + n.face + " (" + n.face_name(e.faces[0]) + ")";
  s += std::to_string(e.faces.size()) + " " + n.faces + " (" + n.faces;
  for (std::size_t i = 0; i < e.faces.size(); ++i) {
    s += i == 0 ? " " : (i + 1 == e.faces.size() ? " and " : ", ");
    s += std::to_string(std::int64_t(e.faces[i]) + n.base);
  }
  return s + "), an odd number";
}

int locate_in_polygon(const std::vector<Vec2>& polygon, const Vec2& p, double tol) {
  bool inside = false;
  const std::size_t k = polygon.size();
  for (std::size_t i = 0; i < k; ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % k];
    const Vec2 ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    if ((a + t * ab - p).norm() <= tol) return 0;
    // Half-open in y so that a vertex on the ray is crossed once.
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) / (b.y() - a.y()) * ab.x();
      if (x > p.x()) inside = !inside;
    }
  }
  return inside ? 1 : -1;
}

int dominant_axis(const Vec3& normal) {
  int axis = 0;
  normal.cwiseAbs().maxCoeff(&axis);
  return axis;
}

Vec2 project(const Vec3& p, int drop_axis) {
  switch (drop_axis) {
    case 0: return {p.y(), p.z()};
    case 1: return {p.z(), p.x()};
    default: return {p.x(), p.y()};
  }
}

}  // namespace bisect::io
