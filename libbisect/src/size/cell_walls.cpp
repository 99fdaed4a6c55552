#include "size/cell_walls.hpp"

#include <algorithm>
#include <cmath>

namespace bisect::size {
namespace {

constexpr double kFacing = 0.906;  // cos 25 degrees: outward normals this close to opposite face each other

}  // namespace

std::vector<double> cell_wall_thickness(const Decomposition& d) {
  const PolyhedralModel& m = d.model;
  std::vector<double> out(d.cells.size(), 0.0);
  for (std::size_t c = 0; c < d.cells.size(); ++c) {
    const ConvexCell& cell = d.cells[c];
    // the cell's input faces, each with its outward plane and its outer loop's corners
    struct Side {
      Vec3 n;
      double offset;
      const std::vector<Index>* corners;
    };
    std::vector<Side> sides;
    for (std::size_t k = 0; k < cell.faces.size(); ++k) {
      const ModelFace& f = m.faces[cell.faces[k]];
      if (!f.alive || f.source < 0 || f.loops.empty()) continue;
      const double s = cell.outward[k] ? 1.0 : -1.0;
      sides.push_back({s * f.normal, s * f.offset, &f.loops[0]});
    }
    // the mean depth of a face's corners below the other face's plane
    auto depth = [&](const Side& from, const Side& plane) {
      double sum = 0;
      for (Index v : *from.corners) sum += plane.offset - plane.n.dot(m.nodes[v]);
      return sum / static_cast<double>(from.corners->size());
    };
    double thinnest = 0;
    for (std::size_t i = 0; i < sides.size(); ++i)
      for (std::size_t j = i + 1; j < sides.size(); ++j) {
        if (sides[i].n.dot(sides[j].n) > -kFacing) continue;
        const double t = 0.5 * (depth(sides[i], sides[j]) + depth(sides[j], sides[i]));
        if (t > 0 && (thinnest == 0 || t < thinnest)) thinnest = t;
      }
    out[c] = thinnest;
  }
  return out;
}

}  // namespace bisect::size
