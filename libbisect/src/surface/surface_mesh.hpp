// Triangle meshes on a parametric surface (thesis 5.3-5.5): nodes carry both their parameters
// and their point, triangles run counter-clockwise in the parameter plane.
#pragma once
#include <array>
#include <vector>

#include "bisect/parametric_surface.hpp"

namespace bisect::surface {

using bisect::ParametricSurface;

struct SurfaceMesh {
  std::vector<Vec2> uv;
  std::vector<Vec3> xyz;   // xyz[i] == surface.point(uv[i])
  std::vector<char> fixed; // boundary nodes: smoothing leaves them
  std::vector<std::array<Index, 3>> tris;
};

// The nodes of an (n + 1) x (n + 1) grid over the parameter box, boundary nodes fixed; no
// triangles yet. With 2 n^2 triangles it gives the element counts of Table 5.3.1.
SurfaceMesh grid_nodes(const ParametricSurface& s, int n);

// Planar Delaunay triangulation of the nodes in parameter space (method 2 of 5.3, first step):
// Bowyer-Watson insertion with the exact incircle and orient2d predicates.
void delaunay_in_parameters(SurfaceMesh& m);

// Method 2 of 5.3, second step: Lawson swaps until no triangle's minimal circum-sphere (the
// sphere through its corners centred in its plane) holds the far corner of a neighbour.
// Returns the number of swaps.
std::size_t surface_delaunay_swaps(SurfaceMesh& m, int max_passes = 100);

// Surface Laplace smoothing of 5.4: each free node moves in parameter space to the average of
// its neighbours weighted by L / PL (3D length over parameter length); a move that would invert
// a triangle in parameter space, turn its normal against the surface's, or lower the smallest
// angle of the triangles around the node is not made. Returns the moves made.
std::size_t surface_laplace_smooth(SurfaceMesh& m, const ParametricSurface& s, int passes = 5);

// Vertex swapping of 5.5 with the angle-first rule of 5.5.2: swap when the smaller angle of the
// two triangles grows by more than angle_tol radians; when the two ways are within angle_tol,
// swap only if the mid-edge surface error (5.5.1) of the new edge is smaller.
std::size_t surface_angle_swaps(SurfaceMesh& m, const ParametricSurface& s, double angle_tol = 1e-3,
                                int max_passes = 100);

struct SurfaceMeshQuality {
  double min_angle = 0, max_angle = 0;  // radians, over all triangle corners in 3D
  double mean_edge_error = 0, max_edge_error = 0;  // distance of edge midpoints from the surface
};
SurfaceMeshQuality surface_quality(const SurfaceMesh& m, const ParametricSurface& s);

// The distance from the surface of the midpoint of the segment ab (5.5.1).
double mid_edge_error(const SurfaceMesh& m, const ParametricSurface& s, Index a, Index b);

}  // namespace bisect::surface
