// The size field of a B-rep (size_field.hpp) from the options: the base spacing, the curvature
// bound on every curved face and edge (elements per full turn, chord deviation), B-rep edges
// shorter than the base (the smallest features), and the mesh regions' local sizes. Sampled on
// the true geometry at the points of a tessellation, whose triangles are subdivided so that the
// samples lie a fraction of a size apart. And the walls: no element larger than the solid is thick
// where it stands (wall_thickness.hpp), so that a thin wall gets elements across it, not flat
// tetrahedra between the grids of its two sides.
#pragma once
#include <string>

#include "bisect/brep_input.hpp"
#include "bisect/generate.hpp"
#include "size/size_field.hpp"
#include "size/wall_thickness.hpp"

namespace bisect::size {

struct BrepSizeReport {
  std::size_t curvature_sources = 0, edge_sources = 0, region_sources = 0, wall_sources = 0;
  double smallest_curvature_size = 0, smallest_edge = 0, thinnest_wall = 0;  // 0: none
};

// The curvature bound's size at curvature kappa (1 / radius), or `none` when kappa is 0 or no
// bound is set: an arc of angle 2 pi / elements, or the chord whose sagitta is the deviation.
double curvature_size(double kappa, const SizeOptions& o, double none);

// base: the spacing from R or the size (already clamped by max_size). walls: the thickness
// samples (wall_thickness.hpp), null for none. Checks the options (InputError naming the option).
SizeField brep_size_field(const BrepInput& in, const BrepTessellation& tess, double base, const SizeOptions& o,
                          BrepSizeReport* report = nullptr, const std::vector<WallSample>* walls = nullptr);

}  // namespace bisect::size
