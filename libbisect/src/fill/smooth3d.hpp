// Laplace smoothing of a tetrahedral mesh's interior nodes (thesis 6.9.2, optimisation (2)):
// each free node moves to the mean of its neighbours when every tetrahedron around it stays
// positive and their smallest solid angle does not fall; nodes below `first_free` (the face
// grids, on the boundary and on every face of every cell) never move.
#pragma once
#include <vector>

#include "fill/tet_complex.hpp"

namespace bisect::fill {

// Returns the number of moves made.
std::size_t smooth_interior(std::vector<Vec3>& X, const std::vector<Tet>& tets, std::size_t first_free, int passes);

}  // namespace bisect::fill
