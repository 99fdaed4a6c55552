#include "mesh2d/prep_regions.hpp"

#include <algorithm>

#include "bisect/errors.hpp"
#include "domain/poly2_overlaps.hpp"

namespace bisect::mesh2d {
namespace {

double signed_area(const std::vector<Vec2>& nodes, const std::vector<Index>& loop) {
  double a = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec2 &p = nodes[loop[i]], &q = nodes[loop[(i + 1) % loop.size()]];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

}  // namespace

PlanarDomain prepare_planar(const Poly2Input& in) {
  reject_overlapping_polygons(in);  // the nesting below assumes polygons that do not overlap in part
  const Poly2Summary sum = summarize(in);
  PlanarDomain d;
  d.nodes = in.nodes;
  d.required_elements = in.required_elements;
  for (std::size_t p = 0; p < in.polygons.size(); ++p) {
    if (in.polygons[p].hole) continue;
    PlanarRegion r;
    r.polygon = static_cast<Index>(p);
    std::vector<Index> outer = in.polygons[p].nodes;
    if (signed_area(d.nodes, outer) < 0) std::reverse(outer.begin(), outer.end());
    r.loops.push_back(outer);
    r.loop_polygon.push_back(static_cast<Index>(p));
    for (std::size_t h = 0; h < in.polygons.size(); ++h) {
      if (sum.polygons[h].inside != static_cast<Index>(p)) continue;
      std::vector<Index> hole = in.polygons[h].nodes;  // a hole, or a sub-domain's outline
      if (signed_area(d.nodes, hole) > 0) std::reverse(hole.begin(), hole.end());
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
