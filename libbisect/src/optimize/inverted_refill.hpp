// The optimiser's last step for a tetrahedron still inside out once the passes are done: a cell
// filled in the proxy's geometry and moved onto a curved face can leave a fold that no flip,
// smoothing or node move undoes (a free node pressed against the face between three surface
// nodes, its star with no position that makes every tetrahedron positive). Such a fold is cut
// out with the stars of its free nodes and of those of the inverted tetrahedra next to it
// (grown by layers of neighbours while that fails, at most 4 layers and 4,000 tetrahedra) and the
// hole filled again, from a point that sees its whole boundary (the star fill, tet/cell_fill.hpp)
// or else by Delaunay boundary recovery (tet/recovery_fill.hpp): the hole's boundary triangles
// are kept, its inner nodes go back in where they lie inside it and drop out where they do not.
// A fill replaces the hole only when its outer faces are exactly the hole's boundary. Only tetrahedra of the
// fold's own region are cut out: input faces and interfaces stay as they are.
#pragma once
#include <cstddef>
#include <vector>

#include "tet/tet_complex.hpp"

namespace bisect::optimize {

struct RefillCounts {
  std::size_t refilled = 0;   // folds cut out and filled again
  std::size_t remaining = 0;  // tetrahedra still not positively oriented afterwards (optimize_mesh
                              // then skips the sliver repair and reports them as folds_left)
};

// cx works on X; fixed[v]: node v lies on an input face or interface (never inside a hole). The
// new tetrahedra are improved by the local transformations and go on cx.changed when it is set.
RefillCounts refill_inverted(tet::TetComplex& cx, const std::vector<Vec3>& X, const std::vector<char>& fixed);

// A tetrahedron of cx that is not positively oriented on X: its centroid, region tag and nodes
// (for the message that refuses the mesh); false when there is none.
bool find_fold(const tet::TetComplex& cx, const std::vector<Vec3>& X, Vec3* centroid, Index* region, tet::Tet* nodes = nullptr);

}  // namespace bisect::optimize
