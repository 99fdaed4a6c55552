#include "tet/face_recovery.hpp"

#include <algorithm>
#include <set>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "geom/predicates.hpp"

namespace bisect::tet {
namespace {

using geom::orient3d;
using Edge = std::pair<Index, Index>;
Edge edge_of(Index a, Index b) { return std::minmax(a, b); }

// The faces and edges of dt's live tetrahedra, counted, kept in step with dt through its
// `touched` log: after a change only the tetrahedra replace() took out or made are looked at.
// (Read again in full after every change, it took a quarter of flange.brep's time at 10^6,
// whose large cells are filled by recovery: a scan of the cell per restored triangle.)
class Present {
 public:
  explicit Present(TetComplex& dt) : dt_(dt), outer_(dt.touched) {
    for (std::size_t t = 0; t < dt.tet.size(); ++t)
      if (dt.alive[t]) take(static_cast<Index>(t), +1);
    dt.touched = &touched_;
  }
  ~Present() {
    if (outer_) outer_->insert(outer_->end(), touched_.begin(), touched_.end());  // what was not synced yet
    dt_.touched = outer_;
  }
  Present(const Present&) = delete;
  Present& operator=(const Present&) = delete;
  bool has_face(Index a, Index b, Index c) {
    sync();
    return faces_.count(face_key(a, b, c)) > 0;
  }
  bool has_edge(Index a, Index b) {
    sync();
    return edges_.count(edge_of(a, b)) > 0;
  }

 private:
  // tetrahedron t as last seen counted in (+1) or out (-1)
  void take(Index t, int sign) {
    if (static_cast<std::size_t>(t) >= seen_.size()) seen_.resize(t + 1), counted_.resize(t + 1, 0);
    if (sign > 0) seen_[t] = dt_.tet[t];
    const Tet& q = seen_[t];
    for (int f = 0; f < 4; ++f) bump(faces_, face_key(q[(f + 1) % 4], q[(f + 2) % 4], q[(f + 3) % 4]), sign);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) bump(edges_, edge_of(q[i], q[j]), sign);
    counted_[t] = sign > 0;
  }
  template <typename Map, typename Key>
  static void bump(Map& m, const Key& k, int sign) {
    auto it = m.try_emplace(k, 0).first;
    if ((it->second += sign) == 0) m.erase(it);
  }
  void sync() {
    if (touched_.empty()) return;
    if (outer_) outer_->insert(outer_->end(), touched_.begin(), touched_.end());
    std::sort(touched_.begin(), touched_.end());
    touched_.erase(std::unique(touched_.begin(), touched_.end()), touched_.end());
    for (Index t : touched_) {
      if (static_cast<std::size_t>(t) < counted_.size() && counted_[t]) take(t, -1);
      if (dt_.alive[t]) take(t, +1);
    }
    touched_.clear();
  }
  struct EdgeHash {
    std::size_t operator()(const Edge& e) const { return static_cast<std::size_t>(e.first) * 73856093u ^ static_cast<std::size_t>(e.second); }
  };
  TetComplex& dt_;
  std::vector<Index>* outer_;
  std::vector<Index> touched_;
  std::vector<Tet> seen_;
  std::vector<char> counted_;
  std::unordered_map<FaceKey, int, FaceKeyHash> faces_;
  std::unordered_map<Edge, int, EdgeHash> edges_;
};

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
      if (dt.neighbour(t, f) < 0 || !in.count(dt.neighbour(t, f))) out.push_back(dt.face(t, f));
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
  Present p(dt);
  std::vector<std::array<Index, 3>> missing;
  for (const auto& t : wanted)
    if (!p.has_face(t[0], t[1], t[2])) missing.push_back(t);
  // Rounds over the missing triangles, each change made at once (and what is present read
  // again), until a round changes nothing: a change can make way for a triangle that failed
  // earlier in the round, and the next round tries it again. Each attempt scans the complex, so
  // the rounds are bounded too.
  for (int round = 0; round < 8 && !missing.empty(); ++round) {
    bool changed = false;
    std::vector<std::array<Index, 3>> left;
    for (const auto& t : missing) {
      if (p.has_face(t[0], t[1], t[2])) continue;  // restored by an earlier change
      bool done = false, edges = true;
      for (int i = 0; i < 3; ++i)
        if (!p.has_edge(t[i], t[(i + 1) % 3])) {
          edges = false;
          if (recover_edge(dt, t[i], t[(i + 1) % 3])) done = true;
          break;  // one edge at a time: the next round sees the others
        }
      if (edges) done = recover_triangle(dt, t);
      if (done) changed = true;
      if (!p.has_face(t[0], t[1], t[2])) left.push_back(t);
    }
    missing = std::move(left);
    if (!changed) break;
  }
  return missing.size();
}

}  // namespace bisect::tet
