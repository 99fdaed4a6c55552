// A convex cell halved across its length: what the cuts made after the convex decomposition
// share (slender_split for needle-making cells, balance_split for cells too large for the
// threads' share). The thesis's own tool, one more bisection, with a plane normal to the cell's
// longest principal axis through the middle of its extent there.
#pragma once
#include <functional>
#include <vector>

#include "bisect/polyhedral_model.hpp"

namespace bisect {

// The principal axes of a cell's vertices (shortest spread first) and the extent of its
// vertices along each.
struct CellExtents {
  Vec3 axis[3];
  double lo[3], hi[3];
  double length(int k) const { return hi[k] - lo[k]; }
  int longest() const;
  double shortest() const;
};

CellExtents principal_extents(const PolyhedralModel& m, Index r);

// Elements per unit volume of the mesh asked for (8 V / s^3 for opt.split_size, else
// opt.split_elements over the live regions' volume); 0 when neither is set. Fills *volume with
// the live regions' volume.
double nominal_density(const PolyhedralModel& m, const DecomposeOptions& opt, double* volume = nullptr);

// Cuts region r normal to e's longest axis through the middle of that extent, or a little off it
// where the cut is rejected there (near a vertex). Appends the new regions to `halves` and
// returns true when a cut was made.
bool halve_cell(PolyhedralModel& m, Index r, const CellExtents& e, const DecomposeOptions& opt, std::vector<Index>& halves);

// Halves every live cell while it holds at least min_elements by volume (at opt's nominal
// density), is at least min_thickness nominal spacings thick along its shortest principal axis,
// and `also` accepts its extents; a cell's halves are asked again. Counts each cut in
// st.bisections[key]. The loop of both rules after the convex decomposition: slender_split
// (also: long for its thickness) and balance_split (a share of the job).
void halve_cells_while(PolyhedralModel& m, const DecomposeOptions& opt, DecomposeStats& st, const char* key,
                       double min_elements, double min_thickness, const std::function<bool(const CellExtents&)>& also);

}  // namespace bisect
