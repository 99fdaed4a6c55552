// Triangle neighbours across edges, built once per pass by the optimisation routines.
#pragma once
#include <array>
#include <utility>
#include <vector>

#include "mesh2d/tri_mesh2.hpp"

namespace bisect::mesh2d {

// across[t][k] = (t', k'): the triangle on the other side of the edge opposite corner k of t,
// and its corner opposite that edge; (-1, -1) on a boundary.
using TriAcross = std::vector<std::array<std::pair<int, int>, 3>>;
TriAcross triangle_neighbours(const TriMesh2& m);

}  // namespace bisect::mesh2d
