#include "mesh2d/spacing.hpp"

#include <algorithm>
#include <cmath>

#include "bisect/errors.hpp"

namespace bisect::mesh2d {

double element_spacing(double area, std::int64_t elements) {
  if (elements <= 0) throw InputError("the required number of elements must be positive");
  return std::sqrt(4.0 * (area / static_cast<double>(elements)) / std::sqrt(3.0));
}

double edge_spacing_at(double x, double len, double sa, double sb, double h) {
  return std::min({h, sa + kSpacingGrowth * x, sb + kSpacingGrowth * (len - x)});
}

std::vector<double> graded_edge_fractions(double len, double sa, double sb, double h) {
  // s(x) = min(h, sa + g x, sb + g (len - x)) is linear between these breakpoints; the integral
  // of 1 / s and its inverse are exact on each piece
  const double g = kSpacingGrowth;
  std::vector<double> xs{0, len, (h - sa) / g, len - (h - sb) / g, (sb - sa + g * len) / (2 * g)};
  for (double& x : xs) x = std::clamp(x, 0.0, len);
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  struct Piece {
    double x0, c, m, integral;  // s = c + m x on [x0, x0 + ...)
  };
  std::vector<Piece> pieces;
  double total = 0;
  for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
    const double x0 = xs[k], x1 = xs[k + 1], xm = 0.5 * (x0 + x1), sm = edge_spacing_at(xm, len, sa, sb, h);
    const double m = sm == h ? 0 : (sm == sa + g * xm ? g : -g);
    const double c = sm - m * xm;
    const double integral = m == 0 ? (x1 - x0) / c : std::log((c + m * x1) / (c + m * x0)) / m;
    pieces.push_back({x0, c, m, integral});
    total += integral;
  }
  const int n = std::max(1, static_cast<int>(std::lround(total)));
  std::vector<double> out;
  std::size_t p = 0;
  double before = 0;  // integral up to pieces[p].x0
  for (int k = 1; k < n; ++k) {
    const double target = total * k / n;
    while (p + 1 < pieces.size() && before + pieces[p].integral < target) before += pieces[p++].integral;
    const Piece& q = pieces[p];
    const double t = target - before;
    const double x = q.m == 0 ? q.x0 + t * q.c : ((q.c + q.m * q.x0) * std::exp(q.m * t) - q.c) / q.m;
    out.push_back(std::clamp(x, 0.0, len) / len);
  }
  return out;
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
      const double sa = g.spacing[lo], sb = g.spacing[hi];
      std::vector<Index> ids;
      const double len = (q - p).norm();
      for (double f : graded_edge_fractions(len, sa, sb, h)) {
        g.nodes.push_back(p + (q - p) * f);
        g.spacing.push_back(edge_spacing_at(f * len, len, sa, sb, h));
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
