// A mesh for the optimiser's tests: the unit cube (its corners fixed) around a jittered
// n x n x n grid of free nodes, Delaunay filled. Little jitter leaves nearly co-spherical node
// sets (slivers); more leaves tetrahedra of every shape.
#pragma once
#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include "tet/cell_fill.hpp"
#include "tet/tet_complex.hpp"

namespace bisect::optimize {

struct GridCube {
  std::vector<Vec3> X;
  std::vector<char> fixed;
  std::vector<tet::Tet> tets;
  explicit GridCube(int n = 6, double jitter = 1e-3, unsigned seed = 7) {
    for (int i = 0; i < 8; ++i) X.push_back(Vec3(i & 1, i >> 1 & 1, i >> 2 & 1));
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> shift(-jitter, jitter);
    const double step = 1.0 / (n + 1);
    for (int i = 1; i <= n; ++i)
      for (int j = 1; j <= n; ++j)
        for (int k = 1; k <= n; ++k) X.push_back(Vec3(i * step + shift(rng), j * step + shift(rng), k * step + shift(rng)));
    fixed.assign(X.size(), 0);
    std::fill(fixed.begin(), fixed.begin() + 8, 1);
    tets = fill();
  }
  // The cube Delaunay filled around every node past its 8 corners (a test may add nodes first;
  // the fill may add a helper node to X).
  std::vector<tet::Tet> fill() {
    std::vector<Index> inside;
    for (std::size_t v = 8; v < X.size(); ++v) inside.push_back(static_cast<Index>(v));
    const std::vector<std::array<Index, 3>> boundary{{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                                     {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    return tet::fill_convex_cell(X, boundary, inside, Vec3(0.5, 0.5, 0.5), true);
  }
};

}  // namespace bisect::optimize
