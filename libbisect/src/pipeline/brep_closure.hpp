// The B-rep route's check that each solid is closed, before anything is tessellated: a solid
// made from an open shell (FreeCAD's Part.Solid of five faces of a box) encloses nothing, and the
// user is told which edge is open, by FreeCAD's names.
#pragma once
#include "bisect/brep_input.hpp"

namespace bisect::pipeline {

// Throws InputError naming the solid, the first free edge and the face it bounds when an edge of
// a solid's faces (not degenerate) is used by only one of them once (a seam edge is used twice by
// its face).
void check_solids_closed(const BrepInput& in);

}  // namespace bisect::pipeline
