// The local thickness of a B-rep's solids (issue 17: good elements at every count): from points
// on every face of a solid, a ray goes into the material along the face's inward normal, and the
// distance to where it leaves the solid (the first tessellation triangle it meets) is the wall's
// thickness there. brep_sizes.hpp caps the element size by it: where the spacing is larger than a
// wall is thick, no interior node fits across the wall, the tetrahedra join the grids of its two
// sides, which are not in line, and many of them come out flat (a 1 mm tube wall at spacing 1.2
// to 1.7: 6 to 12% of the tetrahedra under 10 degrees; at spacing 1, none).
//
// Found on the tessellation (the proxy's facets), and measured between the true surfaces where
// it is under twice the limit: from where the ray's line meets the start's face to where it
// meets the exit's (Newton steps from the facets' points). On the facets alone it was off by up
// to the tessellation's deflection, which can be most of a thin wall's thickness. A ray is not stopped
// by a face that shares a B-rep vertex with the face it starts from: beside an edge where two
// faces meet at an acute angle that distance goes to nought and asks for ever smaller elements,
// which the edge's angle bounds anyway (Angled.step came out with a tetrahedron inside out).
#pragma once
#include <vector>

#include "bisect/brep_input.hpp"

namespace bisect::size {

struct WallSample {
  Vec3 p;            // a point on a face (on its tessellation)
  double thickness;  // the solid's extent from p along the face's inward normal
};

// Samples over every face of every solid where the wall is thinner than `limit`: each
// tessellation triangle is probed at its centre and near its corners, and where a probe finds
// less than `limit`, sampled about one thickness apart (at most 64 subdivisions of its longest
// edge). An interface face (listed by two solids) is sampled into both. A ray that leaves
// through nothing (an open shell) gives no sample.
std::vector<WallSample> wall_thickness(const BrepInput& in, const BrepTessellation& tess, double limit);

}  // namespace bisect::size
