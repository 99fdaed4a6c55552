// The OpenCASCADE side of a BrepInput: the shape as read and FreeCAD's numbering of it, kept
// alive by BrepInput::shape for the tessellation and BrepChecker.
#pragma once
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Solid.hxx>

#include <memory>
#include <string>
#include <vector>

#include "bisect/brep_input.hpp"

namespace bisect::occ {

struct OccShape {
  TopoDS_Shape shape;  // as read
  // FreeCAD's numbering: TopExp::MapShapes over the whole shape, per type (index k + 1 is
  // BrepInput's k)
  TopTools_IndexedMapOfShape vertices, edges, faces;
  // BrepInput::solids, in its order: the shape's solids, then its free closed shells made solids
  std::vector<TopoDS_Solid> solids;
  std::string source;
};

// Topology and geometry of `shape` (topology.cpp); `source` names it in messages. Throws
// InputError when the shape has no solid and no closed shell.
BrepInput brep_input_from_shape(const TopoDS_Shape& shape, const std::string& source);

// BRepMesh's tessellation of the whole shape, welded along edges (tessellate.cpp).
BrepTessellation tessellate_shape(const OccShape& model, double linear, double angular);

// The OccShape of an input made by brep_input_from_shape; InputError when `in` has none.
const OccShape& occ_shape_of(const BrepInput& in);

}  // namespace bisect::occ
