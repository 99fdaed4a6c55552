#include "pcurve_deviation.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace bisect::occ {

double pcurve_deviation(const ParametricCurve& c, const ParameterCurve& pc, const ParametricSurface& s) {
  constexpr int kSteps = 256, kEndSamples = 16, kRefined = 4;
  const double t0 = c.t_min(), t1 = c.t_max(), h = (t1 - t0) / kSteps;
  auto dev = [&](double t) { return (s.point(pc.uv(t)) - c.point(t)).norm(); };
  // equal steps, and steps halving towards both ends: approximated pcurves stray most in their
  // first and last span, often in a spike narrower than one step
  std::vector<double> ts;
  for (int i = 0; i <= kSteps; ++i) ts.push_back(t0 + i * h);
  for (int k = 1; k <= kEndSamples; ++k) {
    ts.push_back(t0 + std::ldexp(h, -k));
    ts.push_back(t1 - std::ldexp(h, -k));
  }
  std::sort(ts.begin(), ts.end());
  const int n = static_cast<int>(ts.size());
  std::vector<double> d(n);
  for (int i = 0; i < n; ++i) d[i] = dev(ts[i]);
  double worst = *std::max_element(d.begin(), d.end());
  // the samples that stand above both neighbours, highest first, each refined by golden-section
  // search between its neighbours
  std::vector<int> peaks;
  for (int i = 0; i < n; ++i)
    if ((i == 0 || d[i] >= d[i - 1]) && (i == n - 1 || d[i] >= d[i + 1])) peaks.push_back(i);
  std::sort(peaks.begin(), peaks.end(), [&](int a, int b) { return d[a] > d[b]; });
  if (peaks.size() > kRefined) peaks.resize(kRefined);
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  for (int i : peaks) {
    double a = ts[std::max(i - 1, 0)], b = ts[std::min(i + 1, n - 1)];
    double x = b - g * (b - a), y = a + g * (b - a), fx = dev(x), fy = dev(y);
    for (int it = 0; it < 40 && b - a > 1e-12 * (t1 - t0); ++it) {
      if (fx > fy) {
        b = y, y = x, fy = fx, x = b - g * (b - a), fx = dev(x);
      } else {
        a = x, x = y, fx = fy, y = a + g * (b - a), fy = dev(y);
      }
    }
    worst = std::max({worst, fx, fy});
  }
  return worst;
}

}  // namespace bisect::occ
