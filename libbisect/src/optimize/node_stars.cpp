#include "optimize/node_stars.hpp"

#include <algorithm>

namespace bisect::optimize {

std::vector<Index> star(const tet::TetComplex& cx, Index v, Index t0, std::size_t limit) { return cx.star(v, t0, limit); }

Vec3 neighbour_mean(const std::vector<Vec3>& X, const std::vector<Tet>& tets, const std::vector<Index>& around, Index v) {
  // the star's other nodes, each once: a stamp per node, kept from call to call on each thread
  // (smoothing asks for every node's mean; sorting the star's nodes to drop repeats was 3% of a
  // run at 10^6). The sum goes in the order the nodes are met, as the sorted list's did not:
  // the mean differs in its last bits, the same on every run and thread.
  thread_local std::vector<unsigned> stamp;
  thread_local unsigned now = 0;
  if (stamp.size() < X.size()) stamp.resize(X.size(), 0);
  if (++now == 0) std::fill(stamp.begin(), stamp.end(), 0u), now = 1;
  Vec3 sum = Vec3::Zero();
  std::size_t count = 0;
  stamp[v] = now;
  for (Index t : around)
    for (Index w : tets[t])
      if (stamp[w] != now) stamp[w] = now, sum += X[w], ++count;
  return sum / static_cast<double>(std::max<std::size_t>(count, 1));
}

std::vector<Index> below_key(const tet::TetComplex& cx, std::vector<Index> ids, double key) {
  const auto keep = [&](Index t) { return cx.alive[t] && cx.q[t] < key; };
  if (ids.size() * 16 < cx.tet.size()) {  // a short list: sorted
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    ids.erase(std::remove_if(ids.begin(), ids.end(), [&](Index t) { return !keep(t); }), ids.end());
    return ids;
  }
  // a long one (the optimiser's lists hold half the mesh): marked, then read in id order, the
  // same list without its sort
  std::vector<char> in(cx.tet.size(), 0);
  for (Index t : ids) in[t] = 1;
  ids.clear();
  for (std::size_t t = 0; t < in.size(); ++t)
    if (in[t] && keep(static_cast<Index>(t))) ids.push_back(static_cast<Index>(t));
  return ids;
}

std::vector<Index> all_below_key(const tet::TetComplex& cx, double key) {
  std::vector<Index> out;
  for (std::size_t t = 0; t < cx.tet.size(); ++t)
    if (cx.alive[t] && cx.q[t] < key) out.push_back(static_cast<Index>(t));
  return out;
}

}  // namespace bisect::optimize
