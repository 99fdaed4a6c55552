// The angles of a region at its edges (thesis 7.2.2 stores one per edge; 6.7 orders reflex edges
// by it). Around an edge, the region's faces are sorted by angle; between consecutive faces lies
// a wedge that is either inside the region or outside it. Non-manifold edges (7.2.5) and
// double-occurring faces (both sides in the region) give several wedges.
#pragma once
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "bisect/polyhedral_model.hpp"
#include "util/edge_key.hpp"

namespace bisect {

struct FaceUse {
  Index face;
  int dir;  // +1 when the face's loop runs from the lower node id to the higher one
};
using RegionEdges = std::unordered_map<std::uint64_t, std::vector<FaceUse>>;

// Every edge of region r's live faces, with the faces that use it.
RegionEdges region_edges(const PolyhedralModel& m, Index r);

struct Wedge {
  Index face0, face1;  // the wedge turns from face0 to face1 about the edge (lower -> higher id)
  int side0, side1;    // the sides of those faces facing into the wedge (0: +normal, 1: -normal)
  double start;        // angle of face0 about the edge in the edge's frame
  double angle;        // opening, radians
};

// The wedges of edge (a, b) (a < b) that lie inside region r.
std::vector<Wedge> interior_wedges(const PolyhedralModel& m, Index r, Index a, Index b, const std::vector<FaceUse>& uses);

// The frame about edge a -> b used by interior_wedges: angle 0 along e1, increasing towards e2.
struct EdgeFrame {
  Vec3 d, e1, e2;
  EdgeFrame(const Vec3& pa, const Vec3& pb);
  double angle_of(const Vec3& w) const;
  Vec3 direction(double angle) const;
};

}  // namespace bisect
