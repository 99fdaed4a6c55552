#include "pipeline/brep_morph.hpp"

#include <algorithm>
#include <numeric>

namespace bisect::pipeline {
namespace {

constexpr int kLeaf = 16;

}  // namespace

Morph::Morph(const BoundaryNodes& nodes, const size::SizeField& h) : h_(h) {
  for (std::size_t i = 0; i < nodes.x.size(); ++i)
    if (nodes.on[i].kind != PointOn::kInterior) {
      p_.push_back(nodes.p[i]);
      d_.push_back(nodes.x[i] - nodes.p[i]);
    }
  if (!p_.empty()) build(0, static_cast<int>(p_.size()), 0);
}

int Morph::build(int first, int count, int depth) {
  const int id = static_cast<int>(tree_.size());
  tree_.push_back({first, count, -1, -1, 0, 0});
  if (count <= kLeaf || depth > 60) return id;
  Vec3 lo = p_[first], hi = p_[first];
  for (int i = first; i < first + count; ++i) lo = lo.cwiseMin(p_[i]), hi = hi.cwiseMax(p_[i]);
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  const int half = count / 2;
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), first);
  std::nth_element(order.begin(), order.begin() + half, order.end(), [&](int a, int b) { return p_[a][axis] < p_[b][axis]; });
  std::vector<Vec3> p(count), d(count);
  for (int i = 0; i < count; ++i) p[i] = p_[order[i]], d[i] = d_[order[i]];
  std::copy(p.begin(), p.end(), p_.begin() + first);
  std::copy(d.begin(), d.end(), d_.begin() + first);
  tree_[id].axis = axis;
  tree_[id].split = p_[first + half][axis];
  const int l = build(first, half, depth + 1);
  const int r = build(first + half, count - half, depth + 1);
  tree_[id].left = l, tree_[id].right = r;
  return id;
}

Vec3 Morph::displacement(const Vec3& p) const {
  if (tree_.empty()) return Vec3::Zero();
  const double rho = 2 * h_.at(p), rho2 = rho * rho, eps2 = 1e-6 * rho2;
  Vec3 sum = Vec3::Zero();
  double weights = 0, nearest2 = rho2;
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const KdNode& n = tree_[stack[--top]];
    if (n.left < 0) {
      for (int i = n.first; i < n.first + n.count; ++i) {
        const double d2 = (p_[i] - p).squaredNorm();
        if (d2 >= rho2) continue;
        const double s = 1 - d2 / rho2, near = d2 + eps2, w = s * s * s / (near * near);
        sum += w * d_[i], weights += w;
        nearest2 = std::min(nearest2, d2);
      }
      continue;
    }
    const double off = p[n.axis] - n.split;
    if (top + 2 > 128) continue;
    if (off < rho) stack[top++] = n.left;
    if (off > -rho) stack[top++] = n.right;
  }
  if (!(weights > 0)) return Vec3::Zero();
  const double s = 1 - nearest2 / rho2;
  return (s * s * s) * sum / weights;
}

}  // namespace bisect::pipeline
