// The subcommands of bisect-mesh. Each returns the process exit code (ARCHITECTURE.md §3) and
// lets bisect::InputError / MeshingError propagate to main, which prints them as one line.
#pragma once
#include <iosfwd>
#include <cstdint>
#include <string>
#include <vector>

namespace bisect::cli {

struct CommonOptions {
  bool json = false;   // machine-readable output on stdout
  bool quiet = false;  // nothing on stdout but what was asked for
};

// `bisect-mesh info INPUT`: read and check a polyhedral (.poly/.stl/.off) or polygonal (.poly2)
// input; print its regions, faces, nodes, bounding box and volume (area in 2D).
int run_info(const std::string& input, const CommonOptions& opt, std::ostream& out, std::ostream& err);

// `bisect-mesh quality MESH`: read a .vtu/.msh/.inp tetrahedral mesh, print the validity check
// and the quality summary. Exit 0 when the mesh is valid, 2 when it violates an invariant.
int run_quality(const std::string& mesh, const CommonOptions& opt, std::ostream& out, std::ostream& err);

}  // namespace bisect::cli

namespace bisect::cli {

// The main job: `bisect-mesh INPUT -o OUTPUT [options]`.
struct MeshOptions {
  std::string output;      // -o
  std::string stats;       // --stats FILE (JSON)
  bool cells_only = false; // --cells-only: stop after the convex decomposition, write .poly cells
  std::int64_t elements = 0;  // -n (0: the input's R)
  double size = 0;            // -s: the nodal spacing itself, instead of -n
  int optimize_passes = 3;    // --optimize PASSES: global min-max transformation passes
  int smooth_passes = 3;      // --smooth PASSES: Laplace smoothing passes
  int sliver_rounds = 8;      // --slivers ROUNDS: sliver repair rounds
  int mean_rounds = 2;        // --mean-shape ROUNDS: rounds for the mean shape after the repair
  bool delaunay_insertion = true;   // --insertion delaunay|minmax
  int threads = 0;            // --threads N (0: one per core)
  int order = 1;              // --order 1|2
  bool boundary_flips = false;  // --boundary-flips: the 2-2 transformation on the outer boundary
  bool face_moves = true;       // --no-face-moves: false
  bool quality_floor = true;    // --no-quality-floor: false
  double grading = 0;         // --grading G (0: uniform interior spacing)
  // the B-rep size field (SizeOptions): --min-size, --max-size, --curvature-elements,
  // --chord-deviation, --size-grading; brep_sizing lists the flags given, so that a polyhedral
  // input, whose surface is its facets, refuses them by name
  double min_size = 0, max_size = 0, curvature_elements = 12, chord_deviation = 0, size_grading = 0.3;
  std::vector<std::string> brep_sizing;
  bool quads = false;         // --quads: 2D meshes get quadrilaterals (thesis 4.7.2)
  double max_memory_mb = 0;   // --max-memory MB (0: half of the physical memory)
  bool quiet = false;
};
int run_mesh(const std::string& input, const MeshOptions& opt, std::ostream& out, std::ostream& err);

}  // namespace bisect::cli
