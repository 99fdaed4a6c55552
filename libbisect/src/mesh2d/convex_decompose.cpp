#include "mesh2d/convex_decompose.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

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

// A loop cut along a separator between its nodes k and j: the side from node k to node j closed
// by `back` (the separator's inner nodes from loop[j] towards loop[k]), then the side from j to
// k closed by the same nodes the other way.
std::pair<std::vector<Index>, std::vector<Index>> split_loop(const std::vector<Index>& loop, std::size_t k, std::size_t j,
                                                             const std::vector<Index>& back) {
  const std::size_t n = loop.size();
  std::vector<Index> first, second;
  for (std::size_t i = k; i != j; i = (i + 1) % n) first.push_back(loop[i]);
  first.push_back(loop[j]);
  first.insert(first.end(), back.begin(), back.end());
  for (std::size_t i = j; i != k; i = (i + 1) % n) second.push_back(loop[i]);
  second.push_back(loop[k]);
  second.insert(second.end(), back.rbegin(), back.rend());
  return {std::move(first), std::move(second)};
}

double area2(const std::vector<Vec2>& X, const std::vector<Index>& l) {
  double s = 0;
  for (std::size_t k = 0; k < l.size(); ++k) {
    const Vec2 &u = X[l[k]], &v = X[l[(k + 1) % l.size()]];
    s += u.x() * v.y() - u.y() * v.x();
  }
  return s;
}

// ---- holes that touch their piece (a notch: a hole or a sub-domain sharing a node or a side) ----

bool shares_node(const std::vector<Index>& a, const std::vector<Index>& b) {
  std::vector<Index> s = a;
  std::sort(s.begin(), s.end());
  for (Index v : b)
    if (std::binary_search(s.begin(), s.end(), v)) return true;
  return false;
}

// Whether the hole lies in the piece it touches: the midpoint of a hole side that is not also a
// side of the piece lies inside (a node both touch can belong to two pieces after a cut).
bool holds(const std::vector<Vec2>& X, const std::vector<Index>& piece, const std::vector<Index>& hole) {
  std::vector<std::pair<Index, Index>> sides;
  for (std::size_t k = 0; k < piece.size(); ++k) sides.push_back({piece[k], piece[(k + 1) % piece.size()]});
  std::sort(sides.begin(), sides.end());
  for (std::size_t k = 0; k < hole.size(); ++k) {
    const Index u = hole[k], v = hole[(k + 1) % hole.size()];
    if (std::binary_search(sides.begin(), sides.end(), std::make_pair(v, u))) continue;
    return inside_loop(X, piece, 0.5 * (X[u] + X[v]));
  }
  return true;  // every side shared: the hole fills the piece
}

// The closed walks around the piece less the hole: the two loops' sides, those running both
// ways (the sides the hole shares with the piece) taken out, followed with the region on the
// left; where several sides leave a node, the first clockwise from the way back, so walks part
// where the region is pinched apart and run on where a hole touches it at a node.
std::vector<std::vector<Index>> boundary_walks(const std::vector<Vec2>& X, const std::vector<Index>& piece,
                                               const std::vector<Index>& hole, bool* closed) {
  std::vector<std::pair<Index, Index>> e;
  for (const auto* l : {&piece, &hole})
    for (std::size_t k = 0; k < l->size(); ++k) e.push_back({(*l)[k], (*l)[(k + 1) % l->size()]});
  std::vector<char> live(e.size(), 1);
  std::map<std::pair<Index, Index>, std::vector<std::size_t>> by_ends;
  for (std::size_t k = 0; k < e.size(); ++k) by_ends[e[k]].push_back(k);
  for (std::size_t k = 0; k < e.size(); ++k) {
    if (!live[k]) continue;
    const auto it = by_ends.find({e[k].second, e[k].first});
    if (it == by_ends.end()) continue;
    for (std::size_t j : it->second)
      if (live[j]) {
        live[j] = live[k] = 0;
        break;
      }
  }
  std::map<Index, std::vector<std::size_t>> leaving;
  for (std::size_t k = 0; k < e.size(); ++k)
    if (live[k]) leaving[e[k].first].push_back(k);
  std::vector<std::vector<Index>> walks;
  *closed = true;
  for (std::size_t s = 0; s < e.size(); ++s) {
    if (!live[s]) continue;
    std::vector<Index> walk;
    std::size_t k = s;
    for (;;) {
      live[k] = 0;
      walk.push_back(e[k].first);
      const Index u = e[k].first, v = e[k].second;
      std::size_t next = e.size();
      double best = 1e300;
      std::vector<std::size_t> cands = leaving[v];
      if (e[s].first == v) cands.push_back(s);  // back at the start: closing is one of the ways on
      for (std::size_t f : cands) {
        if (f != s && !live[f]) continue;
        double a = angle_between(X[e[f].second] - X[v], X[u] - X[v]);  // clockwise from the way back
        if (a <= 0) a = 2 * M_PI;
        if (a < best) best = a, next = f;
      }
      if (next == s) break;
      if (next == e.size()) {  // a side with no way on: the loops do not bound a region
        *closed = false;
        break;
      }
      k = next;
    }
    walks.push_back(std::move(walk));
  }
  return walks;
}

// A separator from walk position pa to position pb: distinct nodes, leaving each into the walk's
// angle there, crossing nothing; when strict, no sliver angle and no node grazed.
bool separator_ok(const std::vector<Vec2>& X, const std::vector<Index>& w, const std::vector<std::vector<Index>>& all, std::size_t pa,
                  std::size_t pb, double h, bool strict) {
  const std::size_t n = w.size();
  const Index a = w[pa], b = w[pb];
  if (a == b || X[a] == X[b]) return false;
  if (!in_angle(X[w[(pa + n - 1) % n]], X[a], X[w[(pa + 1) % n]], X[b])) return false;
  if (!in_angle(X[w[(pb + n - 1) % n]], X[b], X[w[(pb + 1) % n]], X[a])) return false;
  if (!clear(X, all, a, b)) return false;
  if (!strict) return true;
  const auto [a1, a2] = split_angles(X, w, pa, X[b]);
  const auto [b1, b2] = split_angles(X, w, pb, X[a]);
  return std::min({a1, a2, b1, b2}) >= kMinSeparatorAngle && !passes_near(X, all, a, b, h / 4);
}

// A walk that passes a node twice (a hole touching the piece at that node) cut into walks that
// pass no node twice: each time one separator between the part of the walk from the node back
// to it (round the hole) and the rest, the shortest acceptable one. False when none is found;
// *at then holds the node.
bool cut_pinches(std::vector<Vec2>& X, std::vector<Index> walk, const std::vector<std::vector<Index>>& others, double h,
                 std::vector<std::vector<Index>>* out, Index* at) {
  std::vector<std::vector<Index>> todo{std::move(walk)};
  while (!todo.empty()) {
    std::vector<Index> w = std::move(todo.back());
    todo.pop_back();
    const std::size_t n = w.size();
    std::map<Index, std::size_t> first;
    std::size_t i = n, j = n;
    for (std::size_t k = 0; k < n && j == n; ++k) {
      const auto [it, fresh] = first.emplace(w[k], k);
      if (!fresh) i = it->second, j = k;
    }
    if (j == n) {
      out->push_back(std::move(w));
      continue;
    }
    *at = w[i];
    std::vector<std::vector<Index>> all = others;
    all.push_back(w);
    std::size_t pa = n, pb = n;
    for (const bool strict : {true, false}) {
      double best = 1e300;
      for (std::size_t p = i + 1; p < j; ++p) {
        if (w[p] == w[i]) continue;
        std::vector<std::pair<double, std::size_t>> order;  // the rest of the walk, nearest first
        for (std::size_t q = (j + 1) % n; q != i; q = (q + 1) % n) order.push_back({(X[w[q]] - X[w[p]]).squaredNorm(), q});
        std::sort(order.begin(), order.end());
        for (std::size_t c = 0; c < std::min<std::size_t>(order.size(), 12); ++c)
          if (order[c].first < best && separator_ok(X, w, all, p, order[c].second, h, strict)) {
            best = order[c].first, pa = p, pb = order[c].second;
            break;
          }
      }
      if (pa != n) break;
    }
    if (pa == n) return false;
    auto [one, two] = split_loop(w, pa, pb, separator_nodes(X, w[pb], w[pa], h));  // the separator from pb towards pa
    todo.push_back(std::move(one));
    todo.push_back(std::move(two));
  }
  return true;
}

// The piece less a hole that touches it, as simple counter-clockwise loops (none when the hole
// fills it). Throws PlanarFailure at the touching node when it cannot be done.
std::vector<std::vector<Index>> join_touching(std::vector<Vec2>& X, const std::vector<Index>& piece, const std::vector<Index>& hole,
                                              const std::vector<std::vector<Index>>& others, double h, int hole_index) {
  Index touch = hole[0];
  for (Index v : hole)
    if (std::find(piece.begin(), piece.end(), v) != piece.end()) {
      touch = v;
      break;
    }
  bool closed = true;
  const std::vector<std::vector<Index>> walks = boundary_walks(X, piece, hole, &closed);
  if (!closed)
    throw PlanarFailure("convex decomposition: a hole that touches its boundary leaves a side with no way on", X[touch], hole_index);
  std::vector<std::vector<Index>> out;
  for (const auto& w : walks) {
    if (w.size() < 3) continue;
    if (area2(X, w) <= 0)
      throw PlanarFailure("convex decomposition: a hole that touches its boundary is not inside it", X[touch], hole_index);
    Index at = touch;
    if (!cut_pinches(X, w, others, h, &out, &at))
      throw PlanarFailure("convex decomposition: no cut edge joins a hole that touches its boundary at one node to the rest", X[at],
                          hole_index);
  }
  return out;
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
  // 1. holes: each splits the simple piece holding it in two; a hole that touches a piece (shares
  // a node or a side with it: a notch) joins that piece's boundary instead, and goes first
  std::vector<std::vector<Index>> simple{loops[0]};
  std::vector<std::size_t> left;  // holes not yet joined, in order
  for (std::size_t hi = 1; hi < loops.size(); ++hi) left.push_back(hi);
  while (!left.empty()) {
    std::size_t pick = 0, host = simple.size();
    for (std::size_t k = 0; k < left.size() && host == simple.size(); ++k)
      for (std::size_t s = 0; s < simple.size() && host == simple.size(); ++s)
        if (shares_node(simple[s], loops[left[k]]) && holds(X, simple[s], loops[left[k]])) pick = k, host = s;
    const std::size_t hi = left[pick];
    left.erase(left.begin() + static_cast<std::ptrdiff_t>(pick));
    const std::vector<Index>& hole = loops[hi];
    std::vector<std::vector<Index>> others;
    for (std::size_t k : left) others.push_back(loops[k]);
    if (host < simple.size()) {
      std::vector<std::vector<Index>> parts = join_touching(X, simple[host], hole, others, h, static_cast<int>(hi));
      simple.erase(simple.begin() + static_cast<std::ptrdiff_t>(host));
      for (auto& p : parts) simple.push_back(std::move(p));
      continue;
    }
    for (std::size_t s = 0; s < simple.size() && host == simple.size(); ++s)
      if (inside_loop(X, simple[s], X[hole[0]])) host = s;
    if (host == simple.size()) throw PlanarFailure("convex decomposition: a hole lies in no piece", X[hole[0]], static_cast<int>(hi));
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
    // the separator's nodes are made from the reflex vertex on, and split_loop takes them the
    // other way
    const std::vector<Index> mid = separator_nodes(X, l[reflex], l[bw], h);
    auto [p1, p2] = split_loop(l, reflex, bw, std::vector<Index>(mid.rbegin(), mid.rend()));
    simple.push_back(std::move(p1));
    simple.push_back(std::move(p2));
  }
  return out;
}

}  // namespace bisect::mesh2d
