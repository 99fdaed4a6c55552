// The mesh the B-rep route hands out, and its order 2 on the true surfaces.
//
// Mid-nodes of boundary edges go onto the B-rep: at the edge's middle parameter for an edge of
// the mesh along a B-rep edge, else at the middle of the two ends' (u, v) on the face; interior
// mid-nodes are straight. Every element's Jacobian determinant must then stay positive at its
// corners and at the 4 Gauss points CalculiX integrates at (bisect::tet10_jacobian_ratio); where
// the curved boundary folds an element, its interior mid-nodes move along with the curve (the
// best of a few fractions of the boundary's displacement, judged over every element on that
// edge), and as a last resort the element's curved boundary edges are made straight again,
// counted in the stats. No element leaves with a non-positive Jacobian.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "bisect/brep_input.hpp"
#include "bisect/tet_mesh.hpp"
#include "pipeline/brep_grids.hpp"
#include "tet/tet_complex.hpp"

namespace bisect::pipeline {

// The used nodes in their order, the tetrahedra with their solids, the face pieces' triangles
// tagged with their B-rep face (interfaces once), and for order 2 the curved mid-nodes.
// cancelled (optional) is asked every 4096 elements; true stops with Cancelled.
TetMesh assemble_brep_mesh(const BrepGrids& g, const tet::TetComplex& cx, const std::vector<Vec3>& X, const BrepInput& in, int order,
                           std::int64_t* straightened, const std::function<bool()>& cancelled = {});

// Throws MeshingError naming the solid and the place when a tetrahedron of `m` (its corners) is
// inside out, or flat to round-off: six times its volume, in floating point as a solver computes
// its Jacobian, under 1e-10 times its longest edge cubed (a regular tetrahedron: 0.71; a 0.1
// degree sliver: about 1e-3; corpus/Cone_1.brep's first proxy once left one of 1e-15 at the
// apex, smallest dihedral angle 1e-13 degrees, which the order-2 check refused while the 4-node
// mesh kept it). And when a face is shared by three tetrahedra or more (two overlap there:
// corpus/Kurbelwelle.brep at 2*10^4, order 2, once its walls were measured between the true
// surfaces, came out so on its first proxy, which the validator refuses).
void refuse_degenerate_tets(const BrepInput& in, const TetMesh& m);

}  // namespace bisect::pipeline
