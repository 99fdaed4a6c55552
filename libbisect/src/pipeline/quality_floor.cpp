#include "pipeline/quality_floor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace bisect::pipeline {

QualityBars quality_bars(std::int64_t n) {
  QualityBars bars;
  if (n >= 1000) bars.alpha_mean = 0.24;
  return bars;
}

bool meets_mean_bar(const QualitySummary& q, const QualityBars& bars) { return q.tets > 0 && q.alpha.mean >= bars.alpha_mean; }

bool floor_keeps(const QualitySummary& more, const QualitySummary& at_asked, const QualityBars& bars) {
  const double first = at_asked.dihedral_min.min;
  return meets_mean_bar(more, bars) && more.dihedral_min.min >= (first >= bars.dihedral_deg ? bars.dihedral_deg : kFloorDihedralSlack * first);
}

std::vector<std::int64_t> quality_floor_counts(std::int64_t made) {
  std::vector<std::int64_t> out;
  if (made <= 0 || made > kQualityFloorMaxTets) return out;
  const double most = kQualityFloorMaxFactor * static_cast<double>(made);
  for (double f = kQualityFloorStep;; f *= kQualityFloorStep) {
    const double count = std::min(f * static_cast<double>(made), most);
    out.push_back(std::llround(count));
    if (count >= most) break;
  }
  return out;
}

std::string quality_floor_reason(std::int64_t asked, const QualitySummary& at_asked, const QualityBars& bars, std::int64_t kept_tets,
                                 const QualitySummary& kept) {
  char text[300];
  std::snprintf(text, sizeof text,
                "quality: the mesh for R = %lld (%zu tetrahedra) had a mean alpha of %.3f (bar %.2f) and a smallest dihedral of %.1f deg; "
                "%lld tetrahedra give %.3f and %.1f deg",
                static_cast<long long>(asked), at_asked.tets, at_asked.alpha.mean, bars.alpha_mean, at_asked.dihedral_min.min,
                static_cast<long long>(kept_tets), kept.alpha.mean, kept.dihedral_min.min);
  return text;
}

}  // namespace bisect::pipeline
