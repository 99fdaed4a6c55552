#include "bisect/slender_split.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <vector>

#include <Eigen/Eigenvalues>

#include "bisect/plane_cut.hpp"

namespace bisect {

namespace {

// Where a cut is tried along the longest axis, as fractions of the extent from its middle.
constexpr double kOffsets[] = {0, 0.05, -0.05, 0.1, -0.1, 0.15, -0.15};

struct Extents {
  Vec3 axis[3];      // principal axes of the cell's vertices, shortest spread first
  double lo[3], hi[3];
};

Extents principal_extents(const PolyhedralModel& m, Index r) {
  std::vector<Index> nodes;
  for (Index f : m.live_faces(r))
    for (const auto& loop : m.faces[f].loops) nodes.insert(nodes.end(), loop.begin(), loop.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  Vec3 c = Vec3::Zero();
  for (Index v : nodes) c += m.nodes[v];
  c /= static_cast<double>(std::max<std::size_t>(nodes.size(), 1));
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (Index v : nodes) cov += (m.nodes[v] - c) * (m.nodes[v] - c).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);  // eigenvalues ascending
  Extents e;
  for (int k = 0; k < 3; ++k) {
    e.axis[k] = es.eigenvectors().col(k).normalized();
    e.lo[k] = std::numeric_limits<double>::infinity(), e.hi[k] = -e.lo[k];
    for (Index v : nodes) {
      const double p = e.axis[k].dot(m.nodes[v]);
      e.lo[k] = std::min(e.lo[k], p), e.hi[k] = std::max(e.hi[k], p);
    }
  }
  return e;
}

}  // namespace

void split_slender_cells(PolyhedralModel& m, const DecomposeOptions& opt, DecomposeStats& st) {
  std::deque<Index> work;
  double volume = 0;
  for (std::size_t r = 0; r < m.regions.size(); ++r)
    if (m.regions[r].alive) {
      work.push_back(static_cast<Index>(r));
      volume += m.region_volume(static_cast<Index>(r));
    }
  const double density = opt.split_size > 0 ? 8 / (opt.split_size * opt.split_size * opt.split_size)
                         : opt.split_elements > 0 && volume > 0 ? opt.split_elements / volume
                                                                : 0;
  if (!(density > 0)) return;
  const double spacing = std::cbrt(8 / density);  // the nominal spacing: 8 V / s^3 elements
  while (!work.empty()) {
    const Index r = work.front();
    work.pop_front();
    if (!m.regions[r].alive || m.region_volume(r) * density < kSlenderMinElements) continue;
    const Extents e = principal_extents(m, r);
    double shortest = std::numeric_limits<double>::infinity();
    int longest = 0;
    for (int k = 0; k < 3; ++k) {
      shortest = std::min(shortest, e.hi[k] - e.lo[k]);
      if (e.hi[k] - e.lo[k] > e.hi[longest] - e.lo[longest]) longest = k;
    }
    const double length = e.hi[longest] - e.lo[longest];
    if (!(length > kSlenderAspect * shortest) || shortest < kSlenderMinThickness * spacing) continue;
    const Vec3 n = e.axis[longest];
    for (double off : kOffsets) {
      const double at = 0.5 * (e.lo[longest] + e.hi[longest]) + off * length;
      const CutOutcome c = cut_region(m, r, {n, at}, -1, -1, true, opt);
      if (!c.ok) continue;
      ++st.bisections["slender_split"];
      for (Index nr : c.regions) work.push_back(nr);
      break;
    }
  }
}

}  // namespace bisect
