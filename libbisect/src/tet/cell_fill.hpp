// Boundary-constrained local min-max triangulation of one convex cell (thesis 7.6): every
// boundary triangle is joined to one interior node near the cell's centre (a convex cell is
// star-shaped from any interior point), the star is improved by the local transformations, and
// the other interior nodes are inserted one at a time (located by a walk; split inside a
// tetrahedron, on a face or on an edge), each followed by local improvement around it. A cell
// with no interior node gets a helper node at its centroid, removed at the end by the collapse
// onto the neighbour that leaves the best tetrahedra or else by flips (TetComplex::remove_vertex:
// edges at it taken out until a 4-1 flip removes it), either kept only when the cell's worst
// tetrahedron is no worse than with the helper; a helper that stays is a valid node of the mesh.
#pragma once
#include <functional>
#include <array>
#include <cstdint>
#include <vector>

#include "tet/tet_complex.hpp"

namespace bisect::tet {

struct CellFillStats {
  std::int64_t inserted = 0, skipped = 0, flips = 0;
  std::int64_t steiner = 0;  // Steiner points the fill by boundary recovery added (recovery_fill.hpp)
  bool helper = false, helper_removed = false;
};

// Whether p sees every boundary triangle (counter-clockwise from outside) from inside.
bool sees_all(const std::vector<Vec3>& X, const std::vector<std::array<Index, 3>>& boundary, const Vec3& p);

// A centre the whole boundary is seen from: one of the interior nodes nearest the centroid
// (*node >= 0), else a point (*node = -1 and *point: the centroid, or a point of the cell's
// kernel found by projections). False when there is none: the cell is not star-shaped.
bool star_centre(const std::vector<Vec3>& X, const std::vector<std::array<Index, 3>>& boundary, const std::vector<Index>& interior,
                 const Vec3& centroid, Index* node, Vec3* point);

// X: all nodes (a helper node is appended when needed). boundary: the cell's surface triangles
// (node ids), counter-clockwise seen from outside the cell. interior: node ids strictly inside.
// centroid: a point strictly inside (the cell's centroid). delaunay: insert with Delaunay
// cavities and improve once at the end, instead of the thesis's local min-max improvement after
// every insertion. Returns positively oriented tetrahedra
// whose boundary is exactly `boundary`. Throws MeshingError when the star cannot be built.
// cancelled (when set) is polled now and then (TetComplex::cancelled); true throws Cancelled.
std::vector<Tet> fill_convex_cell(std::vector<Vec3>& X, const std::vector<std::array<Index, 3>>& boundary,
                                  const std::vector<Index>& interior, const Vec3& centroid, bool delaunay = false,
                                  CellFillStats* stats = nullptr, const std::function<bool()>& cancelled = {});

}  // namespace bisect::tet
