// The mesh handed out: the used nodes in their order, the tetrahedra with their regions, and the
// boundary triangles tagged with their input face (interfaces once, from the face grids; the
// outer boundary from the complex, which the 2-2 transformation may have re-triangulated), then
// the mid-nodes of order 2.
#pragma once
#include <vector>

#include "bisect/polyhedral_model.hpp"
#include "bisect/tet_mesh.hpp"
#include "mesh2d/face_grids.hpp"
#include "tet/tet_complex.hpp"

namespace bisect::pipeline {

TetMesh assemble_mesh(const PolyhedralModel& m, const mesh2d::FaceGrids& g, const tet::TetComplex& cx, const std::vector<Vec3>& X, int order);

}  // namespace bisect::pipeline
