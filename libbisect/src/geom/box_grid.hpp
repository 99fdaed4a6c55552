// A uniform grid of boxes that lists, in each box, the items whose bounding boxes meet it: the
// candidate pairs of the self-intersection checks come from it in about O(n) for n items of
// similar size. Boxes are stored by their integer coordinates (a hash collision shares a bucket,
// never a box), and are visited in the hash table's order, which depends only on the insertions.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "bisect/types.hpp"

namespace bisect::geom {

class BoxGrid {
 public:
  using Coord = std::array<std::int64_t, 3>;

  // Boxes of side h, with a corner at origin.
  BoxGrid(const Vec3& origin, double h) : origin_(origin), h_(h) {}

  Coord box_of(const Vec3& x) const {
    return {cell(x.x(), origin_.x()), cell(x.y(), origin_.y()), cell(x.z(), origin_.z())};
  }

  // Lists item in every box that the box [lo, hi] meets.
  void insert(std::size_t item, const Vec3& lo, const Vec3& hi) {
    const Coord l = box_of(lo), u = box_of(hi);
    for (std::int64_t i = l[0]; i <= u[0]; ++i)
      for (std::int64_t j = l[1]; j <= u[1]; ++j)
        for (std::int64_t k = l[2]; k <= u[2]; ++k) box({i, j, k}).push_back(item);
  }

  // f(item) for each listing of an item in a box that [lo, hi] meets: an item met in several
  // boxes comes once per box.
  template <class F>
  void visit(const Vec3& lo, const Vec3& hi, F&& f) const {
    const Coord l = box_of(lo), u = box_of(hi);
    for (std::int64_t i = l[0]; i <= u[0]; ++i)
      for (std::int64_t j = l[1]; j <= u[1]; ++j)
        for (std::int64_t k = l[2]; k <= u[2]; ++k)
          if (const std::vector<std::size_t>* items = find({i, j, k}))
            for (std::size_t item : *items) f(item);
  }

  // f(coordinates, items) for every box that lists an item.
  template <class F>
  void for_each_box(F&& f) const {
    for (const auto& [key, bucket] : boxes_)
      for (const Box& b : bucket) f(b.at, b.items);
  }

 private:
  struct Box {
    Coord at;
    std::vector<std::size_t> items;
  };

  std::int64_t cell(double x, double o) const { return static_cast<std::int64_t>(std::floor((x - o) / h_)); }
  static std::uint64_t key(const Coord& c) {
    return (static_cast<std::uint64_t>(c[0]) * 73856093u) ^ (static_cast<std::uint64_t>(c[1]) * 19349663u) ^
           (static_cast<std::uint64_t>(c[2]) * 83492791u);
  }
  std::vector<std::size_t>& box(const Coord& c) {
    std::vector<Box>& bucket = boxes_[key(c)];
    for (Box& b : bucket)
      if (b.at == c) return b.items;
    bucket.push_back({c, {}});
    return bucket.back().items;
  }
  const std::vector<std::size_t>* find(const Coord& c) const {
    const auto it = boxes_.find(key(c));
    if (it == boxes_.end()) return nullptr;
    for (const Box& b : it->second)
      if (b.at == c) return &b.items;
    return nullptr;
  }

  Vec3 origin_;
  double h_;
  std::unordered_map<std::uint64_t, std::vector<Box>> boxes_;
};

}  // namespace bisect::geom
