#include "tet/face_recovery.hpp"

#include <algorithm>
#include <set>
#include <unordered_set>
#include <utility>

#include "geom/predicates.hpp"

namespace bisect::tet {
namespace {

using geom::orient3d;
using Edge = std::pair<Index, Index>;
Edge edge_of(Index a, Index b) { return std::minmax(a, b); }

struct Present {
  std::unordered_set<FaceKey, FaceKeyHash> faces;
  std::set<Edge> edges;
};

Present present(const TetComplex& dt) {
  Present p;
  for (std::size_t t = 0; t < dt.tet.size(); ++t) {
    if (!dt.alive[t]) continue;
    const Tet& q = dt.tet[t];
    for (int f = 0; f < 4; ++f) {
      const auto fc = dt.face(static_cast<Index>(t), f);
      p.faces.insert(face_key(fc[0], fc[1], fc[2]));
    }
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) p.edges.insert(edge_of(q[i], q[j]));
  }
  return p;
}

// Segment pq, its ends on either side of the plane abc, meets the closed triangle abc in its
// interior or on an edge (a flat square's other diagonal meets the one it has on that edge:
// then every tetrahedron at the edge is pierced, and each has a face that says so); through a
// corner, `degenerate` is set.
bool crosses(const std::vector<Vec3>& X, Index p, Index q, Index a, Index b, Index c, bool* degenerate) {
  const int sp = orient3d(X[a], X[b], X[c], X[p]), sq = orient3d(X[a], X[b], X[c], X[q]);
  if (sp == 0 || sq == 0 || sp == sq) return false;
  const int s1 = orient3d(X[p], X[q], X[a], X[b]), s2 = orient3d(X[p], X[q], X[b], X[c]), s3 = orient3d(X[p], X[q], X[c], X[a]);
  const bool nonneg = s1 >= 0 && s2 >= 0 && s3 >= 0, nonpos = s1 <= 0 && s2 <= 0 && s3 <= 0;
  if (!nonneg && !nonpos) return false;
  const int zeros = (s1 == 0) + (s2 == 0) + (s3 == 0);
  if (zeros >= 2) *degenerate = true;
  return zeros <= 1;
}

// The hole's faces, each turned out of the hole (as face() of the tetrahedron taken out gives).
std::vector<std::array<Index, 3>> hole_faces(const TetComplex& dt, const std::vector<Index>& cavity) {
  std::unordered_set<Index> in(cavity.begin(), cavity.end());
  std::vector<std::array<Index, 3>> out;
  for (Index t : cavity)
    for (int f = 0; f < 4; ++f)
      if (dt.nb[t][f] < 0 || !in.count(dt.nb[t][f])) out.push_back(dt.face(t, f));
  return out;
}

// The fan from apex v over the faces that do not hold v; empty when v does not see one of them
// from inside (every face must turn away from v).
bool fan(const std::vector<Vec3>& X, Index v, const std::vector<std::array<Index, 3>>& faces, std::vector<Tet>* out) {
  std::vector<Tet> made;
  for (const auto& f : faces) {
    if (f[0] == v || f[1] == v || f[2] == v) continue;
    if (orient3d(X[f[0]], X[f[1]], X[f[2]], X[v]) >= 0) return false;
    made.push_back({f[0], f[2], f[1], v});  // v behind the face: this order is positive
  }
  out->insert(out->end(), made.begin(), made.end());
  return true;
}

double volume6(const std::vector<Vec3>& X, const Tet& t) {
  return (X[t[1]] - X[t[0]]).dot((X[t[2]] - X[t[0]]).cross(X[t[3]] - X[t[0]]));
}

// Whether `fresh` fills the hole exactly: every new face meets another new one turned the other
// way or is one of the hole's faces, each of those met once, and the volumes agree.
bool fills(const TetComplex& dt, const std::vector<Index>& cavity, const std::vector<Tet>& fresh) {
  const std::vector<std::array<Index, 3>> hole = hole_faces(dt, cavity);
  std::multiset<std::array<Index, 3>> open;  // new faces not yet matched, turned out of their tetrahedron
  for (const Tet& t : fresh) {
    for (const auto& f : std::array<std::array<Index, 3>, 4>{{{t[1], t[2], t[3]}, {t[0], t[3], t[2]}, {t[0], t[1], t[3]}, {t[0], t[2], t[1]}}}) {
      const auto k = smallest_first(f);
      const auto back = smallest_first({f[0], f[2], f[1]});
      const auto it = open.find(back);
      if (it != open.end()) open.erase(it);
      else open.insert(k);
    }
  }
  if (open.size() != hole.size()) return false;
  for (const auto& f : hole) {
    const auto it = open.find(smallest_first(f));
    if (it == open.end()) return false;
    open.erase(it);
  }
  double before = 0, after = 0;
  for (Index t : cavity) before += volume6(dt.X, dt.tet[t]);
  for (const Tet& t : fresh) {
    const double v = volume6(dt.X, t);
    if (!(v > 0)) return false;
    after += v;
  }
  return std::abs(before - after) <= 1e-9 * before;
}

// Tetrahedra whose interior the open segment ab passes through (those with a face it crosses).
std::vector<Index> pierced_by_edge(const TetComplex& dt, Index a, Index b, bool* degenerate) {
  std::vector<Index> out;
  for (std::size_t t = 0; t < dt.tet.size(); ++t) {
    if (!dt.alive[t]) continue;
    for (int f = 0; f < 4; ++f) {
      const auto fc = dt.face(static_cast<Index>(t), f);
      if (std::count(fc.begin(), fc.end(), a) || std::count(fc.begin(), fc.end(), b)) continue;
      if (crosses(dt.X, a, b, fc[0], fc[1], fc[2], degenerate)) {
        out.push_back(static_cast<Index>(t));
        break;
      }
    }
  }
  return out;
}

// Tetrahedra with an edge that crosses the open triangle abc.
std::vector<Index> pierced_by_triangle(const TetComplex& dt, Index a, Index b, Index c, bool* degenerate) {
  std::vector<Index> out;
  for (std::size_t t = 0; t < dt.tet.size(); ++t) {
    if (!dt.alive[t]) continue;
    const Tet& q = dt.tet[t];
    bool hit = false;
    for (int i = 0; i < 4 && !hit; ++i)
      for (int j = i + 1; j < 4 && !hit; ++j) {
        const Index p = q[i], r = q[j];
        if (p == a || p == b || p == c || r == a || r == b || r == c) continue;
        hit = crosses(dt.X, p, r, a, b, c, degenerate);
      }
    if (hit) out.push_back(static_cast<Index>(t));
  }
  return out;
}

bool recover_edge(TetComplex& dt, Index a, Index b) {
  bool degenerate = false;
  const std::vector<Index> cavity = pierced_by_edge(dt, a, b, &degenerate);
  if (cavity.empty() || degenerate) return false;
  const std::vector<std::array<Index, 3>> hole = hole_faces(dt, cavity);
  for (Index apex : {a, b}) {
    std::vector<Tet> fresh;
    if (fan(dt.X, apex, hole, &fresh) && fills(dt, cavity, fresh)) {
      dt.replace(cavity, fresh);
      return true;
    }
  }
  return false;
}

bool recover_triangle(TetComplex& dt, const std::array<Index, 3>& tri) {
  const Index a = tri[0], b = tri[1], c = tri[2];
  bool degenerate = false;
  const std::vector<Index> cavity = pierced_by_triangle(dt, a, b, c, &degenerate);
  if (cavity.empty() || degenerate) return false;
  // the hole's faces on either side of the triangle's plane; one across it: no fan can do
  std::vector<std::array<Index, 3>> up, down;
  std::set<Index> up_nodes, down_nodes;
  for (const auto& f : hole_faces(dt, cavity)) {
    int pos = 0, neg = 0;
    for (Index v : f) {
      if (v == a || v == b || v == c) continue;
      const int s = orient3d(dt.X[a], dt.X[b], dt.X[c], dt.X[v]);
      pos += s > 0, neg += s < 0;
      if (s == 0) return false;
    }
    if (pos > 0 && neg > 0) return false;
    if (pos == 0 && neg == 0) return false;
    (pos > 0 ? up : down).push_back(f);
    for (Index v : f)
      if (v != a && v != b && v != c) (pos > 0 ? up_nodes : down_nodes).insert(v);
  }
  // the triangle closes each side: turned away from it (abc's normal points to the up side)
  up.push_back({a, c, b});
  down.push_back({a, b, c});
  std::vector<Tet> fresh;
  for (const auto& [faces, nodes] : {std::pair{&up, &up_nodes}, std::pair{&down, &down_nodes}}) {
    bool done = false;
    for (Index apex : *nodes) {
      std::vector<Tet> side;
      if (fan(dt.X, apex, *faces, &side)) {
        fresh.insert(fresh.end(), side.begin(), side.end());
        done = true;
        break;
      }
    }
    if (!done) return false;
  }
  if (!fills(dt, cavity, fresh)) return false;
  dt.replace(cavity, fresh);
  return true;
}

}  // namespace

std::size_t recover_faces(TetComplex& dt, const std::vector<std::array<Index, 3>>& wanted) {
  Present p = present(dt);
  std::vector<std::array<Index, 3>> missing;
  for (const auto& t : wanted)
    if (!p.faces.count(face_key(t[0], t[1], t[2]))) missing.push_back(t);
  // Rounds over the missing triangles, each change made at once (and what is present read
  // again), until a round changes nothing: a change can make way for a triangle that failed
  // earlier in the round, and the next round tries it again. Each attempt scans the complex, so
  // the rounds are bounded too.
  for (int round = 0; round < 8 && !missing.empty(); ++round) {
    bool changed = false;
    std::vector<std::array<Index, 3>> left;
    for (const auto& t : missing) {
      if (p.faces.count(face_key(t[0], t[1], t[2]))) continue;  // restored by an earlier change
      bool done = false, edges = true;
      for (int i = 0; i < 3; ++i)
        if (!p.edges.count(edge_of(t[i], t[(i + 1) % 3]))) {
          edges = false;
          if (recover_edge(dt, t[i], t[(i + 1) % 3])) done = true;
          break;  // one edge at a time: the next round sees the others
        }
      if (edges) done = recover_triangle(dt, t);
      if (done) {
        changed = true;
        p = present(dt);
      }
      if (!p.faces.count(face_key(t[0], t[1], t[2]))) left.push_back(t);
    }
    missing = std::move(left);
    if (!changed) break;
  }
  return missing.size();
}

}  // namespace bisect::tet
