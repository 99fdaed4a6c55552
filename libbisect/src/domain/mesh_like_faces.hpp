// The triangles of a mesh made into a shape (FreeCAD's Part "Create shape from mesh" of an STL
// import, then "Convert to solid"): planar B-rep faces of three edges whose neighbour across an
// edge is another such face in the same plane, facing the same way. The B-rep route meshes every
// face on its own, so each of those triangles' edges is an edge the grids follow, and each acute
// corner of a triangle is a corner the elements must take: through mesh_shape, cantilever.stl so
// made (12 faces) gave a smallest dihedral of 7.7 degrees and a mean alpha of 0.168 at R = 300,
// plate-hole.stl 0.7 degrees; after Part's refine (Shape.removeSplitter(), which merges the
// coplanar triangles into the faces they came from) 29.7 degrees and 0.248, and 15.9 degrees.
// The mesher cannot merge them itself without losing the faces FreeCAD's constraints name, so
// it says so (GenerateStats::coplanar_triangles and coplanar_hint).
#pragma once
#include <cstdint>
#include <string>

#include "bisect/brep_input.hpp"

namespace bisect::domain {

struct MeshLikeFaces {
  std::int64_t triangles = 0;  // triangle faces with a coplanar triangle neighbour
  Index a = -1, b = -1;        // the first such pair (0-based faces), for the message
};

// Fewer than this many such triangles is no mesh made into a shape (a face split on purpose,
// for a load on part of it, is rarely a pair of triangles), and is not reported.
inline constexpr std::int64_t kMeshLikeTriangles = 4;

MeshLikeFaces mesh_like_faces(const BrepInput& in);

// The words for the user, empty below kMeshLikeTriangles: "Face1 and Face2 (and 10 more
// triangles) lie in one plane: ...".
std::string mesh_like_hint(const MeshLikeFaces& found);

}  // namespace bisect::domain
