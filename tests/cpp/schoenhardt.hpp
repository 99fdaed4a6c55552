// Schönhardt's twisted prism, for the tests of the fills that add Steiner points: a triangle
// prism whose top is turned by `twist` and whose three sides are each split along the diagonal
// that folds in. No tetrahedralization of its six corners alone fills it.
#pragma once
#include <array>
#include <cmath>
#include <vector>

#include "bisect/types.hpp"

namespace bisect::test {

struct TwistedPrism {
  std::vector<Vec3> X;                          // bottom corners 0..2 (z = 0), top 3..5 (z = 1)
  std::vector<std::array<Index, 3>> boundary;   // counter-clockwise seen from outside
};

inline TwistedPrism schoenhardt_prism(double twist_deg = 25) {
  TwistedPrism p;
  const double twist = twist_deg * M_PI / 180;
  for (int i = 0; i < 3; ++i) p.X.push_back(Vec3(std::cos(2 * M_PI * i / 3), std::sin(2 * M_PI * i / 3), 0));
  for (int i = 0; i < 3; ++i) p.X.push_back(Vec3(std::cos(2 * M_PI * i / 3 + twist), std::sin(2 * M_PI * i / 3 + twist), 1));
  p.boundary.push_back({0, 2, 1});  // bottom, seen from below
  p.boundary.push_back({3, 4, 5});  // top
  // each side (a_i, a_i+1, b_i+1, b_i) split along a_i b_i+1, which the counter-clockwise twist
  // folds in
  for (Index i = 0; i < 3; ++i) {
    const Index a0 = i, a1 = (i + 1) % 3, b0 = 3 + i, b1 = 3 + (i + 1) % 3;
    p.boundary.push_back({a0, a1, b1});
    p.boundary.push_back({a0, b1, b0});
  }
  return p;
}

}  // namespace bisect::test
