// The B-rep route's sure way to fill a cell: in the geometry the decomposition made it in. Every
// node of a B-rep cell has a proxy position (where it sits on the convex proxy cell: a surface
// node on its proxy facet, a cut face node on the cut plane, an interior node where the shrinking
// put it) besides its true one. A cell that no point sees whole in its true geometry (a sliver
// beside a concave face whose bulge is wider than the cell) is still convex in the proxy's: it
// is filled there (thesis 7.6 as for any convex cell), the tetrahedra keep their nodes as the
// nodes move to their true positions, and any tetrahedron that turns inside out is untangled by
// moving its free nodes (each to the best of a few points between its proxy and true position,
// and its neighbours' mean, judged by the smallest volume round it; when none of those leaves
// every volume round it positive, the point farthest inside the planes of its star).
#pragma once
#include <array>
#include <vector>

#include "tet/cell_fill.hpp"

namespace bisect::pipeline {

// X, P: the cell's nodes at their true and proxy positions (the same ids; both get a helper node
// when one is needed, X moves during the untangling). boundary, interior, centroid_p as for
// tet::fill_convex_cell, in the proxy geometry. Throws MeshingError when the tetrahedra cannot
// be untangled; with keep_inverted (the last resort), what the untangling could not mend stays
// inverted: the global optimisation's flips across the cell's faces and, after them, the fold's
// refill (optimize/inverted_refill.hpp) are left to repair it (the mesh is checked at the end).
std::vector<tet::Tet> fill_in_proxy(std::vector<Vec3>& X, std::vector<Vec3>& P, const std::vector<std::array<Index, 3>>& boundary,
                                    const std::vector<Index>& interior, const Vec3& centroid_p, bool delaunay, tet::CellFillStats* stats,
                                    bool keep_inverted = false);

}  // namespace bisect::pipeline
