// How far an edge's pcurve strays from its 3D curve: what the edge's tolerance must cover.
#pragma once
#include "bisect/parametric_surface.hpp"

namespace bisect::occ {

// max over t in [c.t_min(), c.t_max()] of |s(pc(t)) - c(t)|, estimated from 256 equal steps
// and 16 halving steps at each end, the largest local maxima refined by golden-section search.
// A spike narrower than the samples around it is missed: an estimate, from below.
double pcurve_deviation(const ParametricCurve& c, const ParameterCurve& pc, const ParametricSurface& s);

}  // namespace bisect::occ
