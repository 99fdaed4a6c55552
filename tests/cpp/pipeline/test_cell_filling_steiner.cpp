// A cell job filled by boundary recovery with its second phase (pipeline/cell_filling.hpp): the
// Steiner points it adds join the mesh's nodes, the tetrahedra name them, and the stats count
// them; without the phase the same job is refused.
#include <gtest/gtest.h>

#include <vector>

#include "schoenhardt.hpp"
#include "bisect/errors.hpp"
#include "geom/predicates.hpp"
#include "pipeline/cell_filling.hpp"

namespace bisect::pipeline {
namespace {

TEST(CellFillingSteiner, ASteinerPointJoinsTheNodesAndTheTetrahedraUseIt) {
  const test::TwistedPrism prism = test::schoenhardt_prism();
  std::vector<Vec3> X = prism.X;
  X.push_back(Vec3(5, 5, 5));  // a node of the mesh that is not the cell's: the added ones follow it
  CellJob job;
  job.boundary = prism.boundary;
  job.recover = true;
  job.name = "the twisted prism";
  {
    std::vector<Vec3> Y = X;
    EXPECT_THROW(fill_cell_jobs(Y, {job}, false, 1, {}), MeshingError) << "no fill without a Steiner point";
  }
  job.steiner = true;
  const FilledCells f = fill_cell_jobs(X, {job}, false, 1, {});
  ASSERT_GE(f.steiner_nodes, 1);
  EXPECT_EQ(X.size(), 7u + static_cast<std::size_t>(f.steiner_nodes));
  bool uses_added = false;
  for (const tet::Tet& t : f.tets) {
    EXPECT_GT(geom::orient3d(X[t[0]], X[t[1]], X[t[2]], X[t[3]]), 0);
    for (Index v : t) {
      EXPECT_NE(v, 6) << "the node that is not the cell's";
      uses_added |= v >= 7;
    }
  }
  EXPECT_TRUE(uses_added);
  for (std::size_t v = 7; v < X.size(); ++v) EXPECT_TRUE(X[v].z() > 0 && X[v].z() < 1) << "an added node outside the prism";
}

}  // namespace
}  // namespace bisect::pipeline
