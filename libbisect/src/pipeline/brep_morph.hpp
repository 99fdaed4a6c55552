// The morph from the proxy onto the true B-rep (brep_proxy.hpp): the nodes the decomposition and
// the node placement made in the proxy's geometry (cut faces' inner nodes, the nodes where cut
// faces meet, the cells' interior nodes) follow the boundary from its proxy position to its true
// one. Near a convex curved face the true surface lies outside the proxy's chords, near a hole
// inside them; either way the nodes within a few elements of it move with it, and the rest stay.
//
//     D(p) = phi(d / rho) * sum_i w_i D_i / sum_i w_i,   w_i = (1 - (r_i / rho)^2)^3 / (r_i^2 + eps^2)^2
//
// over the boundary samples i within rho of p (their proxy position p_i, r_i = |p - p_i|, and
// displacement D_i = x_i - p_i), d the distance to the nearest, phi(s) = (1 - s^2)^3, rho = 2 h(p)
// and eps = rho / 1000. The inverse fourth power lets the nearest samples decide near the
// surface: a node just off a curved face moves as the grid triangles beside it do, so it stays on
// its side of them (a plain average over rho lags behind the bulge and lets a thin cell fold).
// The proxy's facets span tens of degrees of a surface whose elements span a few (the curvature
// bound), so |D| stays a fraction of h and the gradient of D a fraction of that: the elements
// keep their shape.
#pragma once
#include <vector>

#include "pipeline/brep_boundary.hpp"
#include "size/size_field.hpp"

namespace bisect::pipeline {

class Morph {
 public:
  // Samples: every node of `nodes` that lies on a face, edge or vertex.
  Morph(const BoundaryNodes& nodes, const size::SizeField& h);
  Vec3 displacement(const Vec3& p) const;

 private:
  struct KdNode {
    int first, count, left, right, axis;
    double split;
  };
  std::vector<Vec3> p_, d_;
  std::vector<KdNode> tree_;
  const size::SizeField& h_;
  int build(int first, int count, int depth);
};

}  // namespace bisect::pipeline
