// The B-rep route's two levels: generate_brep_mesh (generate.hpp) splits a shape into groups
// of solids that share faces (brep_bodies.cpp) and meshes each group as one conforming mesh
// with the stage sequence below (brep_generate.cpp).
#pragma once
#include "bisect/generate.hpp"

namespace bisect::pipeline {

// One group of solids joined by shared faces (or a single solid), meshed as one conforming mesh:
// the proxy and its decomposition, the size field, the grids on the true surfaces, the fill, the
// optimisation, the assembly and, for order 2, the curved mid-nodes. Throws as
// generate_brep_mesh does; a cell's MeshingError names the cell and its solid, not the input.
TetMesh generate_connected_solids(const BrepInput& in, const GenerateOptions& opt, GenerateStats* stats);

}  // namespace bisect::pipeline
