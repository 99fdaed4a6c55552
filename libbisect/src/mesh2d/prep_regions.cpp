#include "mesh2d/prep_regions.hpp"

#include <algorithm>

#include "bisect/errors.hpp"
#include "domain/face_split.hpp"
#include "domain/poly2_overlaps.hpp"
#include "geom/predicates.hpp"

namespace bisect::mesh2d {
namespace {

// The polygon with every other polygon's node that lies strictly inside one of its edges put into
// that edge (exactly, by orient2d). A hole or sub-domain whose side runs along part of its
// polygon's edge (a notch on the boundary), or two polygons side by side sharing part of an edge,
// then share the nodes and the edge pieces: the pieces are discretised once for both loops, and a
// hole's edge cancels the boundary's (convex_pieces), where before the two ran over each other.
std::vector<Index> split_at_nodes(const std::vector<Vec2>& X, const std::vector<Index>& poly, const std::vector<Index>& by_x) {
  std::vector<Index> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Index a = poly[i], b = poly[(i + 1) % poly.size()];
    out.push_back(a);
    const Vec2 &p = X[a], &q = X[b];
    const double x0 = std::min(p.x(), q.x()), x1 = std::max(p.x(), q.x());
    const double y0 = std::min(p.y(), q.y()), y1 = std::max(p.y(), q.y());
    auto it = std::lower_bound(by_x.begin(), by_x.end(), x0, [&](Index v, double x) { return X[v].x() < x; });
    std::vector<std::pair<double, Index>> on;
    for (; it != by_x.end() && X[*it].x() <= x1; ++it) {
      const Vec2& r = X[*it];
      if (r.y() < y0 || r.y() > y1 || r == p || r == q || geom::orient2d(p, q, r) != 0) continue;
      if ((r - p).dot(r - q) >= 0) continue;  // not strictly between the ends
      on.push_back({(r - p).squaredNorm(), *it});
    }
    std::sort(on.begin(), on.end());
    for (std::size_t k = 0; k < on.size(); ++k)
      if (k == 0 || X[on[k].second] != X[on[k - 1].second]) out.push_back(on[k].second);
  }
  return out;
}

}  // namespace

PlanarDomain prepare_planar(const Poly2Input& in) {
  reject_overlapping_polygons(in);  // the nesting below assumes polygons that do not overlap in part
  const Poly2Summary sum = summarize(in);
  PlanarDomain d;
  d.nodes = in.nodes;
  d.required_elements = in.required_elements;
  // the polygons' nodes by x, one id per position (the lowest: a node given twice is one node,
  // so a hole written with its own copy of a boundary corner still touches the boundary there),
  // for the edges to pick up the nodes on them
  std::vector<Index> by_x, same(in.nodes.size());
  for (std::size_t v = 0; v < same.size(); ++v) same[v] = static_cast<Index>(v);
  {
    std::vector<char> used(in.nodes.size(), 0);
    for (const auto& poly : in.polygons)
      for (Index v : poly.nodes) used[static_cast<std::size_t>(v)] = 1;
    for (std::size_t v = 0; v < used.size(); ++v)
      if (used[v]) by_x.push_back(static_cast<Index>(v));
    std::sort(by_x.begin(), by_x.end(), [&](Index a, Index b) {
      const Vec2 &p = in.nodes[a], &q = in.nodes[b];
      return p.x() != q.x() ? p.x() < q.x() : p.y() != q.y() ? p.y() < q.y() : a < b;
    });
    for (std::size_t k = 1; k < by_x.size(); ++k)
      if (in.nodes[by_x[k]] == in.nodes[by_x[k - 1]]) same[by_x[k]] = same[by_x[k - 1]];
    by_x.erase(std::unique(by_x.begin(), by_x.end(), [&](Index a, Index b) { return in.nodes[a] == in.nodes[b]; }), by_x.end());
  }
  std::vector<std::vector<Index>> polys;
  for (const auto& poly : in.polygons) {
    std::vector<Index> ids;
    for (Index v : poly.nodes)
      if (ids.empty() || same[v] != ids.back()) ids.push_back(same[v]);
    while (ids.size() > 1 && ids.back() == ids.front()) ids.pop_back();
    polys.push_back(split_at_nodes(in.nodes, ids, by_x));
  }
  const auto at = [&d](Index i) { return d.nodes[i]; };
  for (std::size_t p = 0; p < in.polygons.size(); ++p) {
    if (in.polygons[p].hole) continue;
    PlanarRegion r;
    r.polygon = static_cast<Index>(p);
    std::vector<Index> outer = polys[p];
    if (loop_area2(outer, at) < 0) std::reverse(outer.begin(), outer.end());
    r.loops.push_back(outer);
    r.loop_polygon.push_back(static_cast<Index>(p));
    for (std::size_t h = 0; h < in.polygons.size(); ++h) {
      if (sum.polygons[h].inside != static_cast<Index>(p)) continue;
      std::vector<Index> hole = polys[h];  // a hole, or a sub-domain's outline
      if (loop_area2(hole, at) > 0) std::reverse(hole.begin(), hole.end());
      r.loops.push_back(hole);
      r.loop_polygon.push_back(static_cast<Index>(h));
    }
    r.area = sum.polygons[p].net_area;
    if (r.area <= 0)
      throw InputError(in.source + ": polygon " + std::to_string(p + 1) + " has no area left once its holes are removed");
    d.area += r.area;
    d.regions.push_back(std::move(r));
  }
  if (d.regions.empty()) throw InputError(in.source + ": no polygon to mesh (every polygon is a hole)");
  return d;
}

}  // namespace bisect::mesh2d
