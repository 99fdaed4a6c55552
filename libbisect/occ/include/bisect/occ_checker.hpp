// Exact answers about a shape read by load_brep_file / load_brep_string, from OpenCASCADE's own
// geometry (projections, BRepExtrema, the solid classifier, BRepGProp) and never from the
// BrepInput's data: what tests and reports compare a mesh against.
#pragma once
#include <memory>

#include "bisect/brep_input.hpp"

namespace bisect {

enum class PointState { inside, on, outside };

class BrepChecker {
 public:
  // Throws InputError when `in` did not come from this adapter (it has no OpenCASCADE shape).
  explicit BrepChecker(const BrepInput& in);
  ~BrepChecker();
  BrepChecker(const BrepChecker&) = delete;
  BrepChecker& operator=(const BrepChecker&) = delete;

  // The distance from p to the nearest point of face / edge / vertex k (FreeCAD's Face<k+1>,
  // ...), the trimmed face or edge and not its surface or curve. Throws InputError on a bad index.
  double distance_to_face(Index face, const Vec3& p) const;
  double distance_to_edge(Index edge, const Vec3& p) const;
  double distance_to_vertex(Index vertex, const Vec3& p) const;
  // Where p lies with respect to solid k (the solids of BrepInput::solids, in their order);
  // within `tolerance` of its boundary is `on`.
  PointState classify(Index solid, const Vec3& p, double tolerance) const;
  double solid_volume(Index solid) const;
  double volume() const;  // of all solids together: the sum of theirs (solids do not overlap)
  double face_area(Index face) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bisect
