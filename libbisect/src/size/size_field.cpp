#include "size/size_field.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "bisect/errors.hpp"

namespace bisect::size {
namespace {

constexpr int kLeaf = 8;

double box_distance(const Vec3& x, const Vec3& lo, const Vec3& hi) {
  return (x.cwiseMax(lo).cwiseMin(hi) - x).norm();
}

}  // namespace

SizeField::SizeField(double base, double grading, double min_size, double max_size)
    : base_(base), g_(grading), lo_(min_size), hi_(max_size) {
  if (!(base > 0) || !std::isfinite(base)) throw InputError("size field: the base size must be positive (got " + std::to_string(base) + ")");
  if (!(grading > 0) || !std::isfinite(grading)) throw InputError("size field: the grading must be positive (got " + std::to_string(grading) + ")");
  if (!(min_size >= 0) || !(max_size >= 0)) throw InputError("size field: minimum and maximum sizes must not be negative");
  if (max_size > 0 && min_size > max_size)
    throw InputError("size field: the minimum size " + std::to_string(min_size) + " exceeds the maximum " + std::to_string(max_size));
  if (hi_ > 0) base_ = std::min(base_, hi_);
  if (lo_ > 0) base_ = std::max(base_, lo_);
}

void SizeField::add(const Vec3& p, double s) {
  if (built_) throw MeshingError("size field: a source added after finish()");
  if (!(s > 0) || !p.allFinite()) return;
  if (lo_ > 0) s = std::max(s, lo_);
  if (s >= base_) return;
  src_.push_back({p, s});
}

int SizeField::build(int first, int count, const std::function<bool()>& cancelled) {
  Node n;
  n.lo = n.hi = src_[first].p;
  n.s_min = src_[first].s;
  for (int i = first; i < first + count; ++i) {
    n.lo = n.lo.cwiseMin(src_[i].p), n.hi = n.hi.cwiseMax(src_[i].p);
    n.s_min = std::min(n.s_min, src_[i].s);
  }
  n.first = first, n.count = count, n.left = n.right = -1;
  const int id = static_cast<int>(tree_.size());
  if (cancelled && id % 4096 == 0 && cancelled()) throw Cancelled();
  tree_.push_back(n);
  if (count > kLeaf) {
    int axis = 0;
    (n.hi - n.lo).maxCoeff(&axis);
    const int half = count / 2;
    std::nth_element(src_.begin() + first, src_.begin() + first + half, src_.begin() + first + count,
                     [axis](const SizeSource& a, const SizeSource& b) { return a.p[axis] < b.p[axis]; });
    const int l = build(first, half, cancelled);
    const int r = build(first + half, count - half, cancelled);
    tree_[id].left = l, tree_[id].right = r;
  }
  return id;
}

void SizeField::finish(const std::function<bool()>& cancelled) {
  tree_.clear();
  if (!src_.empty()) build(0, static_cast<int>(src_.size()), cancelled);
  built_ = true;
}

double SizeField::smallest() const {
  return tree_.empty() ? base_ : std::min(base_, tree_.front().s_min);
}

double SizeField::at(const Vec3& x) const {
  double best = base_;
  if (!tree_.empty()) {
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = tree_[stack[--top]];
      if (n.s_min + g_ * box_distance(x, n.lo, n.hi) >= best) continue;
      if (n.left < 0) {
        for (int i = n.first; i < n.first + n.count; ++i) best = std::min(best, src_[i].s + g_ * (x - src_[i].p).norm());
        continue;
      }
      // the nearer child last, so that it is searched first and tightens `best` early
      const Node &l = tree_[n.left], &r = tree_[n.right];
      const double dl = l.s_min + g_ * box_distance(x, l.lo, l.hi), dr = r.s_min + g_ * box_distance(x, r.lo, r.hi);
      if (top + 2 > 128) {  // a degenerate tree deeper than the stack: finish this part by brute force
        for (int i = n.first; i < n.first + n.count; ++i) best = std::min(best, src_[i].s + g_ * (x - src_[i].p).norm());
        continue;
      }
      if (dl < dr) stack[top++] = n.right, stack[top++] = n.left;
      else stack[top++] = n.left, stack[top++] = n.right;
    }
  }
  if (lo_ > 0) best = std::max(best, lo_);
  if (hi_ > 0) best = std::min(best, hi_);
  return best;
}

}  // namespace bisect::size
