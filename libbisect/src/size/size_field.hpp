// The element size every stage of the B-rep route reads (ARCHITECTURE.md §1): one function
//
//     h(x) = clamp(min(base, min over sources i of s_i + g |x - p_i|), min_size, max_size)
//
// where `base` is the spacing from R or the absolute size (thesis 6.11), the sources are points
// that ask for a smaller size (curvature, short B-rep edges, the resolution hints, mesh
// regions), and g bounds the growth per unit of distance, so neighbouring elements never differ
// by more than the grading allows: no fans and no strips where a fine feature meets coarse
// elements. h is 1-Lipschitz times g wherever it is below base, by construction.
//
// Sources are kept in a bounding-volume tree with each node's smallest s, so a query visits the
// few nodes whose lower bound s_min + g dist(x, box) can beat the best found so far.
#pragma once
#include <functional>
#include <vector>

#include "bisect/types.hpp"

namespace bisect::size {

// Both routes' walls: elements no larger than this many times the wall's thickness where they stand. Uncapped, a
// 1 mm tube wall (FreeCAD's constraint_transform_torque) had 6 to 12% of its tetrahedra under 10
// degrees at spacings 1.2 to 1.7, a 50 x 20 x 1 plate a quarter at 1.1 to 1.5. The cap's field
// is not uniform (sources a third of a thickness apart, grown by the grading between them), and
// 1.0 and 0.9 still left some of these shapes' cells with a third of their tetrahedra under 10
// degrees; 0.8 left none in the shapes measured (plate, tube, two bonded plates, a 1 mm disc).
inline constexpr double kWallSizeFactor = 0.8;

struct SizeSource {
  Vec3 p;
  double s;
};

class SizeField {
 public:
  // base > 0; grading > 0; min_size / max_size: 0 for none.
  SizeField(double base, double grading, double min_size = 0, double max_size = 0);

  // Sources asking for at least base (after clamping) are dropped; call finish() before at().
  void add(const Vec3& p, double s);
  // Builds the tree; `cancelled` (optional) is asked every few thousand nodes, and a true answer
  // throws Cancelled (a 5 mm cylinder's curvature samples at a chord deviation of 3e-4: 1.2 s
  // of a sanitizer build).
  void finish(const std::function<bool()>& cancelled = {});

  double at(const Vec3& x) const;
  double base() const { return base_; }
  double grading() const { return g_; }
  double smallest() const;  // the smallest size anywhere (a source's, or base)
  std::size_t sources() const { return src_.size(); }

 private:
  struct Node {
    Vec3 lo, hi;
    double s_min;
    int first, count;   // leaf: sources [first, first + count)
    int left, right;    // inner node: children (-1 for a leaf)
  };
  double base_, g_, lo_, hi_;
  std::vector<SizeSource> src_;
  std::vector<Node> tree_;
  bool built_ = false;
  int build(int first, int count, const std::function<bool()>& cancelled);
};

}  // namespace bisect::size
