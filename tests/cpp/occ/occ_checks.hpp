// What the OpenCASCADE adapter's tests check on every shape, built in a test or read from
// ../shared: the BrepInput's geometry against itself and OpenCASCADE, and a tessellation against
// BrepChecker.
#pragma once
#include <TopoDS_Shape.hxx>

#include <string>

#include "bisect/brep_input.hpp"
#include "bisect/occ_checker.hpp"
#include "bisect/tet_mesh.hpp"

namespace bisect::test {

// The adapter's BrepInput of a shape built in a test.
BrepInput input_of(const TopoDS_Shape& shape, const std::string& name = "test shape");
// The same shape as FreeCAD hands it over: written as a BREP string (Part.Shape.exportBrepToString)
// and read back by load_brep_string. Shapes from memory and from a string need not mesh alike
// (test_brep_apex.cpp, test_brep_surface_flips.cpp): BREP text keeps 15 significant digits, so
// reals come back rounded, e.g. a closed edge's range [0, 2 pi] as [0, 6.28318530717959]
// (measured in FreeCAD 0.20 on the fragments of a box and a ball, whose vertices and tolerances
// come back exact), and the grids, which follow the parameters, part ways from there. The tests
// of the meshing take the string's shape, as FreeCAD gives it.
BrepInput input_through_string(const TopoDS_Shape& shape, const std::string& name = "test shape");

// The volume of tetrahedron t of a mesh, from its corners (straight-sided), and of the whole mesh.
double corner_volume(const TetMesh& m, std::size_t t);
double corner_volume(const TetMesh& m);

// A length against which round-off is measured: the bounding box's diagonal.
double size_of(const BrepInput& in);

// Along every edge use: the surface at the pcurve's (u, v) is the edge's point within the
// tolerances; consecutive uses of a wire share their vertex and meet in (u, v). Returns the
// largest gap seen (model units).
double check_wires(const BrepInput& in);

// closest_point / closest_parameter return the point they were given (3D round trip), and a
// point off the surface comes back no farther than it went.
void check_closest_points(const BrepInput& in);

struct TessellationReport {
  size_t nodes = 0, triangles = 0;
  size_t nodes_checked = 0;  // against BrepChecker
  double worst_node_distance = 0;  // from its vertex, edge or face, over the entity's tolerance
  double worst_volume_error = 0;   // relative, over the solids
};

// Closed per solid with consistent orientation (every directed triangle side once each way),
// counter-clockwise in (u, v), each corner's (u, v) on its node, every node (up to max_checked
// of them, evenly spread) on its vertex, edge or face, volumes within `volume_tolerance` of
// BRepGProp's.
TessellationReport check_tessellation(const BrepInput& in, const BrepTessellation& t, const BrepChecker& checker,
                                      double volume_tolerance, size_t max_checked = 2000);

}  // namespace bisect::test
