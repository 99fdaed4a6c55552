// The walls of a polyhedral input's convex cells (issue 17, the polyhedral route's counterpart of
// wall_thickness.hpp): a cell with two input faces facing each other across it (outward normals
// within 25 degrees of opposite) lies in a wall of that thickness, and no element across it may
// be larger than kWallSizeFactor times it, or the shrinking puts no node between the two faces
// and the tetrahedra join their grids flat (cantilever.stl, a 10 x 10 bar, at R = 50: spacing
// 11.7, smallest dihedral 5.7 degrees). Cut faces do not count: a cell the decomposition cut
// thin from a thick region is no wall, and its neighbours' nodes fill it.
#pragma once
#include <vector>

#include "bisect/polyhedral_model.hpp"

namespace bisect::size {

// Per cell of d: the thickness between its closest pair of facing input faces (the mean depth
// of each face's corners below the other's plane), 0 when it has no such pair.
std::vector<double> cell_wall_thickness(const Decomposition& d);

}  // namespace bisect::size
