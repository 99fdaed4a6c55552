// A planar meshing step that cannot go on, with the place: the steps work in whatever frame their
// caller gave (a face's plane frame for the 3D face grids, a copy moved near the origin for the
// planar mesher), so the place travels as numbers and the caller that knows the input's own
// coordinates and polygon numbers words the message.
#pragma once
#include <string>

#include "bisect/errors.hpp"
#include "bisect/types.hpp"

namespace bisect::mesh2d {

struct PlanarFailure : MeshingError {
  PlanarFailure(const std::string& what, const Vec2& at, int loop_index = -1)
      : MeshingError(what), where(at), loop(loop_index) {}
  Vec2 where;     // a point of the piece or hole, in the caller's frame
  int loop = -1;  // the region's loop it concerns (0 outer, then holes), or -1
};

}  // namespace bisect::mesh2d
