#include "nodes/graded_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

namespace bisect::nodes {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Nodes closer than this many local sizes are too close (the shrinking merges at 1/2 Np; a
// little more keeps the graded shells from crowding).
constexpr double kMinDistance = 0.7;
// Graded nodes whose size is within this fraction of Np are left to the shrinking's nodes.
constexpr double kHandOver = 0.9;

// Points in a uniform grid of cubes, for "anything within r of p" queries.
class PointGrid {
 public:
  explicit PointGrid(double cube) : inv_(1 / cube) {}
  void add(const Vec3& p, std::size_t id) { cubes_[key(cube_of(p))].push_back(id); }
  // f(id) for the points in the cubes that a ball of radius r around p touches; stops when f
  // returns true, and returns whether it did
  template <class F>
  bool any_near(const Vec3& p, double r, F f) const {
    const auto lo = cube_of(p - Vec3::Constant(r)), hi = cube_of(p + Vec3::Constant(r));
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
          const auto it = cubes_.find(key({x, y, z}));
          if (it == cubes_.end()) continue;
          for (std::size_t id : it->second)
            if (f(id)) return true;
        }
    return false;
  }

 private:
  std::array<std::int64_t, 3> cube_of(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() * inv_)), static_cast<std::int64_t>(std::floor(p.y() * inv_)),
            static_cast<std::int64_t>(std::floor(p.z() * inv_))};
  }
  static std::uint64_t key(const std::array<std::int64_t, 3>& c) {
    const auto part = [](std::int64_t v) { return static_cast<std::uint64_t>(v + (1 << 20)) & 0x1fffff; };
    return part(c[0]) | part(c[1]) << 21 | part(c[2]) << 42;
  }
  double inv_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cubes_;
};

// A deterministic number in [-0.5, 0.5) from two integers (splitmix64).
double jitter(std::uint64_t a, std::uint64_t b) {
  std::uint64_t z = a * 0x9E3779B97F4A7C15ull + b + 0x632BE59BD9B4E019ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) / 9007199254740992.0 - 0.5;
}

// Signed distance from p to the cell's boundary, negative inside (the largest face distance).
double face_distance(const Polytope& c, const Vec3& p) {
  double d = -1e300;
  for (std::size_t f = 0; f < c.normal.size(); ++f) d = std::max(d, c.normal[f].dot(p) - c.offset[f]);
  return d;
}

}  // namespace

std::vector<std::vector<Vec3>> graded_cell_nodes(const std::vector<Polytope>& cells, const std::vector<std::vector<Vec3>>& uniform,
                                                 const std::vector<Vec3>& boundary, const std::vector<double>& spacing, double np,
                                                 double grading, GradedNodeStats* stats) {
  GradedNodeStats st;
  if (grading <= 0) {
    if (stats) *stats = st;
    return uniform;
  }
  // the sources: boundary nodes that want less than Np (short edges of the face grids)
  std::vector<std::size_t> sources;
  for (std::size_t v = 0; v < boundary.size() && v < spacing.size(); ++v)
    if (spacing[v] > 0 && spacing[v] < kHandOver * np) sources.push_back(v);
  st.sources = sources.size();
  if (sources.empty()) {
    if (stats) *stats = st;
    return uniform;
  }
  // h(x), from the sources within reach (beyond it a source's size has grown past Np)
  double finest = np;
  for (std::size_t v : sources) finest = std::min(finest, spacing[v]);
  const double reach = (np - finest) / grading;
  PointGrid source_grid(std::max(reach, 1e-12 * np));
  for (std::size_t k = 0; k < sources.size(); ++k) source_grid.add(boundary[sources[k]], k);
  auto size_at = [&](const Vec3& p) {
    double h = np;
    source_grid.any_near(p, reach, [&](std::size_t k) {
      const std::size_t v = sources[k];
      h = std::min(h, spacing[v] + grading * (p - boundary[v]).norm());
      return false;
    });
    return h;
  };
  // cell bounding boxes, to find the cell holding a point
  std::vector<std::pair<Vec3, Vec3>> box(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (const Vec3& p : cells[c].v) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    box[c] = {lo, hi};
  }
  // graded candidates: shells around each source at radii stepping by the size there, points
  // spread by a golden-angle spiral at that size, the radius jittered (a shell's points are
  // co-spherical with its source, the tie that makes slivers)
  struct Candidate {
    Vec3 p;
    double h;
    int cell;
  };
  std::vector<Candidate> graded;
  const double golden = kPi * (3 - std::sqrt(5.0));
  for (std::size_t k = 0; k < sources.size(); ++k) {
    const Vec3& b = boundary[sources[k]];
    const double s = spacing[sources[k]];
    for (double r = s; s + grading * r < kHandOver * np; r += 0.85 * (s + grading * r)) {
      const double h = s + grading * r;
      const std::size_t n = static_cast<std::size_t>(std::ceil(4 * kPi * r * r / (0.8 * h * 0.8 * h)));
      for (std::size_t i = 0; i < n; ++i) {
        const double z = 1 - 2 * (static_cast<double>(i) + 0.5) / static_cast<double>(n);
        const double phi = golden * static_cast<double>(i) + 2 * kPi * (jitter(k, 0) + 0.5);
        const double rho = r * (1 + 0.15 * jitter(k, i + 1));
        const Vec3 p = b + rho * Vec3(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
        const double hp = size_at(p);
        for (std::size_t c = 0; c < cells.size(); ++c) {
          if ((p - box[c].first).minCoeff() < 0 || (box[c].second - p).minCoeff() < 0) continue;
          const double d = face_distance(cells[c], p);
          if (d >= 0) continue;  // not in this cell
          if (d <= -0.5 * hp) graded.push_back({p, hp, static_cast<int>(c)});
          break;  // cells do not overlap
        }
      }
    }
  }
  // finest first; among equal sizes in the order made
  std::vector<std::size_t> order(graded.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return graded[a].h < graded[b].h; });
  PointGrid kept_grid(kMinDistance * np);
  std::vector<char> kept(graded.size(), 0);
  for (std::size_t i : order) {
    const Candidate& c = graded[i];
    const double too_close = kMinDistance * c.h;
    if (kept_grid.any_near(c.p, too_close, [&](std::size_t j) { return (graded[j].p - c.p).norm() < too_close; })) continue;
    kept[i] = 1;
    kept_grid.add(c.p, i);
  }
  // the shrinking's nodes, less those a kept graded node crowds; then the graded nodes
  std::vector<std::vector<Vec3>> out(cells.size());
  for (std::size_t c = 0; c < cells.size() && c < uniform.size(); ++c)
    for (const Vec3& p : uniform[c]) {
      const double too_close = kMinDistance * size_at(p);
      if (kept_grid.any_near(p, too_close, [&](std::size_t j) { return (graded[j].p - p).norm() < too_close; })) {
        ++st.dropped;
        continue;
      }
      out[c].push_back(p);
    }
  for (std::size_t i = 0; i < graded.size(); ++i)
    if (kept[i]) {
      out[static_cast<std::size_t>(graded[i].cell)].push_back(graded[i].p);
      ++st.added;
    }
  if (stats) *stats = st;
  return out;
}

}  // namespace bisect::nodes
