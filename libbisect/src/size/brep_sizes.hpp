// The size field of a B-rep (size_field.hpp) from the options: the base spacing, the curvature
// bound on every curved face and edge (elements per full turn, chord deviation), B-rep edges
// shorter than the base (the smallest features), and the mesh regions' local sizes. Sampled on
// the true geometry at the points of a tessellation, whose triangles are subdivided so that the
// samples lie a fraction of a size apart. And the walls: no element larger than the solid is thick
// where it stands (wall_thickness.hpp), so that a thin wall gets elements across it, not flat
// tetrahedra between the grids of its two sides.
#pragma once
#include <functional>
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

// What brep_size_field evaluates on the true geometry, kept between the count search's rounds
// over one tessellation: a triangle's or an edge's samples lie at the same parameters for every
// base spacing coarser than its curvature asks for, and evaluating B-spline surfaces there was
// most of the search's time (x_as1_tu_203: B-spline derivatives 45% of 49 s, every round again).
struct SizeSamplingCache {
  struct Samples {
    int k = -1;                // the subdivision (triangle) or the segment count (edge) they are for
    std::vector<Vec3> x;       // the points
    std::vector<double> kappa;  // the curvature there (empty where none is asked)
  };
  struct Triangle {
    bool probed = false;
    double kappa[4] = {0, 0, 0, 0};  // at the corners and the centre
    double longest = 0;              // its longest side in 3D
    Samples samples;
  };
  struct Edge {
    bool probed = false;
    double length = 0;
    std::vector<double> probe_kappa;  // at 33 equal parameter steps
    Samples samples;
  };
  std::vector<std::vector<Triangle>> triangles;  // per face, per tessellation triangle
  std::vector<Edge> edges;
};

// The sources come from the faces of in.solids and their edges alone (a compound's separate body,
// meshed on its own, keeps every face of the shape in its input, brep_bodies.cpp).
// base: the spacing from R or the size (already clamped by max_size). walls: the thickness
// samples (wall_thickness.hpp), null for none. cache: the samples of earlier calls on the same
// input and tessellation (null: none kept). cancelled (optional): asked once per tessellation
// triangle and edge and inside the tree's build; a true answer throws Cancelled (a chord
// deviation of 3e-4 on a 5 mm cylinder: 2.7 s under a sanitizer without a poll). Checks the
// options (InputError naming the option).
SizeField brep_size_field(const BrepInput& in, const BrepTessellation& tess, double base, const SizeOptions& o,
                          BrepSizeReport* report = nullptr, const std::vector<WallSample>* walls = nullptr,
                          SizeSamplingCache* cache = nullptr, const std::function<bool()>& cancelled = {});

}  // namespace bisect::size
