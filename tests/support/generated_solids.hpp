// Polyhedral test inputs built in code: the families of thesis 6.10 and random CSG solids.
#pragma once
#include <cstdint>
#include <string>

#include "bisect/poly_input.hpp"

namespace bisect::testing {

// A closed triangulated sphere (thesis 6.10.1) of about `facets` triangles (latitude bands split
// into triangles, fans at the poles), every node on the sphere of the given radius.
PolyInput sphere_polyhedron(int facets, double radius = 1.0);

// Two intersecting spheres of different radii with a cylindrical hole through both (thesis
// 6.10.2), as a body of revolution about z: the sphere of radius 1 about the origin, the sphere
// of radius 0.7 about (0, 0, 1.2), the hole of radius 0.3 along z. The profile is revolved in
// `segments` steps, so every face is a planar trapezoid; about `facets` faces.
PolyInput double_sphere_with_hole(int facets);
// The volume of the smooth solid that double_sphere_with_hole approximates.
double double_sphere_with_hole_volume();

// A union of 2 to 5 random boxes and rotated prisms, built with OpenCASCADE's booleans; about
// one seed in four also gets a cavity (a box cut from inside, which leaves an inner shell in the
// one region, as STL gives it). Planar faces become polygons, inner wires their holes.
// Deterministic per seed. `description` says what was built; `volume` is OpenCASCADE's.
PolyInput random_csg_polyhedron(std::uint64_t seed, std::string* description = nullptr, bool* has_cavity = nullptr,
                                double* volume = nullptr);

}  // namespace bisect::testing
