// A small mesh for the node-move tests of optimize/.
#pragma once
#include <array>
#include <vector>

#include "bisect/types.hpp"

namespace bisect::optimize {

// A triangular bipyramid (apexes fixed at z = +-1, the equator fixed at z = 0) and one free node
// just under the top apex: the three tetrahedra between that node and the top faces are flat.
struct Bipyramid {
  std::vector<Vec3> X{{1, 0, 0}, {-0.5, 0.8660254037844386, 0}, {-0.5, -0.8660254037844386, 0}, {0, 0, 1}, {0, 0, -1}, {0.003, 0.004, 0.97}};
  std::vector<std::array<Index, 3>> boundary{{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, 4}, {2, 1, 4}, {0, 2, 4}};  // outward
  std::vector<char> fixed = std::vector<char>(6, 1);
  Bipyramid() { fixed[5] = 0; }
};

}  // namespace bisect::optimize
