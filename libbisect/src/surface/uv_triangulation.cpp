#include "surface/uv_triangulation.hpp"

#include <algorithm>
#include <string>

#include "bisect/errors.hpp"
#include "geom/predicates.hpp"

namespace bisect::surface {
namespace {

using geom::orient2d;

// incircle in the metric: the points mapped by T first (a floating-point test; the cavity is
// made star-shaped with exact orientation tests afterwards)
bool in_circle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, const Eigen::Matrix2d& T) {
  const Vec2 A = T * (a - d), B = T * (b - d), C = T * (c - d);
  const double det = (A.x() * A.x() + A.y() * A.y()) * (B.x() * C.y() - C.x() * B.y()) -
                     (B.x() * B.x() + B.y() * B.y()) * (A.x() * C.y() - C.x() * A.y()) +
                     (C.x() * C.x() + C.y() * C.y()) * (A.x() * B.y() - B.x() * A.y());
  return det > 0;
}

}  // namespace

unsigned UvTriangulation::new_stamp() {
  mark_.resize(tris.size(), 0);
  if (++stamp_ == 0) std::fill(mark_.begin(), mark_.end(), 0), stamp_ = 1;
  return stamp_;
}

void UvTriangulation::start(const Vec2& lo, const Vec2& hi) {
  const Vec2 mid = 0.5 * (lo + hi);
  const double span = std::max((hi - lo).maxCoeff(), 1e-300) * 64;
  uv = {mid + Vec2(-2 * span, -span), mid + Vec2(2 * span, -span), mid + Vec2(0, 2 * span)};
  tris.clear();
  tris.push_back({{0, 1, 2}, {-1, -1, -1}, 0, true, false});
  at_.assign(3, 0);
}

void UvTriangulation::link(Index t, int k, Index n, int j) {
  tris[t].nb[k] = n;
  if (n >= 0) tris[n].nb[j] = t;
}

int UvTriangulation::side_towards(Index t, Index n) const {
  for (int k = 0; k < 3; ++k)
    if (tris[t].nb[k] == n) return k;
  return -1;
}

Index UvTriangulation::add_tri(Index a, Index b, Index c) {
  tris.push_back({{a, b, c}, {-1, -1, -1}, 0, true, true});
  return static_cast<Index>(tris.size() - 1);
}

Index UvTriangulation::locate(const Vec2& p, Index start) const {
  Index t = start;
  if (t < 0 || t >= static_cast<Index>(tris.size()) || !tris[t].alive) {
    t = -1;
    for (std::size_t k = tris.size(); k-- > 0 && t < 0;)
      if (tris[k].alive) t = static_cast<Index>(k);
    if (t < 0) return -1;
  }
  // a stochastic walk: the edge tried first is drawn at random at every step, which ends in any
  // triangulation (a visibility walk in a fixed order may cycle in one that is not Delaunay in
  // the plane, as a triangulation Delaunay in a varying metric is not)
  const std::size_t limit = 64 + 2 * tris.size();
  std::uint64_t state = 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(t);
  for (std::size_t step = 0; step < limit; ++step) {
    const UvTri& T = tris[t];
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    const int rot = static_cast<int>(state % 3);
    bool moved = false;
    for (int i = 0; i < 3 && !moved; ++i) {
      const int k = (i + rot) % 3;
      if (orient2d(uv[T.v[(k + 1) % 3]], uv[T.v[(k + 2) % 3]], p) < 0) {
        if (T.nb[k] < 0) return -1;
        t = T.nb[k];
        moved = true;
      }
    }
    if (!moved) return t;
  }
  for (std::size_t k = 0; k < tris.size(); ++k) {
    const UvTri& T = tris[k];
    if (!T.alive) continue;
    if (orient2d(uv[T.v[0]], uv[T.v[1]], p) >= 0 && orient2d(uv[T.v[1]], uv[T.v[2]], p) >= 0 && orient2d(uv[T.v[2]], uv[T.v[0]], p) >= 0)
      return static_cast<Index>(k);
  }
  return -1;
}

Index UvTriangulation::insert(Index v, Index start, const Eigen::Matrix2d& T) {
  grow(uv.size());
  const Vec2& p = uv[v];
  const Index t0 = locate(p, start);
  if (t0 < 0) return -1;
  // on a point, or on a constrained edge: not inserted
  std::vector<Index> seed{t0};
  for (int k = 0; k < 3; ++k) {
    const UvTri& t = tris[t0];
    if (uv[t.v[k]] == p) return -1;
    if (orient2d(uv[t.v[(k + 1) % 3]], uv[t.v[(k + 2) % 3]], p) == 0) {
      if (t.held >> k & 1u) return -1;
      if (t.nb[k] >= 0) seed.push_back(t.nb[k]);
    }
  }
  const unsigned in_cavity = new_stamp();
  std::vector<Index> cavity = seed;
  for (Index s : seed) mark_[s] = in_cavity;
  for (std::size_t i = 0; i < cavity.size(); ++i) {
    const UvTri& t = tris[cavity[i]];
    for (int k = 0; k < 3; ++k) {
      const Index n = t.nb[k];
      if (n < 0 || mark_[n] == in_cavity || (t.held >> k & 1u) || tris[n].inside != tris[t0].inside) continue;
      const UvTri& u = tris[n];
      if (in_circle(uv[u.v[0]], uv[u.v[1]], uv[u.v[2]], p, T)) {
        cavity.push_back(n);
        mark_[n] = in_cavity;
      }
    }
  }
  // star-shaped from p: drop (non-seed) triangles with a boundary edge p does not see, then keep
  // what hangs together from the seeds, until nothing changes
  for (;;) {
    bool dropped = false;
    for (Index c : cavity) {
      if (mark_[c] != in_cavity || std::find(seed.begin(), seed.end(), c) != seed.end()) continue;
      const UvTri& t = tris[c];
      for (int k = 0; k < 3; ++k) {
        const Index n = t.nb[k];
        if (n >= 0 && mark_[n] == in_cavity) continue;
        if (orient2d(uv[t.v[(k + 1) % 3]], uv[t.v[(k + 2) % 3]], p) <= 0) {
          mark_[c] = 0;
          dropped = true;
          break;
        }
      }
    }
    if (!dropped) break;
    const unsigned reached = new_stamp();
    std::vector<Index> front = seed;
    for (Index s : seed) mark_[s] = reached;
    for (std::size_t i = 0; i < front.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        const Index n = tris[front[i]].nb[k];
        if (n < 0 || mark_[n] != in_cavity || (tris[front[i]].held >> k & 1u)) continue;
        mark_[n] = reached;
        front.push_back(n);
      }
    for (Index c : cavity)
      if (mark_[c] == in_cavity) mark_[c] = 0;
    for (Index c : front) mark_[c] = in_cavity;
    cavity = std::move(front);
  }
  // the cavity's boundary edges, each joined to p
  struct Edge {
    Index a, b, out;
    int out_k;
    bool held;
  };
  std::vector<Edge> edges;
  for (Index c : cavity) {
    const UvTri& t = tris[c];
    for (int k = 0; k < 3; ++k) {
      const Index n = t.nb[k];
      if (n >= 0 && mark_[n] == in_cavity) continue;
      const Index a = t.v[(k + 1) % 3], b = t.v[(k + 2) % 3];
      if (orient2d(uv[a], uv[b], p) <= 0) return -1;  // a seed edge p lies on (or cannot see): give up cleanly
      edges.push_back({a, b, n, n >= 0 ? side_towards(n, c) : -1, (t.held >> k & 1u) != 0});
    }
  }
  const bool inside = tris[t0].inside;
  std::vector<Index> fresh;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    Index id;
    if (i < cavity.size()) {
      id = cavity[i];
      tris[id] = {{edges[i].a, edges[i].b, v}, {-1, -1, -1}, 0, true, inside};
    } else {
      id = add_tri(edges[i].a, edges[i].b, v);
      tris[id].inside = inside;
    }
    fresh.push_back(id);
  }
  for (std::size_t i = edges.size(); i < cavity.size(); ++i) tris[cavity[i]].alive = false;
  mark_.resize(tris.size(), 0);
  // links: the edge (a, b) opposite p to the outside, (b, p) and (p, a) to each other
  std::vector<std::pair<Index, Index>> by_start;  // (a, triangle)
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Index id = fresh[i];
    link(id, 2, edges[i].out, edges[i].out_k);
    if (edges[i].held) tris[id].held |= 4u;
    by_start.push_back({edges[i].a, id});
    at_[edges[i].a] = id, at_[edges[i].b] = id;
  }
  std::sort(by_start.begin(), by_start.end());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    // the triangle whose edge starts at b follows this one round p: (b, p) is opposite a (k = 0)
    const Index b = edges[i].b;
    const auto it = std::lower_bound(by_start.begin(), by_start.end(), std::make_pair(b, Index(-1)));
    if (it == by_start.end() || it->first != b) continue;
    link(fresh[i], 0, it->second, 1);
  }
  at_[v] = fresh.front();
  return fresh.front();
}

void UvTriangulation::flip(Index t, int k) {
  const Index n = tris[t].nb[k];
  const int j = side_towards(n, t);
  const Index x = tris[t].v[k], y = tris[t].v[(k + 1) % 3], z = tris[t].v[(k + 2) % 3], w = tris[n].v[j];
  // outer neighbours and their constraint bits: t's edges (x y) opposite z, (z x) opposite y;
  // n's edges (z w) ... found by the corner opposite
  auto across = [&](Index tri, Index opp, Index* nb, bool* held) {
    const int c = static_cast<int>(std::find(tris[tri].v.begin(), tris[tri].v.end(), opp) - tris[tri].v.begin());
    *nb = tris[tri].nb[c];
    *held = (tris[tri].held >> c & 1u) != 0;
  };
  Index t_xy, t_zx, n_yw, n_wz;
  bool h_xy, h_zx, h_yw, h_wz;
  across(t, z, &t_xy, &h_xy);
  across(t, y, &t_zx, &h_zx);
  across(n, z, &n_yw, &h_yw);
  across(n, y, &n_wz, &h_wz);
  // t becomes (x, y, w), n becomes (x, w, z)
  tris[t].v = {x, y, w};
  tris[n].v = {x, w, z};
  tris[t].held = tris[n].held = 0;
  auto relink = [&](Index tri, int c, Index outer, bool held) {
    tris[tri].nb[c] = outer;
    if (held) tris[tri].held |= static_cast<unsigned char>(1u << c);
    if (outer >= 0)
      for (int q = 0; q < 3; ++q)
        if (tris[outer].nb[q] == t || tris[outer].nb[q] == n) {
          // the outer triangle's edge that this side now covers: its two corners are both in tri
          const Index a = tris[outer].v[(q + 1) % 3], b = tris[outer].v[(q + 2) % 3];
          const auto& V = tris[tri].v;
          if (std::find(V.begin(), V.end(), a) != V.end() && std::find(V.begin(), V.end(), b) != V.end()) tris[outer].nb[q] = tri;
        }
  };
  relink(t, 0, n_yw, h_yw);  // opposite x: (y, w)
  relink(t, 2, t_xy, h_xy);  // opposite w: (x, y)
  relink(n, 1, t_zx, h_zx);  // opposite w: (z, x)
  relink(n, 0, n_wz, h_wz);  // opposite x: (w, z)
  tris[t].nb[1] = n;          // opposite y: (w, x)
  tris[n].nb[2] = t;          // opposite z: (x, w)
  at_[x] = t, at_[y] = t, at_[w] = t, at_[z] = n;
}

void UvTriangulation::constrain(Index a, Index b) {
  auto find_edge = [&](Index u, Index w, Index* tri, int* k) {
    // rotate round u from a triangle that uses it
    Index t = at_[u];
    if (t < 0 || !tris[t].alive || std::find(tris[t].v.begin(), tris[t].v.end(), u) == tris[t].v.end()) {
      t = -1;
      for (std::size_t s = 0; s < tris.size() && t < 0; ++s)
        if (tris[s].alive && std::find(tris[s].v.begin(), tris[s].v.end(), u) != tris[s].v.end()) t = static_cast<Index>(s);
    }
    for (int dir = 0; dir < 2 && t >= 0; ++dir) {
      Index cur = t;
      for (std::size_t steps = 0; steps < tris.size() + 1; ++steps) {
        const auto& V = tris[cur].v;
        const int i = static_cast<int>(std::find(V.begin(), V.end(), u) - V.begin());
        for (int c = 0; c < 3; ++c)
          if (c != i && V[c] == w) {
            *tri = cur, *k = 3 - i - c;  // the corner that is neither u nor w
            return true;
          }
        const Index next = tris[cur].nb[dir == 0 ? (i + 1) % 3 : (i + 2) % 3];
        if (next < 0 || next == t) break;
        cur = next;
      }
    }
    return false;
  };
  auto mark = [&](Index t, int k) {
    tris[t].held |= static_cast<unsigned char>(1u << k);
    const Index n = tris[t].nb[k];
    if (n >= 0) tris[n].held |= static_cast<unsigned char>(1u << side_towards(n, t));
  };
  Index t = -1;
  int k = -1;
  if (find_edge(a, b, &t, &k)) return mark(t, k);
  const Vec2 &A = uv[a], &B = uv[b];
  auto crosses = [&](Index u, Index w) {
    const int su = orient2d(A, B, uv[u]), sw = orient2d(A, B, uv[w]);
    return su * sw < 0 && orient2d(uv[u], uv[w], A) * orient2d(uv[u], uv[w], B) < 0;
  };
  // the edges the segment crosses, found by walking from a
  std::vector<std::pair<Index, Index>> crossing;
  for (std::size_t s = 0; s < tris.size(); ++s) {
    const UvTri& T = tris[s];
    if (!T.alive) continue;
    for (int c = 0; c < 3; ++c) {
      const Index u = T.v[(c + 1) % 3], w = T.v[(c + 2) % 3];
      if (u < w && crosses(u, w)) crossing.push_back({u, w});
      if (u != a && u != b && orient2d(A, B, uv[u]) == 0 && (uv[u] - A).dot(B - A) > 0 && (uv[u] - B).dot(A - B) > 0)
        throw MeshingError("surface region: a boundary point lies on the boundary segment between two others (the loops touch)");
    }
  }
  std::sort(crossing.begin(), crossing.end());
  crossing.erase(std::unique(crossing.begin(), crossing.end()), crossing.end());
  std::size_t guard = 0;
  while (!crossing.empty()) {
    if (++guard > 64 * (crossing.size() + 16) + tris.size()) throw MeshingError("surface region: a boundary segment cannot be recovered");
    const auto [u, w] = crossing.front();
    crossing.erase(crossing.begin());
    Index ft = -1;
    int fk = -1;
    if (!find_edge(u, w, &ft, &fk)) continue;
    if (tris[ft].held >> fk & 1u) throw MeshingError("surface region: two boundary segments cross");
    const Index n = tris[ft].nb[fk];
    if (n < 0) continue;
    const Index x = tris[ft].v[fk], y = tris[n].v[side_towards(n, ft)];
    // convex quadrilateral x u y w (either order): both new triangles positive
    const Index p = tris[ft].v[(fk + 1) % 3], q = tris[ft].v[(fk + 2) % 3];
    if (orient2d(uv[x], uv[p], uv[y]) <= 0 || orient2d(uv[x], uv[y], uv[q]) <= 0) {
      crossing.push_back({u, w});
      continue;
    }
    flip(ft, fk);
    if (crosses(std::min(x, y), std::max(x, y))) crossing.push_back({std::min(x, y), std::max(x, y)});
  }
  if (!find_edge(a, b, &t, &k)) throw MeshingError("surface region: a boundary segment cannot be recovered");
  mark(t, k);
}

std::vector<Index> UvTriangulation::fan(Index v) const {
  std::vector<Index> out;
  Index t = v < static_cast<Index>(at_.size()) ? at_[v] : -1;
  if (t < 0 || !tris[t].alive || std::find(tris[t].v.begin(), tris[t].v.end(), v) == tris[t].v.end()) {
    t = -1;
    for (std::size_t s = 0; s < tris.size() && t < 0; ++s)
      if (tris[s].alive && std::find(tris[s].v.begin(), tris[s].v.end(), v) != tris[s].v.end()) t = static_cast<Index>(s);
    if (t < 0) return out;
  }
  for (int dir = 0; dir < 2; ++dir) {
    Index cur = t;
    for (std::size_t steps = 0; steps <= tris.size(); ++steps) {
      if (dir == 0 || cur != t) out.push_back(cur);
      const auto& V = tris[cur].v;
      const int i = static_cast<int>(std::find(V.begin(), V.end(), v) - V.begin());
      const Index next = tris[cur].nb[dir == 0 ? (i + 1) % 3 : (i + 2) % 3];
      if (next < 0) break;
      if (next == t) return out;  // closed round v
      cur = next;
    }
  }
  return out;
}

void UvTriangulation::mark_inside() {
  std::vector<int> depth(tris.size(), -1);
  std::vector<Index> queue;
  for (std::size_t t = 0; t < tris.size(); ++t)
    if (tris[t].alive && (tris[t].v[0] < 3 || tris[t].v[1] < 3 || tris[t].v[2] < 3)) depth[t] = 0, queue.push_back(static_cast<Index>(t));
  // breadth by depth: all of depth d before d + 1
  for (int d = 0; !queue.empty(); ++d) {
    std::vector<Index> next;
    for (std::size_t i = 0; i < queue.size(); ++i) {
      const Index t = queue[i];
      for (int k = 0; k < 3; ++k) {
        const Index n = tris[t].nb[k];
        if (n < 0 || depth[n] >= 0) continue;
        if (tris[t].held >> k & 1u) {
          next.push_back(n);
        } else {
          depth[n] = d;
          queue.push_back(n);
        }
      }
    }
    std::vector<Index> fresh;
    for (Index n : next)
      if (depth[n] < 0) depth[n] = d + 1, fresh.push_back(n);
    queue = std::move(fresh);
  }
  for (std::size_t t = 0; t < tris.size(); ++t) tris[t].inside = tris[t].alive && depth[t] % 2 == 1;
}

}  // namespace bisect::surface
