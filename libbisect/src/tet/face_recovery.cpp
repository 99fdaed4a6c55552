#include "tet/face_recovery.hpp"

#include <algorithm>
#include <set>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "geom/predicates.hpp"
#include "geom/segment_triangle.hpp"
#include "tet/cell_fill.hpp"

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
  const int edges = geom::segment_through_triangle(X[p], X[q], X[a], X[b], X[c]);
  if (edges >= 2) *degenerate = true;
  return edges == 0 || edges == 1;
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

// Whether the open segment ab passes through tetrahedron q's interior (crosses one of its faces).
bool tet_pierced(const std::vector<Vec3>& X, const Tet& q, Index a, Index b, bool* degenerate) {
  for (int f = 0; f < 4; ++f) {
    const std::array<Index, 3> fc{q[(f + 1) % 4], q[(f + 2) % 4], q[(f + 3) % 4]};
    if (std::count(fc.begin(), fc.end(), a) || std::count(fc.begin(), fc.end(), b)) continue;
    if (crosses(X, a, b, fc[0], fc[1], fc[2], degenerate)) return true;
  }
  return false;
}

// Tetrahedra whose interior the open segment ab passes through (those with a face it crosses).
std::vector<Index> pierced_by_edge(const TetComplex& dt, Index a, Index b, bool* degenerate) {
  std::vector<Index> out;
  for (std::size_t t = 0; t < dt.tet.size(); ++t)
    if (dt.alive[t] && tet_pierced(dt.X, dt.tet[t], a, b, degenerate)) out.push_back(static_cast<Index>(t));
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

// The hole the open segment ab pierces, filled as a fan from a or from b.
bool recover_edge_by_fan(TetComplex& dt, Index a, Index b) {
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

// The wanted triangles and their edges: what the second phase's changes must not take out.
struct Held {
  std::unordered_set<FaceKey, FaceKeyHash> faces;
  std::set<Edge> edges;
};

// A missing edge ab whose hole no fan from a or b fills, brought closer by flips: a 2-3 flip
// across a face ab crosses, or the removal of an edge of such a face (its ring's best
// triangulation), kept when fewer tetrahedra are left in ab's way, until the fan fills what is
// left. Neither takes out a wanted triangle or an edge of one. Greedy and bounded, so an edge
// it cannot reach stays missing.
bool recover_edge_by_flips(TetComplex& dt, Index a, Index b, const Held& held) {
  constexpr int kSteps = 64;
  std::set<Edge> made_edges, gone_edges;  // what the level changes made and took out: not undone by a later one
  for (int step = 0; step < kSteps; ++step) {
    bool degenerate = false;
    const std::vector<Index> pierced = pierced_by_edge(dt, a, b, &degenerate);
    if (pierced.empty() || degenerate) return false;
    const std::size_t before = pierced.size();
    const std::set<Index> in_way(pierced.begin(), pierced.end());
    // Whether ab would pierce fewer tetrahedra after the change (level: no more), counted
    // before the change is made; made when so.
    auto trial = [&](const std::vector<Index>& old, const std::vector<Tet>& fresh, bool level) {
      std::size_t after = before;
      for (Index t : old) after -= in_way.count(t);
      for (const Tet& q : fresh) {
        bool deg = false;
        after += tet_pierced(dt.X, q, a, b, &deg);
        if (deg) return false;
      }
      if (level ? after > before : after >= before) return false;
      dt.replace(old, fresh);
      return true;
    };
    // A change that gets ab out of fewer tetrahedra is taken first; when there is none, one that
    // leaves as many (a way round a local minimum), never taking back an earlier level change.
    bool moved = false;
    for (const bool level : {false, true}) {
      std::set<Edge> tried;
      for (std::size_t i = 0; i < pierced.size() && !moved; ++i) {
        const Index t = pierced[i];
        for (int f = 0; f < 4 && !moved; ++f) {
          const auto fc = dt.face(t, f);
          if (std::count(fc.begin(), fc.end(), a) || std::count(fc.begin(), fc.end(), b)) continue;
          bool deg = false;
          if (!crosses(dt.X, a, b, fc[0], fc[1], fc[2], &deg) || deg) continue;
          const Index u = dt.neighbour(t, f);
          if (u < 0 || held.faces.count(face_key(fc[0], fc[1], fc[2]))) continue;
          const Edge across = edge_of(dt.tet[t][f], dt.tet[u][dt.neighbour_face(t, f)]);  // the edge a 2-3 flip makes
          std::vector<Tet> fresh;
          if (!(level && gone_edges.count(across)) && dt.flip23_unchecked(t, f, &fresh) && dt.positive_all(fresh) &&
              trial({t, u}, fresh, level)) {
            if (level) made_edges.insert(across);
            moved = true;
            break;
          }
          for (int k = 0; k < 3 && !moved; ++k) {
            const Edge e = edge_of(fc[k], fc[(k + 1) % 3]);
            if (held.edges.count(e) || (level && made_edges.count(e)) || !tried.insert(e).second) continue;
            std::array<Index, TetComplex::kMaxRing> ring, apex;
            bool closed = false, on_held = false;
            const int n = dt.edge_ring(t, e.first, e.second, static_cast<int>(TetComplex::kMaxRing), ring.data(), apex.data(),
                                       &closed, &on_held);
            if (!closed || on_held || n < 3 || n > static_cast<int>(TetComplex::kMaxRing)) continue;
            std::vector<Tet> tri;
            if (!dt.ring_triangulation(e.first, e.second, apex.data(), static_cast<std::size_t>(n), 0, &tri)) continue;
            moved = trial(std::vector<Index>(ring.begin(), ring.begin() + n), tri, level);
            if (moved && level) gone_edges.insert(e);
          }
        }
      }
      if (moved) break;
    }
    if (!moved) return false;
    if (recover_edge_by_fan(dt, a, b)) return true;
  }
  return false;
}

// A point added inside a hole (a Steiner point) when no node sees all of its faces (turned out
// of it): a point of its kernel, found from its nodes' centroid as a star fill's centre is
// (star_centre). Appended to *grow (the nodes dt.X refers to) and returned; -1 when the hole has
// no kernel.
Index steiner_point(TetComplex& dt, std::vector<Vec3>* grow, const std::vector<std::array<Index, 3>>& faces) {
  std::set<Index> nodes;
  for (const auto& f : faces) nodes.insert(f.begin(), f.end());
  Vec3 centroid = Vec3::Zero();
  for (Index v : nodes) centroid += dt.X[v];
  centroid /= static_cast<double>(nodes.size());
  Index node = -1;
  Vec3 point;
  if (!star_centre(dt.X, faces, {}, centroid, &node, &point)) return -1;
  grow->push_back(point);
  return static_cast<Index>(grow->size() - 1);
}

// A missing edge: the fan, then (with `held`, the second phase) the flips, then (with grow) the
// hole of the tetrahedra in its way fanned from a Steiner point and the two tried again (a fold
// such as Schönhardt's prism: no tetrahedralization of the nodes alone has the edge).
bool recover_edge(TetComplex& dt, Index a, Index b, const Held* held, std::vector<Vec3>* grow) {
  if (recover_edge_by_fan(dt, a, b)) return true;
  if (!held) return false;
  if (recover_edge_by_flips(dt, a, b, *held)) return true;
  if (!grow) return false;
  bool degenerate = false;
  const std::vector<Index> cavity = pierced_by_edge(dt, a, b, &degenerate);
  if (cavity.empty() || degenerate) return false;
  // the hole's fan takes out every face inside it: not when one is a wanted triangle already there
  const std::set<Index> in(cavity.begin(), cavity.end());
  for (Index t : cavity)
    for (int f = 0; f < 4; ++f) {
      const auto fc = dt.face(t, f);
      if (in.count(dt.neighbour(t, f)) && held->faces.count(face_key(fc[0], fc[1], fc[2]))) return false;
    }
  const std::vector<std::array<Index, 3>> hole = hole_faces(dt, cavity);
  const std::size_t had = grow->size();
  const Index s = steiner_point(dt, grow, hole);
  std::vector<Tet> fresh;
  if (s < 0 || !fan(dt.X, s, hole, &fresh) || !fills(dt, cavity, fresh)) {
    grow->resize(had);
    return false;
  }
  // the point stays when the edge still cannot be made: the complex is as valid with it (one
  // outside the cell goes with the outside's tetrahedra, recovery_fill)
  dt.replace(cavity, fresh);
  return recover_edge_by_fan(dt, a, b) || recover_edge_by_flips(dt, a, b, *held);
}

bool recover_triangle(TetComplex& dt, const std::array<Index, 3>& tri, std::vector<Vec3>* grow) {
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
  const std::size_t had = grow ? grow->size() : 0;
  auto give_up = [&] {
    if (grow) grow->resize(had);  // the Steiner points of this try are not used
    return false;
  };
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
    if (!done && grow) {
      const Index apex = steiner_point(dt, grow, *faces);
      std::vector<Tet> side;
      if (apex >= 0 && fan(dt.X, apex, *faces, &side)) {
        fresh.insert(fresh.end(), side.begin(), side.end());
        done = true;
      }
    }
    if (!done) return give_up();
  }
  if (!fills(dt, cavity, fresh)) return give_up();
  dt.replace(cavity, fresh);
  return true;
}

}  // namespace

std::size_t recover_faces(TetComplex& dt, const std::vector<std::array<Index, 3>>& wanted, std::vector<Vec3>* grow) {
  Present p(dt);
  std::vector<std::array<Index, 3>> missing;
  for (const auto& t : wanted)
    if (!p.has_face(t[0], t[1], t[2])) missing.push_back(t);
  // Rounds over the missing triangles, each change made at once (and what is present read
  // again), until a round changes nothing: a change can make way for a triangle that failed
  // earlier in the round, and the next round tries it again. Each attempt scans the complex, so
  // the rounds are bounded too. The second phase (flips, Steiner points), when allowed, only in
  // rounds after those without have done what they can.
  Held held;
  if (grow)
    for (const auto& t : wanted) {
      held.faces.insert(face_key(t[0], t[1], t[2]));
      for (int i = 0; i < 3; ++i) held.edges.insert(edge_of(t[i], t[(i + 1) % 3]));
    }
  for (int round = 0, steiner_from = -1; round < 16 && !missing.empty(); ++round) {
    std::vector<Vec3>* steiner = steiner_from >= 0 ? grow : nullptr;
    bool changed = false;
    std::vector<std::array<Index, 3>> left;
    for (const auto& t : missing) {
      if (p.has_face(t[0], t[1], t[2])) continue;  // restored by an earlier change
      bool done = false, edges = true;
      for (int i = 0; i < 3; ++i)
        if (!p.has_edge(t[i], t[(i + 1) % 3])) {
          edges = false;
          if (recover_edge(dt, t[i], t[(i + 1) % 3], steiner ? &held : nullptr, steiner)) done = true;
          break;  // one edge at a time: the next round sees the others
        }
      if (edges) done = recover_triangle(dt, t, steiner);
      if (done) changed = true;
      if (!p.has_face(t[0], t[1], t[2])) left.push_back(t);
    }
    missing = std::move(left);
    if (changed && round - std::max(steiner_from, 0) < 7) continue;
    if (steiner || !grow) break;
    steiner_from = round + 1;  // the first phase's rounds are done: now the second's
  }
  return missing.size();
}

}  // namespace bisect::tet
