// Table 5.3.1 of the thesis, remade: parametric Delaunay against surface Delaunay (method 2 of
// 5.3) on a bicubic patch for 8 to 1,682 triangles (2 n^2 on an (n+1)^2 parameter grid), with
// the thesis's published figures beside ours (its patch is not given in the text, so the
// figures compare in shape, not in value), then the same meshes after surface Laplace smoothing
// (5.4) and angle-first swapping (5.5), and the time of each.
#include <chrono>
#include <cstdio>

#include "surface/analytic_surfaces.hpp"
#include "surface/surface_mesh.hpp"

using namespace bisect::surface;
using Clock = std::chrono::steady_clock;

int main() {
  // Thesis Table 5.3.1: triangles, parametric (max, min angle, error), surface (max, min, error)
  const double thesis[][7] = {
      {8, 1.5708, 0.67474, 0.19267, 1.5708, 0.67474, 0.19267},     {32, 2.49978, 0.25173, 0.04913, 1.8677, 0.54352, 0.04849},
      {50, 2.62658, 0.21078, 0.03085, 1.89385, 0.47648, 0.03066},  {98, 2.64741, 0.20684, 0.01597, 1.93021, 0.41602, 0.01586},
      {162, 2.65236, 0.20632, 0.00972, 1.95157, 0.36733, 0.00964}, {200, 2.64807, 0.20453, 0.00793, 1.96856, 0.35228, 0.00786},
      {242, 2.65338, 0.20661, 0.00653, 1.96375, 0.34101, 0.00647}, {288, 2.6543, 0.20399, 0.00551, 1.96527, 0.33231, 0.00547},
      {392, 2.65678, 0.20413, 0.00405, 1.96439, 0.31984, 0.00402}, {450, 2.6543, 0.20761, 0.00352, 1.97563, 0.31524, 0.00349},
      {512, 2.65762, 0.20452, 0.0031, 1.9799, 0.31139, 0.00308},   {578, 2.65608, 0.2074, 0.00274, 1.99139, 0.30812, 0.00272},
      {648, 2.65774, 0.20499, 0.00245, 1.99912, 0.30533, 0.00243}, {722, 2.65673, 0.20654, 0.0022, 2.00387, 0.3029, 0.00218},
      {800, 2.65947, 0.20547, 0.00199, 2.00775, 0.30078, 0.00197}, {882, 2.6568, 0.20612, 0.0018, 2.01541, 0.29892, 0.00178},
      {1058, 2.65656, 0.20596, 0.0015, 2.02436, 0.29578, 0.00149}, {1250, 2.65739, 0.20596, 0.00127, 2.03116, 0.29326, 0.00126},
      {1458, 2.65842, 0.20604, 0.00109, 2.03802, 0.29118, 0.00108}, {1682, 2.659, 0.20619, 0.00094, 2.0423, 0.28944, 0.00094}};
  const BicubicPatch patch = BicubicPatch::table_531_patch();
  std::printf("angles in radians; error = mean distance of edge midpoints from the surface\n\n");
  std::printf("| tri | param max | param min | param err | surf max | surf min | surf err | thesis param min | thesis surf min | "
              "smoothed+swapped min | smoothed+swapped err | surf ms |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& row : thesis) {
    const int n = static_cast<int>(std::lround(std::sqrt(row[0] / 2)));
    SurfaceMesh m = grid_nodes(patch, n);
    const auto t0 = Clock::now();
    delaunay_in_parameters(m);
    double ms = 1e3 * std::chrono::duration<double>(Clock::now() - t0).count();
    const SurfaceMeshQuality p = surface_quality(m, patch);
    const auto t1 = Clock::now();
    surface_delaunay_swaps(m);
    ms += 1e3 * std::chrono::duration<double>(Clock::now() - t1).count();  // method 2: both steps
    const SurfaceMeshQuality s = surface_quality(m, patch);
    surface_laplace_smooth(m, patch, 5);
    surface_angle_swaps(m, patch);
    const SurfaceMeshQuality o = surface_quality(m, patch);
    std::printf("| %zu | %.5f | %.5f | %.5f | %.5f | %.5f | %.5f | %.5f | %.5f | %.5f | %.5f | %.2f |\n", m.tris.size(), p.max_angle,
                p.min_angle, p.mean_edge_error, s.max_angle, s.min_angle, s.mean_edge_error, row[2], row[5], o.min_angle,
                o.mean_edge_error, ms);
  }
  return 0;
}
