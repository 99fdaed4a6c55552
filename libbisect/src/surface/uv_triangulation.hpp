// A constrained triangulation of points in a surface's parameter plane, the working structure of
// the region mesher (region_mesher.hpp). Triangles are counter-clockwise in (u, v) with their
// neighbours across each edge (nb[k] lies across the edge opposite corner k, -1 on the hull);
// constrained edges (a region's boundary) carry a bit per triangle edge and are never crossed by
// a cavity nor flipped.
//
// Insertion is Bowyer-Watson with the Delaunay test taken in a metric: the points are mapped by a
// linear map T (the square root of the surface's first fundamental form at the new point, so that
// |T du| is the 3D length of du), which makes the triangulation Delaunay as the surface sees it
// near the point rather than as the parameters do. Orientation decisions use the exact orient2d
// on the parameters (T keeps orientation); the cavity is shrunk until the new point sees all of
// its boundary.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "bisect/types.hpp"

namespace bisect::surface {

struct UvTri {
  std::array<Index, 3> v;
  std::array<Index, 3> nb;
  unsigned char held = 0;  // bit k: the edge opposite corner k is constrained
  bool alive = true;
  bool inside = true;      // in the region (false: outside its loops, dropped at the end)
};

class UvTriangulation {
 public:
  std::vector<Vec2> uv;
  std::vector<UvTri> tris;

  // A triangle large enough to hold every point of the box [lo, hi]; its three corners are the
  // first three points.
  void start(const Vec2& lo, const Vec2& hi);
  // The live triangle holding p (on its closure), by a visibility walk from `start`; -1 when p is
  // outside the hull.
  Index locate(const Vec2& p, Index start) const;
  // Inserts point v (its uv already in `uv`) with the Delaunay test in the metric T (row-major
  // 2 by 2, det > 0). Returns a new triangle at v, or -1 when v falls on an existing point or on
  // a constrained edge (not inserted).
  Index insert(Index v, Index start, const Eigen::Matrix2d& T);
  // Makes the segment (a, b) an edge of the triangulation and marks it constrained. Throws
  // MeshingError when a point lies on the open segment (loops that touch) or the segment cannot
  // be recovered.
  void constrain(Index a, Index b);
  // Marks the triangles inside the region: those reached from the outside across an odd number
  // of constrained edges (nested loops: holes are outside again).
  void mark_inside();
  // Flips the edge opposite corner k of triangle t (the two triangles must form a convex
  // quadrilateral; the caller checks). Keeps adjacency and constraint bits.
  void flip(Index t, int k);
  // The corner of t opposite its neighbour n, or -1.
  int side_towards(Index t, Index n) const;
  // The live triangles round point v (its fan), from the hint at_[v].
  std::vector<Index> fan(Index v) const;
  Index live_tri_at(Index v) const { return at_[v]; }
  void set_tri_at(Index v, Index t) { at_[v] = t; }
  void grow(std::size_t nodes) {
    if (at_.size() < nodes) at_.resize(nodes, -1);
  }

 private:
  std::vector<Index> at_;  // per point: a live triangle using it (a hint)
  std::vector<unsigned> mark_;
  unsigned stamp_ = 0;
  unsigned new_stamp();
  void link(Index t, int k, Index n, int j);
  Index add_tri(Index a, Index b, Index c);
};

}  // namespace bisect::surface
