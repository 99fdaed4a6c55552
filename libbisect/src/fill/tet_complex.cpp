#include "fill/tet_complex.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <unordered_map>

#include "bisect/errors.hpp"
#include "bisect/quality.hpp"
#include "bisect/tet_mesh.hpp"
#include "geom/predicates.hpp"

namespace bisect::fill {

using geom::orient3d;

FaceKey face_key(Index a, Index b, Index c) {
  if (a > b) std::swap(a, b);
  if (b > c) std::swap(b, c);
  if (a > b) std::swap(a, b);
  return {a, b, c};
}

bool positive(const std::vector<Vec3>& X, const Tet& t) { return orient3d(X[t[0]], X[t[1]], X[t[2]], X[t[3]]) > 0; }

double tet_angle_key(const std::vector<Vec3>& X, const Tet& t) { return min_solid_angle_tan_half(X[t[0]], X[t[1]], X[t[2]], X[t[3]]); }

void TetComplex::build(std::vector<Tet> tets, std::vector<Index> tags) {
  tet = std::move(tets);
  tag = std::move(tags);
  tag.resize(tet.size(), 0);
  q.resize(tet.size());
  for (std::size_t t = 0; t < tet.size(); ++t) q[t] = tet_angle_key(X, tet[t]);
  nb.assign(tet.size(), {-1, -1, -1, -1});
  alive.assign(tet.size(), 1);
  cmask_.assign(tet.size(), 0);
  born_.assign(tet.size(), ++clock_);
  failed_.clear();
  free_.clear();
  std::unordered_map<FaceKey, std::pair<Index, int>, FaceKeyHash> open;
  open.reserve(tet.size() * 2);
  for (std::size_t t = 0; t < tet.size(); ++t)
    for (int f = 0; f < 4; ++f) {
      const auto fv = face(static_cast<Index>(t), f);
      const FaceKey k = face_key(fv[0], fv[1], fv[2]);
      auto it = open.find(k);
      if (it == open.end()) {
        open.emplace(k, std::make_pair(static_cast<Index>(t), f));
      } else {
        nb[t][f] = it->second.first;
        nb[it->second.first][it->second.second] = static_cast<Index>(t);
        open.erase(it);
      }
    }
}

std::vector<Tet> TetComplex::tets() const {
  std::vector<Tet> out;
  out.reserve(live_count());
  for (std::size_t t = 0; t < tet.size(); ++t)
    if (alive[t]) out.push_back(tet[t]);
  return out;
}

void TetComplex::constrain(const std::unordered_set<FaceKey, FaceKeyHash>& faces) {
  if (faces.empty()) return;
  for (std::size_t t = 0; t < tet.size(); ++t)
    if (alive[t])
      for (int f = 0; f < 4; ++f) {
        const auto fv = face(static_cast<Index>(t), f);
        if (faces.count(face_key(fv[0], fv[1], fv[2]))) cmask_[t] |= static_cast<unsigned char>(1u << f);
      }
}

void TetComplex::refresh_quality() {
  for (std::size_t t = 0; t < tet.size(); ++t)
    if (alive[t]) q[t] = tet_angle_key(X, tet[t]);
  failed_.clear();
}

void TetComplex::moved(const std::vector<Index>& tets) {
  ++clock_;
  for (Index t : tets) {
    q[t] = tet_angle_key(X, tet[t]);
    born_[t] = clock_;
  }
}

std::vector<Index> TetComplex::tags() const {
  std::vector<Index> out;
  out.reserve(live_count());
  for (std::size_t t = 0; t < tet.size(); ++t)
    if (alive[t]) out.push_back(tag[t]);
  return out;
}

std::array<Index, 3> TetComplex::face(Index t, int f) const {
  const auto& c = kTetFace[f];
  return {tet[t][c[0]], tet[t][c[1]], tet[t][c[2]]};
}

bool TetComplex::is_constrained(Index t, int f) const { return nb[t][f] < 0 || (cmask_[t] >> f & 1u); }

int TetComplex::corner_of(Index t, Index v) const {
  for (int k = 0; k < 4; ++k)
    if (tet[t][k] == v) return k;
  return -1;
}

std::vector<Index> TetComplex::tets_at(Index v) const {
  std::vector<Index> around;
  for (std::size_t t = 0; t < tet.size(); ++t)
    if (alive[t] && corner_of(static_cast<Index>(t), v) >= 0) around.push_back(static_cast<Index>(t));
  return around;
}

int TetComplex::face_towards(Index t, Index other) const {
  for (int f = 0; f < 4; ++f)
    if (nb[t][f] == other) return f;
  return -1;
}

std::vector<Index> TetComplex::replace(const std::vector<Index>& old, const std::vector<Tet>& fresh, bool new_boundary) {
  // the old set's outside faces, with the tetrahedron (and its face) on the other side
  struct Outer {
    FaceKey key;
    Index n;
    int nf;
    bool held;  // constrained
  };
  std::vector<Outer> outer;
  const unsigned in_old = new_stamp();
  for (Index o : old) mark_[o] = in_old;
  for (Index o : old)
    for (int f = 0; f < 4; ++f) {
      const Index n = nb[o][f];
      if (marked(n, in_old)) continue;
      const auto fv = face(o, f);
      int nf = -1;
      if (n >= 0)
        for (int g = 0; g < 4; ++g)
          if (tet[n][g] != fv[0] && tet[n][g] != fv[1] && tet[n][g] != fv[2]) nf = g;
      outer.push_back({face_key(fv[0], fv[1], fv[2]), n, nf, is_constrained(o, f)});
    }
  const Index inherited = old.empty() ? 0 : tag[old.front()];
  for (Index o : old) {
    alive[o] = 0;
    free_.push_back(o);
  }
  std::vector<Index> ids;
  for (const Tet& t : fresh) {
    Index id;
    if (!free_.empty()) {
      id = free_.back();
      free_.pop_back();
      tet[id] = t;
      nb[id] = {-1, -1, -1, -1};
      alive[id] = 1;
      tag[id] = inherited;
      q[id] = tet_angle_key(X, t);
      cmask_[id] = 0;
      born_[id] = clock_ + 1;
    } else {
      id = static_cast<Index>(tet.size());
      tet.push_back(t);
      nb.push_back({-1, -1, -1, -1});
      alive.push_back(1);
      tag.push_back(inherited);
      q.push_back(tet_angle_key(X, t));
      cmask_.push_back(0);
      born_.push_back(clock_ + 1);
    }
    ids.push_back(id);
  }
  // match every new face with another new one or with an old outside face: sorted by key,
  // equal keys meet (a new face pairs with at most one other)
  struct Side {
    FaceKey key;
    Index t;
    int f;
    bool fresh, held;
  };
  std::vector<Side> sides;
  sides.reserve(ids.size() * 4 + outer.size());
  for (Index id : ids)
    for (int f = 0; f < 4; ++f) {
      const auto fv = face(id, f);
      sides.push_back({face_key(fv[0], fv[1], fv[2]), id, f, true, false});
    }
  for (const Outer& o : outer) sides.push_back({o.key, o.n, o.nf, false, o.held});
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
    if (x.key.a != y.key.a) return x.key.a < y.key.a;
    if (x.key.b != y.key.b) return x.key.b < y.key.b;
    if (x.key.c != y.key.c) return x.key.c < y.key.c;
    return x.fresh > y.fresh;
  });
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while (j < sides.size() && sides[j].key == sides[i].key) ++j;
    const Side& x = sides[i];
    if (!x.fresh) {  // an old face no new tetrahedron took up
      i = j;
      continue;
    }
    if (j - i == 1 && new_boundary) {  // a new face of the outer boundary
      i = j;
      continue;
    }
    if (j - i != 2) throw MeshingError("tetrahedral complex: a replacement does not fill the space it replaces");
    const Side& y = sides[i + 1];
    nb[x.t][x.f] = y.t;
    if (y.t >= 0) nb[y.t][y.f] = x.t;
    if (y.held && y.t >= 0) cmask_[x.t] |= static_cast<unsigned char>(1u << x.f);  // a kept constrained face
    i = j;
  }
  ++clock_;
  return ids;
}

Index TetComplex::locate(const Vec3& p, Index start) const {
  Index t = start;
  if (t < 0 || t >= static_cast<Index>(tet.size()) || !alive[t]) {
    t = -1;
    for (std::size_t k = 0; k < tet.size() && t < 0; ++k)
      if (alive[k]) t = static_cast<Index>(k);
    if (t < 0) return -1;
  }
  // visibility walk; the face to try first rotates, which keeps the walk from cycling
  const std::size_t limit = 64 + 4 * tet.size();
  unsigned rot = 0;
  for (std::size_t step = 0; step < limit; ++step) {
    bool moved = false;
    for (int k = 0; k < 4 && !moved; ++k) {
      const int f = static_cast<int>((k + rot) % 4);
      const auto fv = face(t, f);
      if (orient3d(X[fv[0]], X[fv[1]], X[fv[2]], p) > 0) {
        if (nb[t][f] < 0) return -1;  // outside, across the boundary (the cells are convex)
        t = nb[t][f];
        moved = true;
      }
    }
    if (!moved) return t;
    rot = rot * 1103515245u + 12345u;
    rot >>= 3;
  }
  for (std::size_t k = 0; k < tet.size(); ++k) {  // the walk did not settle: look everywhere
    if (!alive[k]) continue;
    bool in = true;
    for (int f = 0; f < 4 && in; ++f) {
      const auto fv = face(static_cast<Index>(k), f);
      in = orient3d(X[fv[0]], X[fv[1]], X[fv[2]], p) <= 0;
    }
    if (in) return static_cast<Index>(k);
  }
  return -1;
}

bool TetComplex::holders(const Vec3& p, Index t0, std::vector<Index>* hold) const {
  *hold = {t0};
  for (std::size_t i = 0; i < hold->size(); ++i) {
    const Index t = (*hold)[i];
    int zeros = 0;
    for (int f = 0; f < 4; ++f) {
      const auto fv = face(t, f);
      if (orient3d(X[fv[0]], X[fv[1]], X[fv[2]], p) != 0) continue;
      ++zeros;
      if (is_constrained(t, f)) return false;  // on the boundary: not ours to split
      if (std::find(hold->begin(), hold->end(), nb[t][f]) == hold->end()) hold->push_back(nb[t][f]);
    }
    if (zeros >= 3) return false;  // on a node
  }
  return true;
}

std::vector<Index> TetComplex::insert(Index v, Index start) {
  const Vec3& p = X[v];
  const Index t0 = locate(p, start);
  std::vector<Index> hold;
  if (t0 < 0 || !holders(p, t0, &hold)) return {};
  std::vector<Tet> fresh;
  for (Index t : hold)
    for (int j = 0; j < 4; ++j) {
      const auto fv = face(t, j);
      if (orient3d(X[fv[0]], X[fv[1]], X[fv[2]], p) >= 0) continue;
      Tet n = tet[t];
      n[j] = v;
      fresh.push_back(n);
    }
  return replace(hold, fresh);
}

std::vector<Index> TetComplex::insert_delaunay(Index v, Index start) {
  const Vec3& p = X[v];
  const Index t0 = locate(p, start);
  if (t0 < 0) return {};
  std::vector<Index> seed;  // the tetrahedra whose closure holds p
  if (!holders(p, t0, &seed)) return {};
  const unsigned in_cavity = new_stamp();
  std::vector<Index> cavity = seed;
  for (Index t : seed) mark_[t] = in_cavity;
  for (std::size_t i = 0; i < cavity.size(); ++i)
    for (int f = 0; f < 4; ++f) {
      const Index n = nb[cavity[i]][f];
      if (n < 0 || marked(n, in_cavity) || is_constrained(cavity[i], f)) continue;
      const Tet& u = tet[n];
      if (geom::insphere(X[u[0]], X[u[1]], X[u[2]], X[u[3]], p) > 0) {
        cavity.push_back(n);
        mark_[n] = in_cavity;
      }
    }
  // star-shaped from p: drop (non-seed) tetrahedra whose outer faces p does not see from
  // inside, keep what still hangs together from the seeds, until nothing changes
  auto is_seed = [&](Index t) { return std::find(seed.begin(), seed.end(), t) != seed.end(); };
  unsigned current = in_cavity;
  for (;;) {
    std::vector<Index> kept;
    for (Index t : cavity) {
      bool sees = true;
      for (int f = 0; f < 4 && sees && !is_seed(t); ++f) {
        if (marked(nb[t][f], current)) continue;
        const auto fv = face(t, f);
        sees = orient3d(X[fv[0]], X[fv[1]], X[fv[2]], p) < 0;
      }
      if (sees) kept.push_back(t);
    }
    if (kept.size() == cavity.size()) break;
    const unsigned in_kept = new_stamp();
    for (Index t : kept) mark_[t] = in_kept;
    const unsigned reached = new_stamp();
    std::vector<Index> front = seed;
    for (Index t : seed) mark_[t] = reached;
    for (std::size_t i = 0; i < front.size(); ++i)
      for (int f = 0; f < 4; ++f) {
        const Index n = nb[front[i]][f];
        if (n < 0 || !marked(n, in_kept) || is_constrained(front[i], f)) continue;
        mark_[n] = reached;
        front.push_back(n);
      }
    cavity = std::move(front);
    current = reached;
  }
  const unsigned final_mark = new_stamp();
  for (Index t : cavity) mark_[t] = final_mark;
  // two arms of the cavity may meet across a constrained face: it must stay, so v does not go in
  for (Index t : cavity)
    for (int f = 0; f < 4; ++f)
      if (marked(nb[t][f], final_mark) && is_constrained(t, f)) return {};
  std::vector<Tet> fresh;
  for (Index t : cavity)
    for (int f = 0; f < 4; ++f) {
      const Index n = nb[t][f];
      if (marked(n, final_mark)) continue;
      const auto fv = face(t, f);
      if (orient3d(X[fv[0]], X[fv[1]], X[fv[2]], p) >= 0) continue;  // a seed face p lies on
      Tet m = tet[t];
      m[f] = v;
      fresh.push_back(m);
    }
  return replace(cavity, fresh);
}

int TetComplex::edge_ring(Index t, Index a, Index b, int cap, Index* ring, Index* apex, bool* closed, bool* held) const {
  *closed = *held = false;
  int k = 0;
  Index cur = t, prev = -1;
  while (k < cap) {
    ring[k++] = cur;
    // the two faces of cur through edge ab are those opposite its other two corners
    int next_face = -1;
    for (int f = 0; f < 4; ++f) {
      const Index opp = tet[cur][f];
      if (opp == a || opp == b) continue;
      if (nb[cur][f] == prev && prev >= 0) continue;
      next_face = f;
      if (prev < 0) break;  // first step: either way round
    }
    if (next_face < 0) return k;
    if (is_constrained(cur, next_face)) {
      *held = true;
      return k;
    }
    // the face crossed holds a, b and cur's fourth corner
    for (Index x : tet[cur])
      if (x != a && x != b && x != tet[cur][next_face]) apex[k - 1] = x;
    const Index n = nb[cur][next_face];
    if (n == t) {
      *closed = true;
      return k;
    }
    prev = cur;
    cur = n;
  }
  return k + 1;  // longer than cap
}

namespace {

// The 2-2 transformation keeps boundary triangles at or above this (20 degrees), or at the
// poorer old one's angle when that was below.
constexpr double kMinBoundaryAngle = 0.3490658503988659;

// The angle at p of the triangle p, u, v (radians).
double corner_angle(const Vec3& p, const Vec3& u, const Vec3& v) { return std::atan2((u - p).cross(v - p).norm(), (u - p).dot(v - p)); }

// The smallest angle of a triangle in 3D, radians: the one facing the shortest side.
double triangle_min_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm(), ab = (b - a).squaredNorm();
  if (bc <= ca && bc <= ab) return corner_angle(a, b, c);
  return ca <= ab ? corner_angle(b, c, a) : corner_angle(c, a, b);
}

}  // namespace

bool TetComplex::try_flip22(Index t, int f, std::vector<std::pair<Index, int>>& queue) {
  const Index n = nb[t][f];
  const auto fv = face(t, f);
  const Index d = tet[t][f];
  const int nf = face_towards(n, t);
  const Index e = tet[n][nf];
  for (int k = 0; k < 3; ++k) {
    // the edge (x, y) of the shared face, its third node c: the faces (x, y, d) of t and
    // (x, y, e) of n are those opposite c
    const Index x = fv[k], y = fv[(k + 1) % 3], c = fv[(k + 2) % 3];
    const int ct = corner_of(t, c), cn = corner_of(n, c);
    if (nb[t][ct] >= 0 || nb[n][cn] >= 0) continue;  // not two faces of the outer boundary
    const auto ft = face(t, ct), fn = face(n, cn);
    const auto tag_t = surface_tag.find(face_key(ft[0], ft[1], ft[2]));
    const auto tag_n = surface_tag.find(face_key(fn[0], fn[1], fn[2]));
    if (tag_t == surface_tag.end() || tag_n == surface_tag.end() || tag_t->second != tag_n->second) continue;
    Tet tx = tet[t], ty = tet[t];  // (c, d, e) with x, and with y
    tx[corner_of(t, y)] = e;
    ty[corner_of(t, x)] = e;
    if (!positive(X, tx) || !positive(X, ty)) continue;  // the quadrilateral x d y e is not convex
    const double need = std::min(q[t], q[n]) * (1 + 1e-9);
    if (!(tet_angle_key(X, tx) > need) || !(tet_angle_key(X, ty) > need)) continue;
    // the boundary's grid was made for its triangles (4.4); they may not get worse than the
    // poorer of the two, nor under 20 degrees when they were above (without this, the flips
    // left more slivers than they removed, measured on the ../shared STL models)
    const double was = std::min(triangle_min_angle(X[x], X[y], X[d]), triangle_min_angle(X[x], X[y], X[e]));
    const double now = std::min(triangle_min_angle(X[x], X[d], X[e]), triangle_min_angle(X[y], X[d], X[e]));
    if (now < std::min(was, kMinBoundaryAngle)) continue;
    const Index tag = tag_t->second;
    surface_tag.erase(tag_t);
    surface_tag.erase(tag_n);
    surface_tag[face_key(x, d, e)] = tag;
    surface_tag[face_key(y, d, e)] = tag;
    failed_.erase((static_cast<std::uint64_t>(std::min(x, y)) << 32) | static_cast<std::uint32_t>(std::max(x, y)));
    for (Index id : replace({t, n}, {tx, ty}, true))
      for (int g = 0; g < 4; ++g) queue.push_back({id, g});
    return true;
  }
  return false;
}

bool TetComplex::try_flip23(Index t, int f, std::vector<std::pair<Index, int>>& queue) {
  const Index n = nb[t][f];
  if (n < 0 || is_constrained(t, f)) return false;
  const auto fv = face(t, f);
  Index e = -1;
  for (int g = 0; g < 4; ++g)
    if (tet[n][g] != fv[0] && tet[n][g] != fv[1] && tet[n][g] != fv[2]) e = tet[n][g];
  std::vector<Tet> fresh;
  for (Index c : fv) {  // each face corner of t replaced by e
    Tet m = tet[t];
    m[corner_of(t, c)] = e;
    if (!positive(X, m)) return false;  // the segment between the apexes misses the face
    fresh.push_back(m);
  }
  const double need = std::min(q[t], q[n]) * (1 + 1e-9);
  for (const Tet& m : fresh)
    if (!(tet_angle_key(X, m) > need)) return false;  // the smallest solid angle would not rise
  for (Index id : replace({t, n}, fresh))
    for (int g = 0; g < 4; ++g) queue.push_back({id, g});
  return true;
}

bool TetComplex::try_edge_removal(Index t, Index a, Index b, std::vector<std::pair<Index, int>>& queue) {
  const std::uint64_t edge = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
  const auto seen = failed_.find(edge);
  if (seen != failed_.end()) {
    const Failure& was = seen->second;
    if (was.stamp == kForever) return false;
    bool same = true;
    for (int i = 0; i < was.k && same; ++i) same = alive[was.ring[i]] && born_[was.ring[i]] <= was.stamp;
    if (same) return false;  // the same ring failed before
  }
  std::array<Index, kMaxRing> ring, p;  // p[i]: the node ring[i] shares with ring[i + 1] (besides a and b)
  bool closed = false, held = false;
  const int n = edge_ring(t, a, b, static_cast<int>(kMaxRing), ring.data(), p.data(), &closed, &held);
  if (held) {  // a, b on a constrained face: that never goes, nor does the edge
    failed_[edge] = Failure{kForever, 0, {}};
    return false;
  }
  if (!closed || n < 3) return false;
  const std::size_t k = static_cast<std::size_t>(n);
  auto fail = [&] {
    failed_[edge] = Failure{clock_, n, ring};
    return false;
  };
  double before = 1e300;
  for (std::size_t i = 0; i < k; ++i) before = std::min(before, q[ring[i]]);
  std::vector<Tet> fresh;
  if (!ring_triangulation(a, b, p.data(), k, before * (1 + 1e-9), &fresh)) return fail();
  for (Index id : replace(std::vector<Index>(ring.begin(), ring.begin() + n), fresh))
    for (int g = 0; g < 4; ++g) queue.push_back({id, g});
  return true;
}

bool TetComplex::ring_triangulation(Index a, Index b, const Index* p, std::size_t k, double need, std::vector<Tet>* fresh) const {
  // best triangulation of the polygon (Klincsek's dynamic programme): each triangle (i, m, j)
  // makes two tetrahedra with a and b, valid when a lies on the side `sign` of it and b on the
  // other; the ring's order fixes which sign that is, so both are tried. Only triangulations
  // better than `need` matter, so a part no better than it counts as impossible: most
  // triangles are then rejected before their tetrahedra are graded.
  std::array<double, kMaxRing * kMaxRing> best;
  std::array<int, kMaxRing * kMaxRing> split;
  for (int sign : {1, -1}) {
    best.fill(-1);  // best[i * k + j]: polygon i..j, -1 impossible
    for (std::size_t i = 0; i + 1 < k; ++i) best[i * k + i + 1] = 1e300;
    for (std::size_t len = 2; len < k; ++len)
      for (std::size_t i = 0; i + len < k; ++i) {
        const std::size_t j = i + len;
        for (std::size_t m = i + 1; m < j; ++m) {
          const double l = best[i * k + m], r = best[m * k + j];
          if (l < 0 || r < 0 || std::min(l, r) <= best[i * k + j]) continue;
          const Vec3 &A = X[p[i]], &B = X[p[m]], &C = X[p[j]];
          if (orient3d(A, B, C, X[a]) != sign || orient3d(A, B, C, X[b]) != -sign) continue;
          const double floor = std::max(need, best[i * k + j]);
          const double ka = min_solid_angle_tan_half(A, B, C, X[a]);
          if (!(ka > floor)) continue;
          const double worst = std::min({l, r, ka, min_solid_angle_tan_half(A, B, C, X[b])});
          if (worst > floor) best[i * k + j] = worst, split[i * k + j] = static_cast<int>(m);
        }
      }
    if (best[0 * k + k - 1] < 0) continue;
    fresh->clear();
    std::vector<std::pair<std::size_t, std::size_t>> todo{{0, k - 1}};
    while (!todo.empty()) {
      const auto [i, j] = todo.back();
      todo.pop_back();
      if (j < i + 2) continue;
      const std::size_t m = static_cast<std::size_t>(split[i * k + j]);
      fresh->push_back(sign > 0 ? Tet{p[i], p[m], p[j], a} : Tet{p[m], p[i], p[j], a});
      fresh->push_back(sign > 0 ? Tet{p[m], p[i], p[j], b} : Tet{p[i], p[m], p[j], b});
      todo.push_back({i, m});
      todo.push_back({m, j});
    }
    return true;
  }
  return false;
}

bool TetComplex::remove_vertex(Index v) {
  for (;;) {
    const std::vector<Index> around = tets_at(v);
    if (around.size() < 4) return false;  // not an interior node
    for (Index t : around)  // a face at v that holds (the boundary): v is not inside
      for (int f = 0; f < 4; ++f)
        if (tet[t][f] != v && is_constrained(t, f)) return false;
    if (around.size() == 4) {  // 4-1: the four faces opposite v close up into one tetrahedron
      Tet m = tet[around[0]];
      const int c = corner_of(around[0], v);
      for (Index t : around)
        for (Index x : tet[t])
          if (x != v && std::find(m.begin(), m.end(), x) == m.end()) m[c] = x;
      if (!positive(X, m)) return false;
      replace(around, {m});
      return true;
    }
    // 3-2, 4-4 and larger: an edge (v, x) taken out of its ring, whichever triangulation of the
    // ring is best; v then lies in two tetrahedra fewer
    bool removed = false;
    for (std::size_t i = 0; i < around.size() && !removed; ++i)
      for (Index x : tet[around[i]]) {
        if (x == v) continue;
        std::array<Index, kMaxRing> ring, p;
        bool closed = false, held = false;
        const int n = edge_ring(around[i], v, x, static_cast<int>(kMaxRing), ring.data(), p.data(), &closed, &held);
        if (!closed || n < 3 || n > static_cast<int>(kMaxRing)) continue;
        std::vector<Tet> fresh;
        if (!ring_triangulation(v, x, p.data(), static_cast<std::size_t>(n), 0, &fresh)) continue;
        replace(std::vector<Index>(ring.begin(), ring.begin() + n), fresh);
        removed = true;
        break;
      }
    if (!removed) return false;
  }
}

std::int64_t TetComplex::improve(std::vector<std::pair<Index, int>> queue, std::int64_t max_ops) {
  std::int64_t ops = 0;
  for (std::size_t i = 0; i < queue.size() && ops < max_ops; ++i) {
    const auto [t, f] = queue[i];
    if (!alive[t] || is_constrained(t, f)) continue;
    if (try_flip23(t, f, queue) || (boundary_flips && try_flip22(t, f, queue))) {
      ++ops;
      continue;
    }
    // edge removal costs a small dynamic programme per edge: only around a poor tetrahedron
    if (std::min(q[t], q[nb[t][f]]) >= edge_removal_below) continue;
    const auto fv = face(t, f);
    for (int e = 0; e < 3; ++e)
      if (try_edge_removal(t, fv[e], fv[(e + 1) % 3], queue)) {
        ++ops;
        break;
      }
  }
  return ops;
}

std::int64_t TetComplex::improve_around(const std::vector<Index>& tets) {
  std::vector<std::pair<Index, int>> queue;
  queue.reserve(4 * tets.size());
  for (Index t : tets)
    for (int f = 0; f < 4; ++f) queue.push_back({t, f});
  return improve(std::move(queue), std::numeric_limits<std::int64_t>::max());
}

std::int64_t TetComplex::improve_all(std::int64_t max_ops) {
  std::vector<std::pair<Index, int>> queue;
  for (std::size_t t = 0; t < tet.size(); ++t)
    if (alive[t])
      for (int f = 0; f < 4; ++f)
        if (nb[t][f] > static_cast<Index>(t)) queue.push_back({static_cast<Index>(t), f});
  return improve(std::move(queue), max_ops);
}

}  // namespace bisect::fill
