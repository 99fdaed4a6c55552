#include "bisect/cell_halving.hpp"

#include <algorithm>
#include <limits>

#include <Eigen/Eigenvalues>

#include "bisect/plane_cut.hpp"

namespace bisect {

namespace {

// Where a cut is tried along the longest axis, as fractions of the extent from its middle.
constexpr double kOffsets[] = {0, 0.05, -0.05, 0.1, -0.1, 0.15, -0.15};

}  // namespace

int CellExtents::longest() const {
  int k = 0;
  for (int j = 1; j < 3; ++j)
    if (length(j) > length(k)) k = j;
  return k;
}

double CellExtents::shortest() const { return std::min({length(0), length(1), length(2)}); }

CellExtents principal_extents(const PolyhedralModel& m, Index r) {
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
  CellExtents e;
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

double nominal_density(const PolyhedralModel& m, const DecomposeOptions& opt, double* volume) {
  double v = 0;
  for (std::size_t r = 0; r < m.regions.size(); ++r)
    if (m.regions[r].alive) v += m.region_volume(static_cast<Index>(r));
  if (volume) *volume = v;
  if (opt.split_size > 0) return 8 / (opt.split_size * opt.split_size * opt.split_size);
  return opt.split_elements > 0 && v > 0 ? opt.split_elements / v : 0;
}

bool halve_cell(PolyhedralModel& m, Index r, const CellExtents& e, const DecomposeOptions& opt, std::vector<Index>& halves) {
  const int k = e.longest();
  for (double off : kOffsets) {
    const double at = 0.5 * (e.lo[k] + e.hi[k]) + off * e.length(k);
    const CutOutcome c = cut_region(m, r, {e.axis[k], at}, -1, -1, true, opt);
    if (!c.ok) continue;
    halves.insert(halves.end(), c.regions.begin(), c.regions.end());
    return true;
  }
  return false;
}

}  // namespace bisect
