// A region of a parametric surface meshed in its (u, v) parameters, isotropic in 3D (thesis
// ch. 5): the B-rep route meshes every piece of every face with it, and the planar cut faces.
//
// 1. The boundary nodes are triangulated in (u, v) and the loops' segments recovered
//    (uv_triangulation.hpp); triangles outside the loops are dropped.
// 2. Delaunay refinement in the surface's metric: a triangle larger than the size function asks
//    for (in 3D), or with an angle under 30 degrees while not already small, gets a node at its
//    circumcentre taken in the metric of the first fundamental form (where the surface, not the
//    parametrisation, says the circumcentre is), inserted with the Delaunay test in that metric
//    (5.3's surface Delaunay, with the circle measured on the surface). No boundary node is ever
//    added: a centre that falls outside the region or too near the boundary is not used.
// 3. Surface Laplace smoothing (5.4) and angle-first swapping (5.5) in turn, judged by the 3D
//    angles, never inverting a triangle in (u, v) nor turning it against the surface normal.
//
// A degenerate boundary segment (two consecutive loop nodes at the same 3D point: a pole, a
// cone's apex) is meshed like any other in (u, v); the triangle on it is then dropped and its
// two nodes become one (the first), so triangles fan out from the pole.
#pragma once
#include <array>
#include <functional>
#include <vector>

#include "bisect/parametric_surface.hpp"

namespace bisect::surface {

struct RegionBoundary {
  std::vector<Vec2> uv;                   // boundary nodes' parameters
  std::vector<Vec3> xyz;                  // their points (on the surface; never moved)
  std::vector<std::vector<Index>> loops;  // closed loops of node ids: outer loops counter-clockwise
                                          // in (u, v), holes clockwise
};

struct RegionMeshOptions {
  std::function<double(const Vec3&)> size;  // wanted edge length at a 3D point (> 0)
  bool optimize = true;                     // smoothing and swaps (5.4, 5.5)
  // The boundary nodes triangulated in the surface's metric averaged over them, not in the
  // parameters' own: a second try for a region whose refinement leaves a triangle folded over in
  // 3D (in the parameters' metric the first triangles take the shape of the (u, v) box, and on a
  // face whose parameters are far from proportional to length some span so much of the surface
  // that no node the refinement may place splits them). Only a second try: as the first, it
  // changed most grids of the shared models, some for the worse (Angled.step at 10^5, smallest
  // dihedral 5.8 -> 0.4 degrees).
  bool boundary_in_surface_metric = false;
  std::function<bool()> cancelled;          // polled now and then; true: throws Cancelled
};

struct RegionMesh {
  std::vector<Vec2> uv;
  std::vector<Vec3> xyz;                   // boundary nodes first, in the given order, unchanged;
                                           // then the interior nodes, each exactly point(uv)
  std::vector<std::array<Index, 3>> tris;  // counter-clockwise in (u, v)
};

// Throws MeshingError naming the problem when the loops are not a valid polygon in (u, v).
RegionMesh mesh_region(const ParametricSurface& s, const RegionBoundary& b, const RegionMeshOptions& o);

// The same region meshed in the chart of a plane (projected_chart.hpp): the plane of the
// boundary's mean normal, when the surface's normals over the boundary stay within 75 degrees of
// it. For regions that the surface's own parameters draw badly (at a pole, where (u, v)
// straight segments bend round a point, or where the boundary's (u, v) polygon is not simple).
// The result is as mesh_region's: boundary nodes first and unchanged (their uv as given), inner
// nodes with their surface (u, v), triangles turning like the given loops. Throws MeshingError
// when the surface is not a graph over that plane.
RegionMesh mesh_region_projected(const ParametricSurface& s, const RegionBoundary& b, const RegionMeshOptions& o);

}  // namespace bisect::surface
