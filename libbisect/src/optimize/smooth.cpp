#include "optimize/smooth.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "optimize/node_stars.hpp"

namespace bisect::optimize {

using tet::positive;
using tet::tet_angle_key;

std::size_t smooth_nodes(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed, const std::vector<Index>& tets) {
  // (node, a tetrahedron at it), once per node, in node order (the order of a whole-mesh pass):
  // a long list through one slot per node, a short one sorted
  std::vector<std::pair<Index, Index>> todo;
  if (tets.size() * 8 > X.size()) {
    std::vector<Index> at(X.size(), -1);
    for (Index t : tets)
      if (cx.alive[t])
        for (Index v : cx.tet[t])
          if (!fixed[v] && at[v] < 0) at[v] = t;
    for (std::size_t v = 0; v < X.size(); ++v)
      if (at[v] >= 0) todo.push_back({static_cast<Index>(v), at[v]});
  } else {
    for (Index t : tets)
      if (cx.alive[t])
        for (Index v : cx.tet[t])
          if (!fixed[v]) todo.push_back({v, t});
    std::sort(todo.begin(), todo.end());
    todo.erase(std::unique(todo.begin(), todo.end(), [](const auto& a, const auto& b) { return a.first == b.first; }), todo.end());
  }
  std::size_t moves = 0;
  std::size_t step = 0;
  std::vector<double> keys;  // the star's keys at the new place (handed on: not computed twice)
  for (const auto& [v, t0] : todo) {
    cx.poll(step++);
    // t0 was at v when listed; a move does not change which tetrahedra there are
    const std::vector<Index> around = star(cx, v, t0);
    double before = std::numeric_limits<double>::max();
    for (Index t : around) before = std::min(before, cx.q[t]);
    const Vec3 old = X[v];
    X[v] = neighbour_mean(X, cx.tet, around, v);
    bool ok = true;
    double after = std::numeric_limits<double>::max();
    keys.clear();
    for (Index t : around) {
      if (!positive(X, cx.tet[t])) {
        ok = false;
        break;
      }
      keys.push_back(tet_angle_key(X, cx.tet[t]));
      after = std::min(after, keys.back());
    }
    if (ok && after >= before) {
      ++moves;
      cx.moved(around, keys);
    } else {
      X[v] = old;
    }
  }
  return moves;
}

}  // namespace bisect::optimize
