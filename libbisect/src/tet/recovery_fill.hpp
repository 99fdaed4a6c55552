// A cell that no point sees whole, filled the way Delaunay meshers fill a polyhedron: its
// boundary nodes go into a Delaunay tetrahedralization of a box around them, the boundary
// triangles that are not faces of it are restored by local re-triangulation (face_recovery.hpp;
// never a point on the boundary, which is shared with the neighbouring cells, and inside only
// where the caller allows Steiner points), and when every
// boundary triangle is a face, the tetrahedra inside the boundary are the cell's. The interior nodes then go in with Delaunay cavities that never cross
// the boundary, and the min-max transformations (thesis 7.5) improve the result, as in 7.6.
//
// The B-rep route's fourth fill (brep_cells.hpp): after the star fill, the fill in the proxy's
// geometry and the cells joined with neighbours, before the last resort. It needs no point that
// sees the whole boundary, so a long cell beside a curved face, whose far triangles the bulge
// tilts past every line of sight, is filled as it is.
#pragma once
#include <array>
#include <vector>

#include "tet/cell_fill.hpp"

namespace bisect::tet {

// X: the cell's nodes; boundary: its surface triangles, counter-clockwise seen from outside;
// interior: node ids strictly inside. Returns positively oriented tetrahedra whose boundary is
// exactly `boundary` (interior nodes that fall outside or on another node are skipped, and
// counted). Throws MeshingError when a boundary triangle cannot be made a face of the Delaunay
// tetrahedralization of the boundary nodes, or the inside cannot be told from the outside.
// steiner: null, no node is added; else Steiner points are allowed where a missing triangle's
// hole needs one (face_recovery.hpp), and those the tetrahedra use are returned there, as nodes
// X.size(), X.size() + 1, ... (counted in stats->steiner).
std::vector<Tet> fill_by_recovery(const std::vector<Vec3>& X, const std::vector<std::array<Index, 3>>& boundary,
                                  const std::vector<Index>& interior, CellFillStats* stats = nullptr,
                                  std::vector<Vec3>* steiner = nullptr);

}  // namespace bisect::tet
