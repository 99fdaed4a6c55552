#include "nodes/sized_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "nodes/cell_nodes.hpp"

namespace bisect::nodes {
namespace {

// Below this fraction of the base size the octree places the nodes, above it the shrinking.
constexpr double kFine = 0.85;
constexpr double kApart = 0.6;  // nodes no nearer each other than this many sizes

// A deterministic number in [-0.5, 0.5) from two integers (splitmix64).
double jitter(std::uint64_t a, std::uint64_t b) {
  std::uint64_t z = a * 0x9E3779B97F4A7C15ull + b + 0x632BE59BD9B4E019ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) / 9007199254740992.0 - 0.5;
}

// The smallest distance from p to the cell's face planes (positive inside).
double depth(const Polytope& cell, const Vec3& p) {
  double d = 1e300;
  for (std::size_t f = 0; f < cell.normal.size(); ++f) d = std::min(d, cell.offset[f] - cell.normal[f].dot(p));
  return d;
}

class Grid {
 public:
  explicit Grid(double cube) : inv_(1 / cube) {}
  void add(const Vec3& p, std::size_t id) { cubes_[key(p, 0, 0, 0)].push_back(id); }
  template <class F>
  bool any_near(const Vec3& p, F f) const {
    for (int x = -1; x <= 1; ++x)
      for (int y = -1; y <= 1; ++y)
        for (int z = -1; z <= 1; ++z) {
          const auto it = cubes_.find(key(p, x, y, z));
          if (it == cubes_.end()) continue;
          for (std::size_t id : it->second)
            if (f(id)) return true;
        }
    return false;
  }

 private:
  std::uint64_t key(const Vec3& p, int dx, int dy, int dz) const {
    auto part = [](std::int64_t v) { return static_cast<std::uint64_t>(v + (1 << 20)) & 0x1fffff; };
    return part(static_cast<std::int64_t>(std::floor(p.x() * inv_)) + dx) | part(static_cast<std::int64_t>(std::floor(p.y() * inv_)) + dy) << 21 |
           part(static_cast<std::int64_t>(std::floor(p.z() * inv_)) + dz) << 42;
  }
  double inv_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cubes_;
};

}  // namespace

std::vector<Vec3> sized_cell_nodes(const Polytope& cell, const size::SizeField& h, std::size_t* graded) {
  if (graded) *graded = 0;
  const double np = h.base();
  std::vector<Vec3> uniform = shrink_cell_nodes(cell, np);
  if (h.smallest() >= kFine * np || cell.v.empty()) return uniform;
  // the octree's fine leaves
  Vec3 lo = cell.v[0], hi = cell.v[0];
  for (const Vec3& p : cell.v) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  std::vector<std::pair<Vec3, double>> fine;  // node, its size
  struct Box {
    Vec3 lo;
    double edge;
    int depth;
  };
  std::vector<Box> todo;
  for (double x = lo.x(); x < hi.x(); x += np)
    for (double y = lo.y(); y < hi.y(); y += np)
      for (double z = lo.z(); z < hi.z(); z += np) todo.push_back({Vec3(x, y, z), np, 0});
  std::uint64_t counter = 0;
  while (!todo.empty()) {
    const Box b = todo.back();
    todo.pop_back();
    const Vec3 c = b.lo + Vec3::Constant(0.5 * b.edge);
    // a box wholly outside the cell, or far inside where the field is at its base, has no fine node
    if (depth(cell, c) < -0.87 * b.edge) continue;
    const double s = h.at(c);
    if (s >= kFine * np && b.depth == 0) continue;
    if (b.edge > s && b.depth < 14) {
      const double e = 0.5 * b.edge;
      for (int k = 0; k < 8; ++k) todo.push_back({b.lo + Vec3(k & 1 ? e : 0, k & 2 ? e : 0, k & 4 ? e : 0), e, b.depth + 1});
      continue;
    }
    ++counter;
    const Vec3 p = c + 0.2 * b.edge * Vec3(jitter(counter, 1), jitter(counter, 2), jitter(counter, 3));
    const double sp = h.at(p);
    if (sp >= kFine * np || depth(cell, p) < 0.5 * sp) continue;
    fine.push_back({p, sp});
  }
  // the shrinking's nodes where the field is at its base, the octree's elsewhere; none closer
  // to another than kApart sizes (finest first)
  std::vector<std::pair<Vec3, double>> all = fine;
  for (const Vec3& p : uniform) all.push_back({p, h.at(p)});
  std::stable_sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  Grid grid(kApart * np);
  std::vector<Vec3> out;
  std::vector<double> size;
  for (const auto& [p, s] : all) {
    const bool crowded = grid.any_near(p, [&](std::size_t id) { return (out[id] - p).norm() < kApart * std::max(s, size[id]); });
    if (crowded) continue;
    grid.add(p, out.size());
    out.push_back(p);
    size.push_back(s);
    if (graded && s < kFine * np) ++*graded;
  }
  return out;
}

}  // namespace bisect::nodes
