// The optimisation's passes on several threads (issue 18). The passes over the whole mesh (the
// min-max transformations, then smoothing: min_max_passes.hpp) are made block by block: a grid
// of cubes cuts the mesh into blocks (a tetrahedron goes where its centroid lies), and each block
// becomes a complex of its own, on any thread, with everything outside it held: its outer faces
// are its complex's boundary, and the nodes it shares with another block do not move.
//
// So the grid's walls stay as they were. A second grid, shifted by a third of a cube along every
// axis, has them inside its blocks; it takes only the band round the nodes the first held, and
// its passes start at those nodes. A third, shifted once more, does the same for the nodes both
// held (where the first two grids' walls cross, along lines). What all three held (where three
// walls meet, at points) is left to the caller, on one thread.
//
// The blocks depend on the mesh alone, never on the thread count, and their results are taken
// up in block order: the output is the same for every thread count.
#pragma once
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "tet/tet_complex.hpp"

namespace bisect::optimize {

// Blocks hold about max(kBlockTets, a sixteenth of the mesh) tetrahedra each; a mesh under twice
// kBlockTets is not cut. Smaller blocks share the work more evenly, but more of it lies at their
// walls and is done again by the later grids (lug at 10^6 on two threads: 16,384 per block cost
// 3.1 s, 65,536 2.6 s).
inline constexpr std::size_t kBlockTets = 16384;
std::size_t block_size(std::size_t tets);

using FaceSet = std::unordered_set<tet::FaceKey, tet::FaceKeyHash>;
using FaceTags = std::unordered_map<tet::FaceKey, Index, tet::FaceKeyHash>;

struct BlockOptions {
  int passes = 3, smooth_passes = 3;  // OptimizeOptions'
  bool boundary_flips = false;        // TetComplex's
  double edge_removal_below = tet::TetComplex::kEdgeRemovalBelow;
  int threads = 1;  // 0: one per core
};

struct BlockPassCounts {
  std::size_t blocks = 0;  // blocks of the first grid (0: the mesh was too small to cut, and is unchanged)
  std::int64_t flips = 0;  // transformations made
  std::int64_t moves = 0;  // node moves made
  // per node: held by every grid (a free node where walls of all three meet); the caller's
  // passes start at the tetrahedra there
  std::vector<char> held_throughout;
};

// The passes in blocks over the tetrahedra `tets` (positively oriented; tags: their regions),
// which are replaced by the result. held: faces no transformation crosses or removes (the outer
// boundary's need not be in it); surface_tag: the outer boundary's faces with their input face,
// kept up to date through the 2-2 transformation (boundary_flips). fixed[v]: node v never moves.
// progress(fraction of the work done) is called on the calling thread, often (the blocks' loops
// poll it; the other threads see a flag its answer sets); false throws Cancelled.
BlockPassCounts block_pass(std::vector<tet::Tet>& tets, std::vector<Index>& tags, std::vector<Vec3>& X, const std::vector<char>& fixed,
                           const FaceSet& held, FaceTags& surface_tag, const BlockOptions& opt,
                           const std::function<bool(double)>& progress = {});

}  // namespace bisect::optimize
