// The planar mesher of thesis chapter 4: regions from the .poly2 input (4.6.1), the spacing from
// the required number of elements (4.6.2), boundaries discretised once for both sides of every
// interface, each region cut into convex pieces (4.6.3, 4.6.4), nodes placed by shrinking the
// pieces (4.6.5), each piece triangulated by recursive bisection (4.3), then vertex swapping and
// Laplace smoothing (4.4) and, if asked, quadrilaterals by the walking method (4.7.2).
//
// Real meshes hold a little more or fewer triangles than the area over the equilateral element
// (THESIS-NOTES: calibrate the spacing): the spacing is corrected from a first count so that the
// count lands near the request.
#pragma once
#include <cstdint>
#include <string>

#include "bisect/errors.hpp"
#include "bisect/poly_input.hpp"
#include "mesh2d/tri_mesh2.hpp"

namespace bisect::mesh2d {

struct PlanarOptions {
  std::int64_t elements = 0;  // required triangles; 0: the file's R
  bool optimize = true;       // swaps and smoothing (4.4)
  bool quads = false;         // quadrilaterals by the walking method (4.7.2)
};

struct PlanarStats {
  std::int64_t nodes = 0, triangles = 0, quads = 0, convex_pieces = 0;
  double min_angle_deg = 0, max_angle_deg = 0;
  double seconds_nodes = 0, seconds_triangulate = 0, seconds_optimize = 0, seconds_total = 0;
};

TriMesh2 mesh_planar(const Poly2Input& in, const PlanarOptions& opt, PlanarStats* stats = nullptr);

struct PlanarFailure;
// A step's failure in region `region` of the input, worded with the file, the input's polygon
// numbers and a point in its own coordinates (the steps ran on a copy moved by -shift): "FILE:
// polygon P[ around polygon Q (a hole)]: WHAT, near (x, y)". What mesh_planar throws.
MeshingError placed_failure(const Poly2Input& in, std::size_t region, const PlanarFailure& e, const Vec2& shift);

// VTK XML unstructured grid (z = 0): triangles and quadrilaterals, the region as cell data.
void write_tri_vtu(const TriMesh2& m, const std::string& path);
std::string planar_stats_json(const PlanarStats& s);

}  // namespace bisect::mesh2d
