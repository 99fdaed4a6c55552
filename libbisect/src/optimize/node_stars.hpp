// The star of a node (the tetrahedra around it), which the node moves of smoothing and sliver
// repair work on, and the optimiser's work lists.
#pragma once
#include <vector>

#include "tet/tet_complex.hpp"

namespace bisect::optimize {

using tet::Tet;

// The live tetrahedra around node v, found by a walk across the faces at v from t0 (a live
// tetrahedron with corner v; TetComplex::star): the cost is the star's, not the mesh's (no
// node-to-tetrahedron index to keep up through the flips). t0 comes first.
// With `limit`: the search stops once the star holds more than `limit` tetrahedra (what it
// returns is then only a part, larger than limit).
std::vector<Index> star(const tet::TetComplex& cx, Index v, Index t0, std::size_t limit = static_cast<std::size_t>(-1));

// The mean of the nodes sharing a tetrahedron of `around` with v.
Vec3 neighbour_mean(const std::vector<Vec3>& X, const std::vector<Tet>& tets, const std::vector<Index>& around, Index v);

// The live tetrahedra among `ids` (any order, repeats allowed) whose key (tet_angle_key, kept by
// cx) is below `key`, sorted and once each: a work list, the same for the same mesh.
std::vector<Index> below_key(const tet::TetComplex& cx, std::vector<Index> ids, double key);
// The same over the whole mesh (a scan of the stored keys).
std::vector<Index> all_below_key(const tet::TetComplex& cx, double key);

}  // namespace bisect::optimize
