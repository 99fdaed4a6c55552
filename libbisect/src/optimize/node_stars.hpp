// The star of a node (the tetrahedra around it), which the node moves of smoothing and sliver
// repair work on.
#pragma once
#include <vector>

#include "tet/tet_complex.hpp"

namespace bisect::optimize {

using tet::Tet;

// The tetrahedra around each node (only the live ones when `alive` is given).
std::vector<std::vector<Index>> incidence(std::size_t nodes, const std::vector<Tet>& tets, const std::vector<char>* alive);

// The mean of the nodes sharing a tetrahedron of `around` with v.
Vec3 neighbour_mean(const std::vector<Vec3>& X, const std::vector<Tet>& tets, const std::vector<Index>& around, Index v);

}  // namespace bisect::optimize
