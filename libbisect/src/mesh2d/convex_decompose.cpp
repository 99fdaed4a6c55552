#include "mesh2d/convex_decompose.hpp"

#include <algorithm>
#include <cmath>

#include "bisect/errors.hpp"
#include "geom/predicates.hpp"
#include "mesh2d/loop_geometry.hpp"
#include "mesh2d/planar_failure.hpp"

namespace bisect::mesh2d {
namespace {

using geom::orient2d;

bool crosses(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const int o1 = orient2d(a, b, c), o2 = orient2d(a, b, d), o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  // a node of cd strictly inside ab (or the reverse) blocks too
  auto on = [](const Vec2& s, const Vec2& t, const Vec2& x) {
    return orient2d(s, t, x) == 0 && (x - s).dot(x - t) < 0;
  };
  return on(a, b, c) || on(a, b, d);
}

// Whether p -> q leaves p into the interior angle at loop position k (prev, p, next).
bool in_angle(const Vec2& prev, const Vec2& p, const Vec2& next, const Vec2& q) {
  if (orient2d(prev, p, next) > 0) return orient2d(p, next, q) > 0 && orient2d(prev, p, q) > 0;
  return !(orient2d(p, next, q) <= 0 && orient2d(prev, p, q) <= 0);
}

// The separator p q between nodes of the given loops stays inside: no loop edge crossed.
bool clear(const std::vector<Vec2>& X, const std::vector<std::vector<Index>>& loops, Index p, Index q) {
  for (const auto& l : loops)
    for (std::size_t i = 0; i < l.size(); ++i) {
      const Index a = l[i], b = l[(i + 1) % l.size()];
      if (a == p || a == q || b == p || b == q) continue;
      if (crosses(X[p], X[q], X[a], X[b])) return false;
    }
  return true;
}

// Whether the segment p q passes closer than `gap` to a loop node other than its ends. `clear`
// lets such a separator through, but it leaves a sliver piece between itself and that node (a
// hole cut grazing the hole's own corner made 0.4 degree pieces on a square with holes).
bool passes_near(const std::vector<Vec2>& X, const std::vector<std::vector<Index>>& loops, Index p, Index q, double gap) {
  const Vec2 a = X[p], d = X[q] - X[p];
  const double len2 = d.squaredNorm();
  for (const auto& l : loops)
    for (Index v : l) {
      if (v == p || v == q) continue;
      const Vec2 r = X[v] - a;
      const double t = r.dot(d);
      if (t <= 0 || t >= len2) continue;
      if (std::abs(d.x() * r.y() - d.y() * r.x()) < gap * std::sqrt(len2)) return true;
    }
  return false;
}

const double kMinSeparatorAngle = 20 * M_PI / 180;

double angle_between(const Vec2& u, const Vec2& v) {  // counter-clockwise from u to v, in [0, 2 pi)
  double a = std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
  return a < 0 ? a + 2 * M_PI : a;
}

// The two angles a separator from loop position k towards q makes with the loop's edges there.
std::pair<double, double> split_angles(const std::vector<Vec2>& X, const std::vector<Index>& loop, std::size_t k, const Vec2& q) {
  const std::size_t n = loop.size();
  const Vec2 p = X[loop[k]];
  const Vec2 to_next = X[loop[(k + 1) % n]] - p, to_prev = X[loop[(k + n - 1) % n]] - p, to_q = q - p;
  return {angle_between(to_next, to_q), angle_between(to_q, to_prev)};
}

// Nodes along the separator a -> b at about spacing h (not a and b themselves).
std::vector<Index> separator_nodes(std::vector<Vec2>& X, Index a, Index b, double h) {
  std::vector<Index> out;
  const Vec2 p = X[a], q = X[b];
  const int steps = std::max(1, static_cast<int>(std::lround((q - p).norm() / h)));
  for (int s = 1; s < steps; ++s) {
    X.push_back(p + (q - p) * (static_cast<double>(s) / steps));
    out.push_back(static_cast<Index>(X.size() - 1));
  }
  return out;
}

double area2(const std::vector<Vec2>& X, const std::vector<Index>& l) {
  double s = 0;
  for (std::size_t k = 0; k < l.size(); ++k) {
    const Vec2 &u = X[l[k]], &v = X[l[(k + 1) % l.size()]];
    s += u.x() * v.y() - u.y() * v.x();
  }
  return s;
}

// Splits `outer` with the hole `hole` inside it into two simple pieces by two separators. When
// `strict`, a separator must meet both loops at 20 degrees or more and pass no other node closer
// than h / 4, so that the cut makes no sliver.
bool cut_hole(std::vector<Vec2>& X, const std::vector<Index>& outer, const std::vector<Index>& hole,
              const std::vector<std::vector<Index>>& others, double h, bool strict, std::vector<Index>* a, std::vector<Index>* b) {
  std::vector<std::vector<Index>> all = others;
  all.push_back(outer);
  all.push_back(hole);
  const std::size_t no = outer.size(), nh = hole.size();
  // separators from every hole node to its nearest visible outer node, shortest first
  struct Sep {
    double len;
    std::size_t hi, oi;
  };
  std::vector<Sep> seps;
  for (std::size_t hi = 0; hi < nh; ++hi) {
    std::vector<std::pair<double, std::size_t>> order;
    for (std::size_t oi = 0; oi < no; ++oi) order.push_back({(X[outer[oi]] - X[hole[hi]]).norm(), oi});
    std::sort(order.begin(), order.end());
    for (std::size_t c = 0; c < std::min<std::size_t>(order.size(), 12); ++c) {
      const std::size_t oi = order[c].second;
      const Index hv = hole[hi], ov = outer[oi];
      if (!in_angle(X[hole[(hi + nh - 1) % nh]], X[hv], X[hole[(hi + 1) % nh]], X[ov])) continue;
      if (!in_angle(X[outer[(oi + no - 1) % no]], X[ov], X[outer[(oi + 1) % no]], X[hv])) continue;
      if (!clear(X, all, hv, ov)) continue;
      if (strict) {
        const auto [h1, h2] = split_angles(X, hole, hi, X[ov]);
        const auto [o1, o2] = split_angles(X, outer, oi, X[hv]);
        if (std::min({h1, h2, o1, o2}) < kMinSeparatorAngle || passes_near(X, all, hv, ov, h / 4)) continue;
      }
      seps.push_back({order[c].first, hi, oi});
      break;
    }
  }
  std::sort(seps.begin(), seps.end(), [](const Sep& x, const Sep& y) { return x.len < y.len; });
  for (std::size_t s1 = 0; s1 < seps.size(); ++s1)
    for (std::size_t s2 = seps.size(); s2-- > s1 + 1;) {  // the second as far round the hole as can be
      const Sep &A = seps[s1], &B = seps[s2];
      if (A.hi == B.hi || A.oi == B.oi) continue;
      if (crosses(X[hole[A.hi]], X[outer[A.oi]], X[hole[B.hi]], X[outer[B.oi]])) continue;
      // piece 1: outer A -> B, separator B to the hole, hole B -> A, separator A back out;
      // piece 2: outer B -> A, separator A in, hole A -> B, separator B out. Checked without
      // the separators' inner nodes first, so a rejected pair leaves no stray node behind.
      auto build = [&](const std::vector<Index>& sep_a, const std::vector<Index>& sep_b, std::vector<Index>* p1,
                       std::vector<Index>* p2) {
        p1->clear(), p2->clear();
        for (std::size_t k = A.oi; k != B.oi; k = (k + 1) % no) p1->push_back(outer[k]);
        p1->push_back(outer[B.oi]);
        p1->insert(p1->end(), sep_b.begin(), sep_b.end());
        for (std::size_t k = B.hi; k != A.hi; k = (k + 1) % nh) p1->push_back(hole[k]);
        p1->push_back(hole[A.hi]);
        p1->insert(p1->end(), sep_a.begin(), sep_a.end());
        for (std::size_t k = B.oi; k != A.oi; k = (k + 1) % no) p2->push_back(outer[k]);
        p2->push_back(outer[A.oi]);
        p2->insert(p2->end(), sep_a.rbegin(), sep_a.rend());
        for (std::size_t k = A.hi; k != B.hi; k = (k + 1) % nh) p2->push_back(hole[k]);
        p2->push_back(hole[B.hi]);
        p2->insert(p2->end(), sep_b.rbegin(), sep_b.rend());
      };
      std::vector<Index> p1, p2;
      build({}, {}, &p1, &p2);
      if (area2(X, p1) <= 0 || area2(X, p2) <= 0) continue;
      const std::vector<Index> sep_b = separator_nodes(X, outer[B.oi], hole[B.hi], h);
      const std::vector<Index> sep_a = separator_nodes(X, hole[A.hi], outer[A.oi], h);
      build(sep_a, sep_b, &p1, &p2);
      *a = std::move(p1);
      *b = std::move(p2);
      return true;
    }
  return false;
}

// The loop node that the separator from reflex vertex `reflex` should go to: inside the loop,
// splitting the reflex angle into two of at most 180 degrees, the largest smallest angle at
// both ends; one passing near another node only when there is nothing else. n when none.
std::size_t best_separator(const std::vector<Vec2>& X, const std::vector<Index>& l, std::size_t reflex, double h) {
  const std::size_t n = l.size();
  double best = -1, best_grazing = -1;
  std::size_t bw = n, grazing = n;
  for (std::size_t w = 0; w < n; ++w) {
    if (w == reflex || w == (reflex + 1) % n || (w + 1) % n == reflex) continue;
    const Vec2 q = X[l[w]];
    const auto [a1, a2] = split_angles(X, l, reflex, q);
    if (a1 > M_PI || a2 > M_PI) continue;  // does not resolve the reflex angle
    const auto [b1, b2] = split_angles(X, l, w, X[l[reflex]]);
    if (b1 <= 0 || b2 <= 0 || b1 + b2 > 2 * M_PI - 1e-12) continue;
    const double worst = std::min({a1, a2, b1, b2});
    if (worst <= best) continue;
    if (!clear(X, {l}, l[reflex], l[w])) continue;
    if (!in_angle(X[l[(w + n - 1) % n]], q, X[l[(w + 1) % n]], X[l[reflex]])) continue;
    if (passes_near(X, {l}, l[reflex], l[w], h / 4)) {
      if (worst > best_grazing) best_grazing = worst, grazing = w;
      continue;
    }
    best = worst, bw = w;
  }
  return bw == n ? grazing : bw;
}

}  // namespace

std::vector<std::vector<Index>> convex_pieces(std::vector<Vec2>& X, const std::vector<std::vector<Index>>& loops, double h) {
  // 1. holes: each splits the simple piece holding it in two
  std::vector<std::vector<Index>> simple{loops[0]};
  for (std::size_t hi = 1; hi < loops.size(); ++hi) {
    const std::vector<Index>& hole = loops[hi];
    std::size_t host = simple.size();
    for (std::size_t s = 0; s < simple.size() && host == simple.size(); ++s)
      if (inside_loop(X, simple[s], X[hole[0]])) host = s;
    if (host == simple.size()) throw PlanarFailure("convex decomposition: a hole lies in no piece", X[hole[0]], static_cast<int>(hi));
    std::vector<std::vector<Index>> others(loops.begin() + static_cast<std::ptrdiff_t>(hi) + 1, loops.end());
    std::vector<Index> a, b;
    if (!cut_hole(X, simple[host], hole, others, h, true, &a, &b) && !cut_hole(X, simple[host], hole, others, h, false, &a, &b))
      throw PlanarFailure("convex decomposition: no pair of cut edges joins a hole to its boundary", X[hole[0]], static_cast<int>(hi));
    simple[host] = std::move(a);
    simple.push_back(std::move(b));
  }
  // 2. reflex vertices: a separator into the inner cone, the best angles
  std::vector<std::vector<Index>> out;
  while (!simple.empty()) {
    std::vector<Index> l = std::move(simple.back());
    simple.pop_back();
    const std::size_t n = l.size();
    // the first reflex vertex that some separator resolves; a piece none of whose reflex
    // vertices can be resolved (a neck narrower than any separator's angle) stays as it is
    std::size_t reflex = n, bw = n;
    for (std::size_t k = 0; k < n && bw == n; ++k) {
      // reflex beyond round-off: separator nodes are interpolated, so a straight run of them can
      // turn by 1e-16 either way, which is no corner to resolve
      const Vec2 a = X[l[k]] - X[l[(k + n - 1) % n]], b = X[l[(k + 1) % n]] - X[l[k]];
      if (a.x() * b.y() - a.y() * b.x() >= -1e-9 * a.norm() * b.norm()) continue;
      reflex = k;
      bw = best_separator(X, l, k, h);
    }
    if (bw == n) {
      out.push_back(std::move(l));
      continue;
    }
    const std::vector<Index> mid = separator_nodes(X, l[reflex], l[bw], h);
    std::vector<Index> p1, p2;
    for (std::size_t k = reflex; k != bw; k = (k + 1) % n) p1.push_back(l[k]);
    p1.push_back(l[bw]);
    for (std::size_t k = mid.size(); k-- > 0;) p1.push_back(mid[k]);
    for (std::size_t k = bw; k != reflex; k = (k + 1) % n) p2.push_back(l[k]);
    p2.push_back(l[reflex]);
    p2.insert(p2.end(), mid.begin(), mid.end());
    simple.push_back(std::move(p1));
    simple.push_back(std::move(p2));
  }
  return out;
}

}  // namespace bisect::mesh2d
