// The global improvement once the cells are filled (thesis 6.9.2): passes of the local min-max
// transformations of 7.5 (only the constrained faces hold: input faces and interfaces; the cut
// faces are gone) in turn with Laplace smoothing, each opening moves for the other; then the
// repair of the slivers they leave, and passes for the mean shape (mean_shape.hpp). The first
// pass covers the whole mesh, the rest work lists (min_max_passes.hpp); on a large mesh those
// passes run in blocks on several threads (block_pass.hpp).
#pragma once
#include <functional>
#include <cstdint>
#include <vector>

#include "bisect/generate.hpp"
#include "optimize/block_pass.hpp"
#include "optimize/mean_shape.hpp"
#include "tet/tet_complex.hpp"

namespace bisect::optimize {

// Sliver repair works on tetrahedra whose smallest dihedral angle is under this (degrees).
inline constexpr double kSliverBelowDeg = 10;

struct OptimizeCounts {
  std::int64_t flips = 0;         // transformations applied
  std::int64_t sliver_moves = 0;  // node moves and insertions of the sliver repair
  std::int64_t surface_moves = 0;  // node moves for the boundary triangles' angles (surface_angles.hpp)
  std::int64_t mean_changes = 0;  // transformations and node moves of the mean-shape passes
  std::int64_t refilled_folds = 0;  // inverted tetrahedra's neighbourhoods filled again (inverted_refill.hpp)
  std::int64_t blocks = 0;          // blocks of the passes' first grid (block_pass.hpp; 0: the whole mesh on one thread)
  std::int64_t folds_left = 0;      // tetrahedra still inside out after the refill (no sliver repair then): refuse the mesh
  OptimizeTimes times;              // seconds per part (build and blocks: optimize_filled's)
};

// cx (built, its constrained faces marked) works on X; fixed[v]: node v never moves (X may grow:
// the sliver repair inserts nodes). progress(fraction of the optimisation done) is called on this
// thread, at every step and every 50 ms within one; false throws Cancelled. Everything runs on
// this thread.
OptimizeCounts optimize_mesh(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed, const OptimizeOptions& opt,
                             const std::function<bool(double)>& progress = {});

// The cells' tetrahedra as the fill made them, before the complex is built.
struct FilledMesh {
  std::vector<tet::Tet> tets;
  std::vector<Index> tags;  // regions
  FaceSet held;             // input faces and interfaces: no transformation crosses or removes them
  FaceTags surface_tag;     // the outer boundary's faces with their input face (TetComplex::surface_tag)
  // the fixed nodes the mean shape's passes may move within their input faces (mean_shape.hpp)
  FaceSlides slides;
  // the surface angles' pass may trade tetrahedra's angles for triangles under 20 degrees
  // (surface_angles.hpp: the B-rep route)
  bool surface_trades = false;
};

// The same from the fill's output: the transformation and smoothing passes in blocks on `threads`
// threads (0: one per core) when the mesh is large enough to cut (block_pass.hpp), then cx
// (empty, on X) is built from the result, and the rest as above, the mean shape's node moves on
// the same threads (mean_shape.hpp); times.build and times.blocks are filled. The mesh is the
// same for every thread count.
OptimizeCounts optimize_filled(tet::TetComplex& cx, FilledMesh filled, std::vector<Vec3>& X, const std::vector<char>& fixed,
                               const OptimizeOptions& opt, const std::function<bool(double)>& progress = {}, int threads = 1);

}  // namespace bisect::optimize
