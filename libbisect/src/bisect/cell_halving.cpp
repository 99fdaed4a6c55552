#include "bisect/cell_halving.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
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

void halve_cells_while(PolyhedralModel& m, const DecomposeOptions& opt, DecomposeStats& st, const char* key,
                       double min_elements, double min_thickness, const std::function<bool(const CellExtents&)>& also) {
  const double density = nominal_density(m, opt);
  if (!(density > 0)) return;
  const double spacing = std::cbrt(8 / density);  // the nominal spacing: 8 V / s^3 elements
  std::deque<Index> work;
  for (std::size_t r = 0; r < m.regions.size(); ++r)
    if (m.regions[r].alive) work.push_back(static_cast<Index>(r));
  std::vector<Index> halves;
  while (!work.empty()) {
    const Index r = work.front();
    work.pop_front();
    if (!m.regions[r].alive || !(m.region_volume(r) * density >= min_elements)) continue;
    const CellExtents e = principal_extents(m, r);
    if (e.shortest() < min_thickness * spacing || !also(e)) continue;
    halves.clear();
    if (!halve_cell(m, r, e, opt, halves)) continue;
    ++st.bisections[key];
    work.insert(work.end(), halves.begin(), halves.end());
  }
}

}  // namespace bisect
