#include "mesh2d/bisect2d.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "bisect/errors.hpp"
#include "geom/predicates.hpp"
#include "mesh2d/loop_geometry.hpp"
#include "mesh2d/planar_failure.hpp"
#include "mesh2d/tri_quality.hpp"

namespace bisect::mesh2d {
namespace {

using geom::orient2d;

struct Work {
  std::vector<Index> loop, inside;
};

bool proper_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const int o1 = orient2d(a, b, c), o2 = orient2d(a, b, d), o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  return o1 * o2 < 0 && o3 * o4 < 0;
}

// Whether segment p q (between loop nodes or inside nodes) stays inside the loop: it crosses
// no loop edge, passes through no loop node, and leaves p into the interior when p is a loop node.
bool segment_inside(const std::vector<Vec2>& X, const std::vector<Index>& loop, Index p, Index q) {
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Index a = loop[i], b = loop[(i + 1) % n];
    if (a == p || a == q || b == p || b == q) continue;
    if (proper_cross(X[p], X[q], X[a], X[b])) return false;
  }
  for (Index a : loop)  // a loop node on the segment (a spike along the loop's own edges)
    if (a != p && a != q && orient2d(X[p], X[q], X[a]) == 0 && (X[a] - X[p]).dot(X[a] - X[q]) < 0) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (loop[i] != p) continue;
    const Vec2 &prev = X[loop[(i + n - 1) % n]], &v = X[p], &next = X[loop[(i + 1) % n]];
    const Vec2& w = X[q];
    // inside the interior angle at v (counter-clockwise from v->next to v->prev)
    if (orient2d(prev, v, next) > 0) {
      if (!(orient2d(v, next, w) > 0 && orient2d(prev, v, w) > 0)) return false;
    } else if (orient2d(v, next, w) <= 0 && orient2d(prev, v, w) <= 0) {
      return false;
    }
  }
  return true;
}

double loop_spacing(const std::vector<Vec2>& X, const std::vector<Index>& loop) {
  double s = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) s += (X[loop[i]] - X[loop[(i + 1) % loop.size()]]).norm();
  return s / static_cast<double>(loop.size());
}

// Splits w along the path from loop[i] to loop[j] through the given inside nodes, when valid.
bool split_along(const std::vector<Vec2>& X, const Work& w, std::size_t i, std::size_t j, const std::vector<Index>& via,
                 Work* a, Work* b) {
  const std::size_t n = w.loop.size();
  std::vector<Index> path{w.loop[i]};
  path.insert(path.end(), via.begin(), via.end());
  path.push_back(w.loop[j]);
  for (std::size_t k = 0; k + 1 < path.size(); ++k)
    if (!segment_inside(X, w.loop, path[k], path[k + 1])) return false;
  a->loop.clear(), b->loop.clear(), a->inside.clear(), b->inside.clear();
  for (std::size_t k = i; k != j; k = (k + 1) % n) a->loop.push_back(w.loop[k]);
  a->loop.push_back(w.loop[j]);
  for (std::size_t k = via.size(); k-- > 0;) a->loop.push_back(via[k]);
  for (std::size_t k = j; k != i; k = (k + 1) % n) b->loop.push_back(w.loop[k]);
  b->loop.push_back(w.loop[i]);
  b->loop.insert(b->loop.end(), via.begin(), via.end());
  // the other inside nodes go to the part that holds them (exact crossing parity on loop a)
  for (Index p : w.inside) {
    if (std::find(via.begin(), via.end(), p) != via.end()) continue;
    for (std::size_t k = 0; k + 1 < path.size(); ++k)  // a node on the new boundary: no split here
      if (orient2d(X[path[k]], X[path[k + 1]], X[p]) == 0 && (X[p] - X[path[k]]).dot(X[p] - X[path[k + 1]]) <= 0) return false;
    (inside_loop(X, a->loop, X[p]) ? a : b)->inside.push_back(p);
  }
  // both parts must run counter-clockwise (a path leaving the polygon would turn one over)
  auto area2 = [&](const std::vector<Index>& l) {
    double s2 = 0;
    for (std::size_t k = 0; k < l.size(); ++k) {
      const Vec2 &u = X[l[k]], &v = X[l[(k + 1) % l.size()]];
      s2 += u.x() * v.y() - u.y() * v.x();
    }
    return s2;
  };
  // and neither may be flat: a rounded area of collinear nodes can come out positive, so count
  // exactly convex corners too (a polygon with area has three or more)
  auto flat = [&](const std::vector<Index>& l) {
    int convex = 0;
    for (std::size_t k = 0; k < l.size() && convex < 3; ++k)
      convex += orient2d(X[l[(k + l.size() - 1) % l.size()]], X[l[k]], X[l[(k + 1) % l.size()]]) > 0;
    return convex < 3;
  };
  if (area2(a->loop) <= 0 || area2(b->loop) <= 0 || flat(a->loop) || flat(b->loop)) return false;
  return a->loop.size() >= 3 && b->loop.size() >= 3;
}

// 4.3.3: cut off the vertex whose triangle has the largest smallest angle and holds nothing.
bool remove_vertex(const std::vector<Vec2>& X, Work& w, std::vector<std::array<Index, 3>>& tris) {
  const std::size_t n = w.loop.size();
  int best = -1;
  double best_angle = -1;
  for (std::size_t k = 0; k < n; ++k) {
    const Index a = w.loop[(k + n - 1) % n], v = w.loop[k], b = w.loop[(k + 1) % n];
    if (orient2d(X[a], X[v], X[b]) <= 0) continue;
    bool empty = true;
    for (Index p : w.inside) empty &= !(orient2d(X[a], X[v], X[p]) >= 0 && orient2d(X[v], X[b], X[p]) >= 0 && orient2d(X[b], X[a], X[p]) >= 0);
    for (Index p : w.loop)
      if (p != a && p != v && p != b)
        empty &= !(orient2d(X[a], X[v], X[p]) >= 0 && orient2d(X[v], X[b], X[p]) >= 0 && orient2d(X[b], X[a], X[p]) >= 0);
    if (!empty || (n > 3 && !segment_inside(X, w.loop, a, b))) continue;
    const double ang = min_angle_deg(X[a], X[v], X[b]);
    if (ang > best_angle) best_angle = ang, best = static_cast<int>(k);
  }
  if (best < 0) return false;
  const Index a = w.loop[(best + n - 1) % n], v = w.loop[best], b = w.loop[(best + 1) % n];
  tris.push_back({a, v, b});
  w.loop.erase(w.loop.begin() + best);
  return true;
}

// A triangle with nodes inside: join two corners to the inside node that makes the best triangle
// holding no other inside node.
bool split_triangle(const std::vector<Vec2>& X, Work& w, std::vector<std::array<Index, 3>>& tris) {
  std::vector<std::tuple<double, int, Index>> cands;  // smallest angle, corner, node
  for (int k = 0; k < 3; ++k)
    for (Index p : w.inside)
      if (orient2d(X[w.loop[k]], X[w.loop[(k + 1) % 3]], X[p]) > 0)
        cands.emplace_back(min_angle_deg(X[w.loop[k]], X[w.loop[(k + 1) % 3]], X[p]), k, p);
  std::sort(cands.rbegin(), cands.rend());
  for (const auto& [angle, k, p] : cands) {
    const Index a = w.loop[k], b = w.loop[(k + 1) % 3], c = w.loop[(k + 2) % 3];
    bool empty = true;
    for (Index q : w.inside)
      if (q != p && orient2d(X[a], X[b], X[q]) >= 0 && orient2d(X[b], X[p], X[q]) >= 0 && orient2d(X[p], X[a], X[q]) >= 0) empty = false;
    if (!empty) continue;
    tris.push_back({a, b, p});
    w.loop = {b, c, a, p};
    w.inside.erase(std::find(w.inside.begin(), w.inside.end(), p));
    return true;
  }
  return false;
}

// The last resort when neither a split line nor a vertex removal works (a long thin region whose
// nodes all sit on lines, a triangle whose inside node is on a corner's line): cut one triangle
// off a loop edge with the node that sees the edge under the largest angle, as a constrained
// Delaunay triangulation would, which leaves the triangle empty. The rest is one or two loops.
bool grow_from_edge(const std::vector<Vec2>& X, const Work& w, std::vector<std::array<Index, 3>>& tris, std::vector<Work>& stack) {
  const std::size_t n = w.loop.size();
  std::vector<std::pair<double, std::size_t>> edges;  // shortest edges first
  for (std::size_t i = 0; i < n; ++i) edges.push_back({(X[w.loop[(i + 1) % n]] - X[w.loop[i]]).squaredNorm(), i});
  std::sort(edges.begin(), edges.end());
  for (const auto& [len2, i] : edges) {
    const Index a = w.loop[i], b = w.loop[(i + 1) % n];
    std::vector<std::pair<double, Index>> cands;  // angle a p b, node
    auto consider = [&](Index p) {
      if (p == a || p == b || orient2d(X[a], X[b], X[p]) <= 0) return;
      const Vec2 u = X[a] - X[p], v = X[b] - X[p];
      cands.push_back({std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v)), p});
    };
    for (Index p : w.loop) consider(p);
    for (Index p : w.inside) consider(p);
    std::sort(cands.rbegin(), cands.rend());
    for (const auto& [angle, p] : cands) {
      if (!segment_inside(X, w.loop, a, p) || !segment_inside(X, w.loop, p, b)) continue;
      bool empty = true;  // nothing inside the triangle or on its two new sides
      auto blocks = [&](Index q) {
        if (q == a || q == b || q == p) return false;
        return orient2d(X[a], X[b], X[q]) > 0 && orient2d(X[b], X[p], X[q]) >= 0 && orient2d(X[p], X[a], X[q]) >= 0;
      };
      for (Index q : w.loop) empty = empty && !blocks(q);
      for (Index q : w.inside) empty = empty && !blocks(q);
      if (!empty) continue;
      tris.push_back({a, b, p});
      const auto at = std::find(w.loop.begin(), w.loop.end(), p);
      if (at == w.loop.end()) {  // an inside node: it joins the loop between a and b
        Work rest;
        rest.loop = w.loop;
        rest.loop.insert(rest.loop.begin() + static_cast<std::ptrdiff_t>(i + 1), p);
        for (Index q : w.inside)
          if (q != p) rest.inside.push_back(q);
        stack.push_back(std::move(rest));
        return true;
      }
      // a loop node: b .. p and p .. a remain, each with the inside nodes it holds
      const std::size_t k = static_cast<std::size_t>(at - w.loop.begin());
      Work one, two;
      for (std::size_t j = (i + 1) % n;; j = (j + 1) % n) {
        one.loop.push_back(w.loop[j]);
        if (j == k) break;
      }
      for (std::size_t j = k;; j = (j + 1) % n) {
        two.loop.push_back(w.loop[j]);
        if (j == i) break;
      }
      for (Index q : w.inside) (one.loop.size() >= 3 && inside_loop(X, one.loop, X[q]) ? one : two).inside.push_back(q);
      if (one.loop.size() >= 3) stack.push_back(std::move(one));
      if (two.loop.size() >= 3) stack.push_back(std::move(two));
      return true;
    }
  }
  return false;
}

}  // namespace

void bisection_triangulate(const std::vector<Vec2>& X, const std::vector<Index>& loop, const std::vector<Index>& inside,
                           std::vector<std::array<Index, 3>>& tris) {
  // a failure is placed at the middle of the piece's boundary nodes
  auto centre = [&](const Work& w) {
    Vec2 c = Vec2::Zero();
    for (Index v : w.loop) c += X[v];
    return Vec2(c / static_cast<double>(std::max<std::size_t>(w.loop.size(), 1)));
  };
  std::vector<Work> stack{{loop, inside}};
  while (!stack.empty()) {
    Work w = std::move(stack.back());
    stack.pop_back();
    const std::size_t n = w.loop.size();
    if (n < 3) throw PlanarFailure("recursive bisection: a piece with fewer than three boundary nodes", centre(w));
    if (n == 3 && w.inside.empty()) {
      if (orient2d(X[w.loop[0]], X[w.loop[1]], X[w.loop[2]]) <= 0) throw PlanarFailure("recursive bisection: a flat triangle", centre(w));
      tris.push_back({w.loop[0], w.loop[1], w.loop[2]});
      continue;
    }
    if (n == 3) {
      if (split_triangle(X, w, tris)) {
        stack.push_back(std::move(w));
      } else if (!grow_from_edge(X, w, tris, stack)) {
        throw PlanarFailure("recursive bisection: a triangle with nodes inside cannot be split", centre(w));
      }
      continue;
    }
    // 4.3.1: candidate lines between nearly opposite boundary nodes, the best weight wins
    const double half_spacing = 0.5 * loop_spacing(X, w.loop);
    struct Candidate {
      double weight;
      std::size_t i, j;
      std::vector<Index> via;
    };
    std::vector<Candidate> candidates;
    const std::size_t starts = std::min<std::size_t>(n, 12);
    for (std::size_t s = 0; s < starts; ++s) {
      const std::size_t i = s * n / starts;
      for (int off = -2; off <= 2; ++off) {
        const std::size_t j = (i + n / 2 + n + static_cast<std::size_t>(off + 2) - 2) % n;
        if (j == i || (j + 1) % n == i || (i + 1) % n == j) continue;
        const Vec2 p = X[w.loop[i]], q = X[w.loop[j]], d = (q - p);
        const double len = d.norm();
        if (len <= 0) continue;
        const Vec2 u = d / len;
        // E: half the spacing, or the distance of the nearest inside node within the rectangle
        double E = half_spacing;
        std::vector<std::pair<double, Index>> near;
        for (Index v : w.inside) {
          const Vec2 r = X[v] - p;
          const double t = r.dot(u), dist = std::abs(u.x() * r.y() - u.y() * r.x());
          if (t <= 0 || t >= len) continue;
          if (dist < half_spacing) near.push_back({t, v});  // 4.3.2: joins the new boundary
          else E = std::min(E, dist);
        }
        std::sort(near.begin(), near.end());
        Candidate c{0, i, j, {}};
        for (const auto& [t, v] : near) c.via.push_back(v);
        std::size_t count = 0;
        for (std::size_t k = 0; k < n; ++k) {
          if (k == i || k == j) continue;
          const Vec2 r = X[w.loop[k]] - p;
          c.weight += std::log(std::max(std::abs(u.x() * r.y() - u.y() * r.x()), 1e-300));
          ++count;
        }
        c.weight += static_cast<double>(count) * std::log(E);
        candidates.push_back(std::move(c));
      }
    }
    // the heaviest line that gives a valid split (validation costs more than weighing)
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) { return x.weight > y.weight; });
    bool split = false;
    for (const Candidate& c : candidates) {
      Work a, b;
      if (!split_along(X, w, c.i, c.j, c.via, &a, &b)) continue;
      stack.push_back(std::move(a));
      stack.push_back(std::move(b));
      split = true;
      break;
    }
    if (split) continue;
    // 4.3.3: a domain of peculiarity. Lines from a boundary node to its next but one, the one
    // cutting off the best triangle first, inside nodes near the line joining the split.
    std::vector<std::pair<double, std::size_t>> ears;
    for (std::size_t k = 0; k < n; ++k) {
      const Index a = w.loop[(k + n - 1) % n], v = w.loop[k], b = w.loop[(k + 1) % n];
      if (orient2d(X[a], X[v], X[b]) > 0) ears.push_back({min_angle_deg(X[a], X[v], X[b]), k});
    }
    std::sort(ears.rbegin(), ears.rend());
    for (const auto& [angle, k] : ears) {
      const std::size_t i = (k + n - 1) % n, j = (k + 1) % n;
      const Vec2 p = X[w.loop[i]], q = X[w.loop[j]];
      const double len = (q - p).norm();
      if (len <= 0) continue;
      const Vec2 u = (q - p) / len;
      std::vector<std::pair<double, Index>> near;
      for (Index v : w.inside) {
        const Vec2 r = X[v] - p;
        const double t = r.dot(u), dist = std::abs(u.x() * r.y() - u.y() * r.x());
        if (t > 0 && t < len && dist < half_spacing) near.push_back({t, v});
      }
      std::sort(near.begin(), near.end());
      std::vector<Index> via;
      for (const auto& [t, v] : near) via.push_back(v);
      Work a, b;
      if (!split_along(X, w, i, j, via, &a, &b)) continue;
      stack.push_back(std::move(a));
      stack.push_back(std::move(b));
      split = true;
      break;
    }
    if (split) continue;
    if (remove_vertex(X, w, tris)) {
      stack.push_back(std::move(w));
    } else if (!grow_from_edge(X, w, tris, stack)) {
      throw PlanarFailure("recursive bisection: a piece of " + std::to_string(w.loop.size()) +
                              " nodes with no split and no removable vertex",
                          centre(w));
    }
  }
}

}  // namespace bisect::mesh2d
