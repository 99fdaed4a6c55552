// Triangle soups (STL, OFF) describe a flat face of the part as many facets, often long and
// thin. Meshed as they are, every facet is an input face whose grid keeps its thin triangles, and
// the tetrahedra along it are as thin. The thesis's inputs are polygon faces (6.13); this pass
// gives a triangle soup the same shape: adjacent triangles that lie exactly in one plane (exact
// orient3d), face the same way and belong to the same regions become one polygon face, with
// holes where the merged patch has inner loops. Edges shared by more than two faces, and patches
// whose boundary touches itself at a node, are left alone.
#pragma once
#include <cstddef>

#include "bisect/poly_input.hpp"

namespace bisect {

// The input with its exactly coplanar triangle patches merged; other faces as they were. Each
// merged face (and its holes) follows the faces it replaces in the regions' lists.
PolyInput merge_coplanar_triangles(const PolyInput& in, std::size_t* merged_faces = nullptr);

}  // namespace bisect
