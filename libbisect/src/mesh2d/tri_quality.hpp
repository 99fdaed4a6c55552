// Angles of planar triangles and quadrilaterals, in degrees.
#pragma once
#include <array>

#include "mesh2d/tri_mesh2.hpp"

namespace bisect::mesh2d {

double min_angle_deg(const Vec2& a, const Vec2& b, const Vec2& c);  // of one triangle
double min_angle_deg(const TriMesh2& m);                            // over triangles and quads
double max_angle_deg(const TriMesh2& m);
double total_area(const TriMesh2& m);

}  // namespace bisect::mesh2d
