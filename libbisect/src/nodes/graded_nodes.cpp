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

// The size field's sources in a k-d tree, each box with the finest spacing below it, for
// h(x) = min(Np, min_b s_b + g |x - b|) by branch and bound: a box none of whose sources can
// beat the best found (its finest spacing plus g times its distance from x) is skipped. The
// terms that are evaluated are the same expression as a scan of all sources, and a minimum does
// not depend on the order, so h is the same to the bit; but near a cluster of short edges a
// point looks at a few dozen sources, not all of them (flange.stl at R = 2·10^4 and G = 0.3: the
// scan took minutes).
class SourceTree {
 public:
  SourceTree(const std::vector<Vec3>& points, const std::vector<double>& spacing, const std::vector<std::size_t>& ids, double grading)
      : X_(points), s_(spacing), ids_(ids), g_(grading) {
    if (!ids_.empty()) build(0, ids_.size(), 0);
  }
  // `start`: a bound already known (a source's own term), which prunes from the first box on
  double size_at(const Vec3& p, double np, double start = 1e300) const {
    double h = std::min(np, start);
    if (!nodes_.empty()) visit(0, p, h);
    return h;
  }

 private:
  struct Node {
    Vec3 lo, hi;
    double finest;
    std::size_t begin, end;
    int left = -1, right = -1;
  };
  static constexpr std::size_t kLeaf = 8;

  int build(std::size_t begin, std::size_t end, int depth) {
    Node n;
    n.lo = Vec3::Constant(1e300), n.hi = Vec3::Constant(-1e300), n.finest = 1e300, n.begin = begin, n.end = end;
    for (std::size_t k = begin; k < end; ++k) {
      const Vec3& q = X_[ids_[k]];
      n.lo = n.lo.cwiseMin(q), n.hi = n.hi.cwiseMax(q), n.finest = std::min(n.finest, s_[ids_[k]]);
    }
    const int at = static_cast<int>(nodes_.size());
    nodes_.push_back(n);
    if (end - begin > kLeaf) {
      int axis = 0;
      (n.hi - n.lo).maxCoeff(&axis);
      const std::size_t mid = begin + (end - begin) / 2;
      std::nth_element(ids_.begin() + static_cast<std::ptrdiff_t>(begin), ids_.begin() + static_cast<std::ptrdiff_t>(mid),
                       ids_.begin() + static_cast<std::ptrdiff_t>(end),
                       [&](std::size_t a, std::size_t b) { return X_[a][axis] < X_[b][axis]; });
      const int l = build(begin, mid, depth + 1), r = build(mid, end, depth + 1);
      nodes_[static_cast<std::size_t>(at)].left = l, nodes_[static_cast<std::size_t>(at)].right = r;
    }
    return at;
  }
  double bound(const Node& n, const Vec3& p) const {
    const Vec3 d = (n.lo - p).cwiseMax(p - n.hi).cwiseMax(0.0);
    return n.finest + g_ * d.norm();
  }
  void visit(int i, const Vec3& p, double& h) const {
    const Node& n = nodes_[static_cast<std::size_t>(i)];
    if (n.left < 0) {
      for (std::size_t k = n.begin; k < n.end; ++k) {
        const std::size_t v = ids_[k];
        h = std::min(h, s_[v] + g_ * (p - X_[v]).norm());
      }
      return;
    }
    const double bl = bound(nodes_[static_cast<std::size_t>(n.left)], p), br = bound(nodes_[static_cast<std::size_t>(n.right)], p);
    const int first = bl <= br ? n.left : n.right, second = bl <= br ? n.right : n.left;
    if (std::min(bl, br) < h) visit(first, p, h);
    if (std::max(bl, br) < h) visit(second, p, h);
  }

  const std::vector<Vec3>& X_;
  const std::vector<double>& s_;
  std::vector<std::size_t> ids_;
  double g_;
  std::vector<Node> nodes_;
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
  // h(x): the sources that can give less than Np (beyond (Np - s) / G a source's size is past it)
  const SourceTree source_tree(boundary, spacing, sources, grading);
  auto size_at = [&](const Vec3& p) { return source_tree.size_at(p, np); };
  // at a point of source v's shell, v's own term (the same expression) is the bound to start from
  auto size_near = [&](const Vec3& p, std::size_t v) {
    return source_tree.size_at(p, np, spacing[v] + grading * (p - boundary[v]).norm());
  };
  // cell bounding boxes, to find the cell holding a point: a grid of buckets over all of them,
  // each listing the cells whose box meets it in cell order, so a point is tested against a few
  // cells, and the first that holds it is the one a scan of all cells finds
  std::vector<std::pair<Vec3, Vec3>> box(cells.size());
  Vec3 all_lo = Vec3::Constant(1e300), all_hi = Vec3::Constant(-1e300);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (const Vec3& p : cells[c].v) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    box[c] = {lo, hi};
    all_lo = all_lo.cwiseMin(lo), all_hi = all_hi.cwiseMax(hi);
  }
  const int per_axis = std::clamp(static_cast<int>(std::cbrt(8.0 * static_cast<double>(cells.size()))), 1, 64);
  const Vec3 bucket = ((all_hi - all_lo) / per_axis).cwiseMax(1e-300);
  const auto bucket_of = [&](const Vec3& p, int axis) {
    return std::clamp(static_cast<int>(std::floor((p[axis] - all_lo[axis]) / bucket[axis])), 0, per_axis - 1);
  };
  std::vector<std::vector<int>> buckets(static_cast<std::size_t>(per_axis * per_axis * per_axis));
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (cells[c].v.empty()) continue;
    for (int x = bucket_of(box[c].first, 0); x <= bucket_of(box[c].second, 0); ++x)
      for (int y = bucket_of(box[c].first, 1); y <= bucket_of(box[c].second, 1); ++y)
        for (int z = bucket_of(box[c].first, 2); z <= bucket_of(box[c].second, 2); ++z)
          buckets[static_cast<std::size_t>((x * per_axis + y) * per_axis + z)].push_back(static_cast<int>(c));
  }
  const auto cell_of = [&](const Vec3& p) {  // -1: in no cell
    if ((p - all_lo).minCoeff() < 0 || (all_hi - p).minCoeff() < 0) return std::make_pair(-1, 0.0);
    for (int c : buckets[static_cast<std::size_t>((bucket_of(p, 0) * per_axis + bucket_of(p, 1)) * per_axis + bucket_of(p, 2))]) {
      const auto& [lo, hi] = box[static_cast<std::size_t>(c)];
      if ((p - lo).minCoeff() < 0 || (hi - p).minCoeff() < 0) continue;
      const double d = face_distance(cells[static_cast<std::size_t>(c)], p);
      if (d < 0) return std::make_pair(c, d);  // cells do not overlap
    }
    return std::make_pair(-1, 0.0);
  };
  // graded candidates: shells around each source at radii stepping by the size there, points
  // spread by a golden-angle spiral at that size, the radius jittered (a shell's points are
  // co-spherical with its source, the tie that makes slivers). The size at a point is looked up
  // only for points inside a cell, and the shells stop once they lie wholly outside the cells'
  // box (at a coarse trial spacing of the count calibration they grow to several model sizes).
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
    const double farthest = (b - all_lo).cwiseAbs().cwiseMax((all_hi - b).cwiseAbs()).norm();
    for (double r = s; s + grading * r < kHandOver * np; r += 0.85 * (s + grading * r)) {
      if (r * (1 - 0.075) > farthest) break;  // every point of this shell and beyond is outside
      const double h = s + grading * r;
      const std::size_t n = static_cast<std::size_t>(std::ceil(4 * kPi * r * r / (0.8 * h * 0.8 * h)));
      for (std::size_t i = 0; i < n; ++i) {
        const double z = 1 - 2 * (static_cast<double>(i) + 0.5) / static_cast<double>(n);
        const double phi = golden * static_cast<double>(i) + 2 * kPi * (jitter(k, 0) + 0.5);
        const double rho = r * (1 + 0.15 * jitter(k, i + 1));
        const Vec3 p = b + rho * Vec3(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
        const auto [c, d] = cell_of(p);
        if (c < 0) continue;
        const double hp = size_near(p, sources[k]);
        if (d <= -0.5 * hp) graded.push_back({p, hp, c});
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
