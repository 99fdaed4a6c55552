#include "mesh2d/spacing.hpp"

#include <algorithm>
#include <cmath>

#include "bisect/errors.hpp"

namespace bisect::mesh2d {

double element_spacing(double area, std::int64_t elements) {
  if (elements <= 0) throw InputError("the required number of elements must be positive");
  return std::sqrt(4.0 * (area / static_cast<double>(elements)) / std::sqrt(3.0));
}

BoundaryGrid discretise_boundaries(const PlanarDomain& d, double h) {
  BoundaryGrid g;
  g.nodes = d.nodes;
  g.spacing.assign(d.nodes.size(), h);
  for (const PlanarRegion& r : d.regions)
    for (const auto& loop : r.loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Index a = loop[i], b = loop[(i + 1) % loop.size()];
        const double len = (d.nodes[a] - d.nodes[b]).norm();
        g.spacing[a] = std::min(g.spacing[a], len);
        g.spacing[b] = std::min(g.spacing[b], len);
      }
  std::map<std::pair<Index, Index>, std::vector<Index>> done;  // edge (lo, hi) -> inner nodes lo..hi
  auto inner_nodes = [&](Index a, Index b) {
    const bool flip = a > b;
    const Index lo = flip ? b : a, hi = flip ? a : b;
    auto it = done.find({lo, hi});
    if (it == done.end()) {
      const Vec2 p = d.nodes[lo], q = d.nodes[hi];
      const double len = (q - p).norm(), sa = g.spacing[lo], sb = g.spacing[hi];
      // integral of ds / (sa + (sb - sa) s / len) over the edge
      const double steps = std::abs(sb - sa) < 1e-12 * sa ? len / sa : len * std::log(sb / sa) / (sb - sa);
      const int n = std::max(1, static_cast<int>(std::lround(steps)));
      std::vector<Index> ids;
      for (int k = 1; k < n; ++k) {
        // the s where the integral reaches k / n of its total
        const double target = steps * k / n;
        const double s = std::abs(sb - sa) < 1e-12 * sa ? target * sa
                                                        : (sa * (std::exp(target * (sb - sa) / len) - 1)) * len / (sb - sa);
        g.nodes.push_back(p + (q - p) * (s / len));
        g.spacing.push_back(sa + (sb - sa) * s / len);
        ids.push_back(static_cast<Index>(g.nodes.size() - 1));
      }
      it = done.emplace(std::make_pair(lo, hi), ids).first;
    }
    std::vector<Index> out = it->second;
    if (flip) std::reverse(out.begin(), out.end());
    return out;
  };
  for (const PlanarRegion& r : d.regions) {
    g.loops.emplace_back();
    for (const auto& loop : r.loops) {
      std::vector<Index> full;
      for (std::size_t i = 0; i < loop.size(); ++i) {
        full.push_back(loop[i]);
        for (Index v : inner_nodes(loop[i], loop[(i + 1) % loop.size()])) full.push_back(v);
      }
      g.loops.back().push_back(std::move(full));
    }
  }
  return g;
}

}  // namespace bisect::mesh2d
