// The checks every polyhedral reader applies to its faces (.poly, STL, OFF), written once so that
// the formats agree on what is bad and say it the same way: too few nodes, a node twice, zero
// area, a non-planar polygon, an open surface. Readers check index ranges themselves, because
// only they know how the file numbers its nodes.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "bisect/poly_input.hpp"

namespace bisect::io {

// How a format names its faces and nodes in messages, and from which number it counts.
struct Naming {
  std::string face = "face", faces = "faces";
  std::string node = "node", nodes = "nodes";
  int base = 1;      // the number the file gives its first node and face
  std::string note;  // appended to messages, e.g. " (OFF numbers vertices and faces from 0)"

  std::string face_name(Index f) const { return face + " " + std::to_string(std::int64_t(f) + base); }
  std::string node_name(Index n) const { return node + " " + std::to_string(std::int64_t(n) + base); }
};

// Tolerances, relative to the size of what is measured so that a model in millimetres and the
// same model in metres are judged alike.
constexpr double kPlanarityRelTol = 1e-9;  // of the face diameter
constexpr double kZeroAreaRelTol = 1e-12;  // twice the area, of the diameter squared
constexpr double kRoundoffFloor = 16 * 2.220446049250313e-16;  // of the coordinates' magnitude

struct FaceShape {
  Vec3 newell = Vec3::Zero();    // right-hand normal direction, length twice the area
  Vec3 centroid = Vec3::Zero();  // mean of the nodes
  double diameter = 0;           // largest distance between two nodes
  double scale = 0;              // largest coordinate magnitude (for the round-off floor)
};
FaceShape face_shape(const std::vector<Vec3>& nodes, const std::vector<Index>& face);

// Each throws InputError "WHERE: what" (where = "file:line" or "file").
void check_face_size(const std::vector<Index>& face, Index f, const std::string& where, const Naming& n);
void check_distinct_nodes(const std::vector<Index>& face, Index f, const std::string& where, const Naming& n);
// Zero area always; planarity when asked (a triangle is planar by construction).
void check_face_shape(const std::vector<Vec3>& nodes, const std::vector<Index>& face, Index f,
                      const std::string& where, const Naming& n, bool planarity);

// An edge used by an odd number of faces: the surface is open there.
struct OddEdge {
  Index a = -1, b = -1;        // its nodes, a < b
  std::vector<Index> faces;    // the faces using it, in file order
};
// The first such edge in face order among `subset` (all faces when empty). Edges of faces for
// which `excused` is true are not reported: a face hole's edges also bound its parent face.
std::optional<OddEdge> first_odd_edge(const std::vector<PolyFace>& faces, const std::vector<Index>& subset,
                                      const std::vector<bool>* excused = nullptr);
// "edge between nodes 12 (x, y, z) and 40 (x, y, z) belongs to only one triangle (triangle 17)"
std::string describe(const OddEdge& e, const std::vector<Vec3>& nodes, const Naming& n);

// Where a point lies with respect to a polygon given in the plane: +1 inside, 0 on its boundary
// (within tol), -1 outside. Crossing parity, so either direction and non-convex polygons work.
int locate_in_polygon(const std::vector<Vec2>& polygon, const Vec2& p, double tol);

// Drops the coordinate along the normal's dominant axis: a projection that keeps the polygon's
// shape non-degenerate, for 2D containment tests of coplanar faces.
Vec2 project(const Vec3& p, int drop_axis);
int dominant_axis(const Vec3& normal);

}  // namespace bisect::io
