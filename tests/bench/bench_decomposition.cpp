// Decomposition speed on the families of thesis 6.10: one bisection and the whole convex
// decomposition against the number of faces, with the fitted growth exponent (the thesis found
// one bisection linear in the number of faces). There is no peer to run beside it: Gmsh and
// TetGen do not decompose into convex cells.
//
//   build/bench/bench_decomposition [OUT_DIR]   writes decomposition.csv (and decomposition.png
//                                               through tests/bench/plot_decomposition.py)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "bisect/plane_cut.hpp"
#include "bisect/polyhedral_model.hpp"
#include "generated_solids.hpp"

using namespace bisect;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Row {
  std::string family;
  std::size_t faces;
  double one_bisection, decomposition;
  std::size_t cells;
};

// Best of a few runs: the machine is shared and noisy.
template <class F>
double best_of(int runs, F f) {
  double best = 1e300;
  for (int i = 0; i < runs; ++i) {
    const auto t = Clock::now();
    f();
    best = std::min(best, seconds_since(t));
  }
  return best;
}

// A horizontal plane in the widest gap between the nodes' heights in the middle third: it passes
// no node closely, so the splitting method accepts it and a real bisection is timed.
CutPlane middle_plane(const PolyhedralModel& prepared) {
  std::vector<double> z;
  for (const Vec3& p : prepared.nodes) z.push_back(p.z());
  std::sort(z.begin(), z.end());
  const double lo = z.front() + (z.back() - z.front()) / 3, hi = z.back() - (z.back() - z.front()) / 3;
  double best = -1, c = 0.5 * (lo + hi);
  for (std::size_t i = 0; i + 1 < z.size(); ++i)
    if (z[i] >= lo && z[i + 1] <= hi && z[i + 1] - z[i] > best) best = z[i + 1] - z[i], c = 0.5 * (z[i] + z[i + 1]);
  return {Vec3::UnitZ(), c};
}

Row measure(const std::string& family, const PolyInput& in) {
  const PolyhedralModel prepared = prepare_model(in);
  const CutPlane plane = middle_plane(prepared);
  const int runs = in.faces.size() > 20000 ? 2 : 4;
  const double one = best_of(runs, [&] {
    PolyhedralModel m = prepared;  // the copy's own time is taken off below
    const CutOutcome c = cut_region(m, 0, plane, -1, -1, true, DecomposeOptions{});
    if (!c.ok) std::fprintf(stderr, "%s: the bisection was rejected (%s)\n", family.c_str(), c.reason.c_str());
  });
  const double copy = best_of(runs, [&] { PolyhedralModel m = prepared; (void)m; });
  std::size_t cells = 0;
  const double whole = best_of(runs > 2 ? 2 : 1, [&] { cells = decompose(in).cells.size(); });
  return {family, in.faces.size(), std::max(one - copy, 1e-9), whole, cells};
}

double fitted_exponent(const std::vector<Row>& rows, const std::string& family, double Row::*field) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (const Row& r : rows) {
    if (r.family != family) continue;
    const double x = std::log(static_cast<double>(r.faces)), y = std::log(r.*field);
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out_dir = argc > 1 ? argv[1] : ".";
  std::vector<Row> rows;
  // one bisection: a plane across the middle (through the hole of the second family)
  for (int f : {100, 300, 1000, 3000, 10000, 30000, 100000})
    rows.push_back(measure("sphere", testing::sphere_polyhedron(f)));
  for (int f : {1000, 2000, 5000, 10000, 20000, 50000})
    rows.push_back(measure("double_sphere_hole", testing::double_sphere_with_hole(f)));

  std::printf("| family | faces | one bisection (ms) | decomposition (ms) | convex cells |\n|---|---|---|---|---|\n");
  for (const Row& r : rows)
    std::printf("| %s | %zu | %.3f | %.1f | %zu |\n", r.family.c_str(), r.faces, 1e3 * r.one_bisection, 1e3 * r.decomposition,
                r.cells);
  for (const char* fam : {"sphere", "double_sphere_hole"})
    std::printf("%s: one bisection grows as faces^%.2f, the decomposition as faces^%.2f\n", fam,
                fitted_exponent(rows, fam, &Row::one_bisection), fitted_exponent(rows, fam, &Row::decomposition));
  const std::string csv = out_dir + "/decomposition.csv";
  std::ofstream out(csv);
  out << "family,faces,one_bisection_s,decomposition_s,cells\n";
  for (const Row& r : rows) out << r.family << ',' << r.faces << ',' << r.one_bisection << ',' << r.decomposition << ',' << r.cells << '\n';
  out.close();
  const std::string plot = std::string(BISECT_BENCH_DIR) + "/plot_decomposition.py";
  const std::string cmd = "/usr/bin/python3 '" + plot + "' '" + csv + "' '" + out_dir + "/decomposition.png'";
  if (std::system(cmd.c_str()) == 0) std::printf("plot: %s/decomposition.png\n", out_dir.c_str());
  return 0;
}
