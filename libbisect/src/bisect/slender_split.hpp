// Convex cells cut again across their length (the thesis's own tool, one more bisection) when
// they are long and thin and hold many elements. A 32 x 1 x 1 bar, or each plate of FreeCAD's
// bimetal strip (100 x 5 x 1), is one convex cell, and the star fill of such a cell from its
// centre is all needles: slow, and left with slivers that the optimisation cannot mend (the bar
// at R = 5*10^5: 15.7 s, smallest dihedral angle 0.03 degrees, 0.36% of the tetrahedra under 10;
// the strip at 1.5*10^5: 14 s, 0.01 degrees, 2.3% under 10). Cut into halves while slender:
// 8.1 s, 10.5 degrees and 2.3 s, 12.8 degrees, none under 10.
#pragma once
#include "bisect/polyhedral_model.hpp"

namespace bisect {

// A cell is cut when its extent along its longest principal axis (of its vertices) exceeds
// kSlenderAspect times that along its shortest, that shortest extent is at least
// kSlenderMinThickness nominal spacings (8 V / s^3 elements: opt.split_size, else from
// opt.split_elements and the model's volume), and it holds at least kSlenderMinElements
// elements by volume. A thin wall that the spacing crosses in one or two elements is no cell to
// cut: its cut faces only add constraints (the strip at R = 10^4, one element thick: 0.6 degrees
// cut, 21.6 uncut). Cells up to an aspect of 16 keep the star's speed and quality (a 16 x 1 x 1
// bar at 2*10^5: 3.6 s, 12.4 degrees; an 8 x 1 x 1 one 3.0 s, 11.9), and the large cells of the
// shared models stay under 13, so none of them is cut.
// The plane is normal to the longest axis through the middle of that extent, or a little off it
// where the cut code rejects the middle (near a vertex). Both halves are convex, and are cut
// again while they are slender. Counted in st.bisections["slender_split"].
inline constexpr double kSlenderAspect = 16;
inline constexpr double kSlenderMinThickness = 1.5;
inline constexpr double kSlenderMinElements = 2000;

void split_slender_cells(PolyhedralModel& m, const DecomposeOptions& opt, DecomposeStats& st);

}  // namespace bisect
