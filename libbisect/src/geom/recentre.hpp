// Parts far from the origin (thesis A5: tolerances relative to the part, not its position).
//
// Areas, volumes and plane offsets computed from coordinates near 1e8 lose the part's own digits
// to the position's (a unit square at 1e8 has a shoelace area of rounding noise), and the
// tolerances scaled by the part's size then judge noise. The entry points therefore mesh a copy
// moved near the origin and move the result back. The shift is a multiple of a power of two no
// smaller than the part's extent, so every input coordinate moves exactly and comes back bit for
// bit; only the nodes the mesher makes are rounded to the far position's precision on the way back.
#pragma once
#include <cmath>
#include <vector>

#include "bisect/types.hpp"

namespace bisect::geom {

// The shift that brings the nodes' bounding box near the origin, per coordinate: zero where the
// box's centre lies within twice a power of two above the box's extent of the origin (near parts
// are meshed as given). Where it is not zero, every node and the shift lie within a factor of two
// of each other, so that the subtraction is exact (Sterbenz's lemma) and so is the way back.
template <class V>
V recentring_shift(const std::vector<V>& nodes) {
  V shift = V::Zero();
  if (nodes.empty()) return shift;
  V lo = nodes[0], hi = nodes[0];
  for (const V& p : nodes) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const V centre = 0.5 * lo + 0.5 * hi;
  const double extent = (hi - lo).template lpNorm<Eigen::Infinity>();
  if (!std::isfinite(extent) || !std::isfinite(centre.squaredNorm())) return shift;  // the readers refuse these
  const double q = std::ldexp(1.0, std::ilogb(std::max(extent, 1e-300)) + 1);  // a power of two above the extent
  for (int i = 0; i < shift.size(); ++i)
    if (std::abs(centre[i]) > 2 * q) shift[i] = std::round(centre[i] / q) * q;
  return shift;
}

}  // namespace bisect::geom
