#include "domain/face_split.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "bisect/errors.hpp"

namespace bisect {

double loop_area2(const std::vector<Index>& loop, const std::function<Vec2(Index)>& pos) {
  double a = 0;
  const std::size_t n = loop.size();
  const Vec2 o = pos(loop[0]);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const Vec2 p = pos(loop[i]) - o, q = pos(loop[i + 1]) - o;
    a += p.x() * q.y() - p.y() * q.x();
  }
  return a;
}

double turning_angle_sum(const std::vector<Vec2>& loop) {
  double s = 0;
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 d0 = loop[(i + 1) % n] - loop[i], d1 = loop[(i + 2) % n] - loop[(i + 1) % n];
    s += std::atan2(d0.x() * d1.y() - d0.y() * d1.x(), d0.dot(d1));
  }
  return s;
}

bool point_in_loops(const Vec2& p, const std::vector<std::vector<Vec2>>& loops) {
  bool in = false;
  for (const auto& l : loops)
    for (std::size_t i = 0, j = l.size() - 1; i < l.size(); j = i++) {
      const Vec2 &a = l[i], &b = l[j];
      if ((a.y() > p.y()) != (b.y() > p.y()) &&
          p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
        in = !in;
    }
  return in;
}

std::vector<std::vector<std::vector<Index>>> split_polygon_by_chords(
    const std::vector<std::vector<Index>>& loops, const std::vector<std::array<Index, 2>>& chords,
    const std::function<Vec2(Index)>& pos) {
  // Directed edges: the loops (face on their left) and every chord both ways. Each face of the
  // resulting planar graph is traced by leaving every vertex along the first outgoing edge
  // clockwise from the way back, which keeps the traced face on the left.
  struct Half { Index from, to; bool used = false; };
  std::vector<Half> half;
  for (const auto& loop : loops)
    for (std::size_t i = 0; i < loop.size(); ++i) half.push_back({loop[i], loop[(i + 1) % loop.size()]});
  for (const auto& c : chords) {
    half.push_back({c[0], c[1]});
    half.push_back({c[1], c[0]});
  }
  std::map<Index, std::vector<std::size_t>> out;
  for (std::size_t h = 0; h < half.size(); ++h) out[half[h].from].push_back(h);
  auto angle = [&](Index from, Index to) {
    const Vec2 d = pos(to) - pos(from);
    return std::atan2(d.y(), d.x());
  };
  for (auto& [v, hs] : out)
    std::sort(hs.begin(), hs.end(), [&](std::size_t a, std::size_t b) { return angle(v, half[a].to) < angle(v, half[b].to); });

  std::vector<std::vector<Index>> outer, holes;
  for (std::size_t start = 0; start < half.size(); ++start) {
    if (half[start].used) continue;
    std::vector<Index> cyc;
    std::size_t h = start;
    for (std::size_t guard = 0; !half[h].used; ++guard) {
      if (guard > half.size()) throw MeshingError("face split: a traced loop does not close");
      half[h].used = true;
      cyc.push_back(half[h].from);
      const Index v = half[h].to;
      const auto& hs = out[v];
      // the edge back is at angle(v, from); take the next one clockwise (previous in CCW order)
      const double back = angle(v, half[h].from);
      std::size_t best = hs.front();
      double best_turn = -1;
      for (std::size_t k : hs) {
        double turn = back - angle(v, half[k].to);  // clockwise rotation from the way back
        while (turn <= 1e-15) turn += 2 * M_PI;
        if (half[k].to == half[h].from && hs.size() > 1) turn = 4 * M_PI;  // never straight back
        if (best_turn < 0 || turn < best_turn) best_turn = turn, best = k;
      }
      h = best;
    }
    if (h != start) throw MeshingError("face split: traced loops are inconsistent");
    (loop_area2(cyc, pos) > 0 ? outer : holes).push_back(std::move(cyc));
  }
  std::vector<std::vector<std::vector<Index>>> pieces;
  std::vector<std::vector<Vec2>> outer2d;
  for (auto& o : outer) {
    pieces.push_back({o});
    std::vector<Vec2> p;
    for (Index v : o) p.push_back(pos(v));
    outer2d.push_back(std::move(p));
  }
  for (auto& h : holes) {
    // The hole goes into the smallest outer loop around one of its vertices' neighbourhood: test
    // the midpoint of its first edge nudged to its left (into the face, away from the hole).
    const Vec2 a = pos(h[0]), b = pos(h[1]);
    const Vec2 d = b - a;
    const Vec2 probe = 0.5 * (a + b) + 1e-7 * Vec2(-d.y(), d.x());
    std::size_t best = pieces.size();
    double best_area = 0;
    for (std::size_t i = 0; i < outer2d.size(); ++i) {
      if (!point_in_loops(probe, {outer2d[i]})) continue;
      const double ar = loop_area2(pieces[i][0], pos);
      if (best == pieces.size() || ar < best_area) best = i, best_area = ar;
    }
    if (best == pieces.size()) throw MeshingError("face split: a hole lies in no piece");
    pieces[best].push_back(std::move(h));
  }
  return pieces;
}

}  // namespace bisect
