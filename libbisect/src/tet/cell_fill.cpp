#include "tet/cell_fill.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>

#include "bisect/errors.hpp"
#include "geom/predicates.hpp"

namespace bisect::tet {

using geom::orient3d;
namespace {

// The interior nodes nearest the cell's centre tried as the star's centre before a helper.
constexpr std::size_t kCentreCandidates = 8;

// The star of the boundary from node c: one tetrahedron per boundary triangle; empty when c
// does not see every triangle from inside.
std::vector<Tet> star(const std::vector<Vec3>& X, const std::vector<std::array<Index, 3>>& boundary, Index c) {
  std::vector<Tet> tets;
  tets.reserve(boundary.size());
  for (const auto& t : boundary) {
    const Tet m{t[1], t[0], t[2], c};  // outward triangle seen from inside: reversed
    if (!positive(X, m)) return {};
    tets.push_back(m);
  }
  return tets;
}

// A point that sees every boundary triangle from inside, with a margin, near `start`: cyclic
// projections onto the triangles' inner half-spaces (each violated one in turn; the kernel is
// their intersection, convex, so the projections converge when it has an interior). For cells
// that are star-shaped but not convex, where neither the centroid nor a node near it will do.
bool kernel_point(const std::vector<Vec3>& X, const std::vector<std::array<Index, 3>>& boundary, const Vec3& start, Vec3* out) {
  std::vector<Vec3> n;
  std::vector<double> d;
  double shortest = 1e300;
  for (const auto& t : boundary) {
    const Vec3 a = X[t[0]], b = X[t[1]], c = X[t[2]];
    Vec3 m = (b - a).cross(c - a);  // outward
    const double len = m.norm();
    if (!(len > 0)) continue;
    m /= len;
    n.push_back(m), d.push_back(m.dot(a));
    shortest = std::min({shortest, (b - a).norm(), (c - b).norm(), (a - c).norm()});
  }
  Vec3 x = start;
  for (double margin : {0.05 * shortest, 0.01 * shortest, 1e-4 * shortest}) {
    for (int sweep = 0; sweep < 400; ++sweep) {
      double worst = 0;
      for (std::size_t i = 0; i < n.size(); ++i) {
        const double over = n[i].dot(x) - d[i] + margin;  // > 0: outside the shrunken half-space
        if (over > 0) {
          x -= 1.5 * over * n[i];  // over-relaxed projection
          worst = std::max(worst, over);
        }
      }
      if (worst == 0) break;
    }
    bool all = true;
    for (const auto& t : boundary)
      if (orient3d(X[t[1]], X[t[0]], X[t[2]], x) <= 0) {
        all = false;
        break;
      }
    if (all) {
      *out = x;
      return true;
    }
  }
  return false;
}

// Removes the helper node v by collapsing it onto the neighbour that leaves the best
// tetrahedra, when every changed tetrahedron stays positive. Returns whether it went.
bool collapse_helper(TetComplex& cx, Index v) {
  const std::vector<Index> around = cx.tets_at(v);
  std::vector<Index> neighbours;
  for (Index t : around)
    for (Index w : cx.tet[t])
      if (w != v && std::find(neighbours.begin(), neighbours.end(), w) == neighbours.end()) neighbours.push_back(w);
  double best = -1;
  std::vector<Tet> best_fresh;
  for (Index w : neighbours) {
    std::vector<Tet> fresh;
    double worst = std::numeric_limits<double>::max();
    bool ok = true;
    for (Index t : around) {
      if (cx.corner_of(t, w) >= 0) continue;  // tetrahedra on the edge v w vanish
      Tet m = cx.tet[t];
      m[cx.corner_of(t, v)] = w;
      if (!positive(cx.X, m)) {
        ok = false;
        break;
      }
      worst = std::min(worst, tet_angle_key(cx.X, m));
      fresh.push_back(m);
    }
    if (ok && worst > best) best = worst, best_fresh = std::move(fresh);
  }
  if (best < 0) return false;
  cx.replace(around, best_fresh);
  return true;
}

// Biased randomised insertion order (Amenta, Choi and Rote): the nodes shuffled, then taken in
// rounds of doubling size, each round sorted along a Morton curve. Random order keeps the
// cavities small on average (the first nodes, inserted into the star of long thin tetrahedra,
// would otherwise each take most of it); the sorting keeps the walks short.
void brio_order(const std::vector<Vec3>& X, std::vector<Index>& v) {
  if (v.size() < 8) return;
  std::uint64_t state = 0x2545F4914F6CDD1Dull ^ v.size();
  for (std::size_t i = v.size() - 1; i > 0; --i) {  // Fisher-Yates with xorshift
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    std::swap(v[i], v[state % (i + 1)]);
  }
  Vec3 lo = X[v[0]], hi = X[v[0]];
  for (Index i : v) lo = lo.cwiseMin(X[i]), hi = hi.cwiseMax(X[i]);
  const Vec3 span = (hi - lo).cwiseMax(Vec3::Constant(1e-300));
  // each node's Morton code once (within the comparison it was computed twice per comparison)
  std::vector<std::uint64_t> morton(X.size(), 0);
  for (Index i : v) {
    std::uint64_t code = 0;
    const Vec3 q = (X[i] - lo).cwiseQuotient(span);
    const std::uint64_t x = static_cast<std::uint64_t>(q.x() * 1023), y = static_cast<std::uint64_t>(q.y() * 1023), z = static_cast<std::uint64_t>(q.z() * 1023);
    for (int b = 9; b >= 0; --b) code = (code << 3) | (((x >> b) & 1) << 2) | (((y >> b) & 1) << 1) | ((z >> b) & 1);
    morton[i] = code;
  }
  for (std::size_t begin = 0, size = 8; begin < v.size(); begin += size, size *= 2) {
    const std::size_t end = std::min(v.size(), begin + size);
    std::sort(v.begin() + static_cast<std::ptrdiff_t>(begin), v.begin() + static_cast<std::ptrdiff_t>(end),
              [&](Index a, Index b) { return morton[a] < morton[b]; });
  }
}

}  // namespace

bool sees_all(const std::vector<Vec3>& X, const std::vector<std::array<Index, 3>>& boundary, const Vec3& p) {
  for (const auto& t : boundary)
    if (orient3d(X[t[1]], X[t[0]], X[t[2]], p) <= 0) return false;  // outward triangle seen from inside: reversed
  return true;
}

bool star_centre(const std::vector<Vec3>& X, const std::vector<std::array<Index, 3>>& boundary, const std::vector<Index>& interior,
                 const Vec3& centroid, Index* node, Vec3* point) {
  // a convex cell is seen whole from its nearest node; a star-shaped one (the B-rep route's cells,
  // whose faces were moved onto curved surfaces) from some node near its middle, or else from a
  // point of its kernel
  std::vector<Index> near = interior;
  const std::size_t k = std::min<std::size_t>(near.size(), kCentreCandidates);
  std::partial_sort(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(k), near.end(),
                    [&](Index a, Index b) { return (X[a] - centroid).squaredNorm() < (X[b] - centroid).squaredNorm(); });
  for (std::size_t i = 0; i < k; ++i)
    if (sees_all(X, boundary, X[near[i]])) {
      *node = near[i];
      return true;
    }
  *node = -1;
  if (sees_all(X, boundary, centroid)) {
    *point = centroid;
    return true;
  }
  return kernel_point(X, boundary, centroid, point);
}

std::vector<Tet> fill_convex_cell(std::vector<Vec3>& X, const std::vector<std::array<Index, 3>>& boundary,
                                  const std::vector<Index>& interior, const Vec3& centroid, bool delaunay, CellFillStats* stats,
                                  const std::function<bool()>& cancelled) {
  CellFillStats st;
  // the star's centre: the interior node nearest the centroid, else a helper at the centroid
  std::vector<Index> rest = interior;
  std::sort(rest.begin(), rest.end(), [&](Index a, Index b) { return (X[a] - centroid).squaredNorm() < (X[b] - centroid).squaredNorm(); });
  Index node = -1;
  Vec3 point;
  if (!star_centre(X, boundary, rest, centroid, &node, &point))
    throw MeshingError("cell fill: neither the centre nor a node near it sees every boundary triangle (the cell is not star-shaped)");
  Index centre = node;
  if (node >= 0) {
    rest.erase(std::find(rest.begin(), rest.end(), node));
  } else {
    X.push_back(point);
    centre = static_cast<Index>(X.size() - 1);
    st.helper = true;
  }
  std::vector<Tet> tets = star(X, boundary, centre);
  TetComplex cx(X);
  // only the worst tetrahedra (Ω < 0.12 sr) get edge removal here: the global passes see every
  // tetrahedron again with the full threshold, and at half the filling's cost
  cx.edge_removal_below = 0.060072058;  // tan(0.06)
  cx.cancelled = cancelled;
  cx.build(std::move(tets));
  st.flips += cx.improve_all(std::numeric_limits<std::int64_t>::max());
  if (delaunay) brio_order(X, rest);
  // the other nodes (min-max: nearest the centre first, so that each walk starts close to its
  // target; Delaunay: in biased randomised rounds, see brio_order)
  Index last = 0;
  std::size_t step = 0;
  for (Index v : rest) {
    cx.poll(step++);
    const std::vector<Index> made = delaunay ? cx.insert_delaunay(v, last) : cx.insert(v, last);
    if (made.empty()) {
      ++st.skipped;
      continue;
    }
    ++st.inserted;
    last = made.front();
    if (!delaunay) st.flips += cx.improve_around(made);
    if (!cx.alive[last]) last = 0;
  }
  if (delaunay) st.flips += cx.improve_all(std::numeric_limits<std::int64_t>::max());
  // The helper goes (7.6) by the collapse onto the neighbour that leaves the best tetrahedra,
  // else by flips, when the cell's worst tetrahedron is then no worse than with it: a cell
  // without interior nodes whose faces are finely gridded keeps better tetrahedra around it.
  if (st.helper) {
    auto worst = [](const TetComplex& c) {
      double w = 1e300;
      for (std::size_t t = 0; t < c.tet.size(); ++t)
        if (c.alive[t]) w = std::min(w, c.q[t]);
      return w;
    };
    const double with_helper = worst(cx);
    for (int how = 0; how < 2 && !st.helper_removed; ++how) {
      TetComplex trial = cx;
      if (!(how == 0 ? collapse_helper(trial, centre) : trial.remove_vertex(centre))) continue;
      const std::int64_t flips = trial.improve_all(std::numeric_limits<std::int64_t>::max());
      if (worst(trial) < with_helper) continue;
      st.helper_removed = true;
      st.flips += flips;
      if (stats) *stats = st;
      return trial.tets();
    }
  }
  if (stats) *stats = st;
  return cx.tets();
}

}  // namespace bisect::tet
