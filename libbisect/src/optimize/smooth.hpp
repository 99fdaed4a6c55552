// Laplace smoothing of the interior nodes (thesis 6.9.2, optimisation (2)): each free node moves
// to the mean of its neighbours when every tetrahedron around it stays positive and their
// smallest solid angle does not fall. Nodes marked `fixed` (on input faces and region
// interfaces) never move; every other node may (inside the cells, and on the cut faces, which
// the mesh no longer keeps once the cells are joined).
#pragma once
#include <vector>

#include "tet/tet_complex.hpp"

namespace bisect::optimize {

// One pass over the free nodes of the tetrahedra `tets` (live ones of cx), each node once, in
// the order of their numbers. cx must work on X and hold every tetrahedron's current key; the
// tetrahedra around a moved node get theirs again (TetComplex::moved). Returns the moves made.
std::size_t smooth_nodes(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed, const std::vector<Index>& tets);

}  // namespace bisect::optimize
