// The 3D generator end to end (thesis 6.9.2): the convex decomposition, the nodal spacing from
// the required number of elements (6.11, A2: Np = cbrt(8 V / R)), face grids on every face of
// every cell (5.2, shared across cells and interfaces), interior nodes by 3D convex shrinking
// (7.4), the boundary-constrained local min-max triangulation of each cell (7.6), then the
// local transformations over the whole mesh (7.5), Laplace smoothing that never inverts an
// element nor moves a boundary node, and the repair of the slivers left (smooth3d.hpp).
#pragma once
#include <cstdint>
#include <functional>
#include <string>

#include "bisect/brep_input.hpp"
#include "bisect/poly_input.hpp"
#include "bisect/polyhedral_model.hpp"
#include "bisect/quality.hpp"
#include "bisect/tet_mesh.hpp"

namespace bisect {

// The nodal spacing of thesis 6.11 and A2 for a volume V and R elements: Np = cbrt(8 V / R)
// (real meshes hold more tetrahedra than V / (Np^3 / 8): the count is then calibrated).
double nominal_spacing(double volume, double elements);

// A local size on B-rep entities (FreeCAD's mesh regions): elements no larger than `size` on
// these faces, edges and vertices and inside these solids (0-based, FreeCAD's numbering less 1).
struct SizeRegion {
  double size = 0;
  std::vector<Index> faces, edges, vertices, solids;
};

// How big the elements are.
struct SizeOptions {
  std::int64_t elements = 0;  // the thesis's R; 0: the input's own (its header), else `size`
  double size = 0;            // an absolute spacing Np instead of R, when > 0
  // interior nodes graded from the boundary's fine spacing (graded_nodes.hpp): the size grows by
  // this much per unit of distance from a short boundary edge up to Np; 0 (the default): the
  // shrinking's uniform Np everywhere. Off by default: measured on the ../shared STL models it
  // moved the slivers around rather than removing them (README, Tetrahedral meshes). The B-rep
  // route always grades (size_grading).
  double grading = 0;
  // The B-rep route's size field (size/size_field.hpp): sizes never below min_size nor above
  // max_size (0: no bound); on curved faces and edges at least `curvature_elements` elements per
  // full turn (0: no bound) and chords within `chord_deviation` of the surface (0: no bound);
  // local sizes from regions; and the size growing by at most size_grading per unit of distance.
  double min_size = 0, max_size = 0;
  double curvature_elements = 12;
  double chord_deviation = 0;
  double size_grading = 0.3;
  std::vector<SizeRegion> regions;
};

// The global improvement once the cells are filled (thesis 7.5 and 6.9.2).
struct OptimizeOptions {
  int passes = 3;         // global min-max transformation passes (7.5)
  int smooth_passes = 3;  // Laplace smoothing passes over interior nodes, one after each of those
  int sliver_rounds = 8;  // rounds of node moves on tetrahedra with a dihedral angle under 10 degrees
  // rounds of transformations and node moves for the mean α̂ after the sliver repair, from the
  // tetrahedra under α̂ 0.18, keeping every smallest angle (optimize/mean_shape.hpp)
  int mean_rounds = 2;
  // in those rounds, nodes inside an input face move within it too (in a flat face's plane; on a
  // B-rep's curved face, taken back onto it; never onto or across its edges): at coarse counts
  // most nodes are on the boundary; and after those rounds, moves of the nodes of boundary
  // triangles under 25 degrees within their faces for those triangles' sake, each keeping its
  // star's smallest dihedral angle (optimize/surface_angles.hpp)
  bool face_moves = true;
  // the 2-2 transformation on the outer boundary in the global passes (7.5): off by default, as
  // the face grids are already optimised and on the ../shared models it removed no more
  // slivers than it made
  bool boundary_flips = false;
};

// Every option of the generator, in one place: the CLI parses into it and the Python module
// binds it, with these defaults.
struct GenerateOptions {
  SizeOptions sizing;
  DecomposeOptions decompose;
  OptimizeOptions optimize;
  int order = 1;  // 1: 4-node tetrahedra; 2: 10-node, mid-nodes on the straight edges
  // exactly coplanar neighbouring triangles (STL, OFF) merged into polygon faces first, so
  // that a flat face's thin facets do not make thin elements; input face numbers (tri_tag) then
  // number the merged faces
  bool merge_coplanar = true;
  // polyhedral route: when the mesh made for R (up to 5,000 tetrahedra) misses the mean's quality
  // bar (mean alpha 0.20, 0.24 from 1,000 tetrahedra on), meshes of 1.5, 2.25, 3.375 and 4 times
  // its count are made in turn and the first that meets it, with a smallest dihedral of 10 degrees
  // (or 0.8 times the first mesh's, if less), is kept, its count reported as count_floor with the reason
  // "quality: ..." (pipeline/quality_floor.hpp); when none does, the first mesh stays. Not with a
  // given size.
  bool quality_floor = true;
  bool delaunay_insertion = true;   // Delaunay cavities, else the thesis's min-max (cell_fill.hpp)
  // threads for the face grids and the cell fillings (0: one per core); the mesh is the same
  // for every count, and the progress callback is called on the calling thread only
  int threads = 0;
  std::function<bool(double)> progress;  // fraction done; return false to cancel
  // A job whose nodes, once placed, predict more tetrahedra than this is refused (InputError)
  // before any cell is filled: thin walls and small features keep elements small whatever R
  // asks (a 1000 x 1000 x 1 sheet at R = 10^4 would make some 1.6 * 10^7). 0: no bound. The
  // CLI sets it from its memory limit (--max-memory); `limit_cause` names that setting.
  double max_elements = 0;
  std::string limit_cause;
};

// Seconds of the optimisation's parts: the complex's build with its constraints, the
// transformation passes, the smoothing passes, the refill of folds, the sliver repair, the
// mean-shape passes.
struct OptimizeTimes {
  double build = 0, blocks = 0, flips = 0, smooth = 0, refill = 0, slivers = 0, mean = 0;
};

struct GenerateStats {
  std::int64_t nodes = 0, tets = 0, regions = 0, convex_cells = 0;
  double spacing = 0;                 // the Np used
  std::int64_t helper_nodes = 0;      // cells that needed a centroid helper (7.6)
  std::int64_t helpers_removed = 0;   // of those, helpers removed again
  std::int64_t skipped_nodes = 0;     // interior nodes that fell on a face or node (not inserted)
  std::int64_t flips = 0;             // local transformations applied, all stages
  std::int64_t sliver_moves = 0;      // node moves of the sliver repair
  std::int64_t mean_changes = 0;      // transformations and node moves of the mean-shape passes
  std::int64_t surface_moves = 0;     // node moves within faces for the boundary triangles' angles
  std::int64_t surface_flips = 0;     // B-rep: edge flips within faces for the boundary triangles' angles
  std::int64_t fillings = 0;          // times the cells were filled while the count was sought
  std::int64_t graded_nodes = 0;      // interior nodes placed by the grading from fine boundary spacing
  // when the count misses R by more than 20%: the count predicted at the coarsest spacing, the
  // least the input's own nodes and edges allow (facet-bound inputs such as fine STL files)
  std::int64_t count_floor = 0;
  std::string count_floor_reason;  // what sets the floor: "facets", "curvature", "features", "quality: ...", ...
  // B-rep route: triangle faces lying in one plane with a triangle neighbour (a shape made from a
  // mesh, domain/mesh_like_faces.hpp), and when there are 4 or more, what to do about them (else
  // empty): their edges and corners bound the elements
  std::int64_t coplanar_triangles = 0;
  std::string coplanar_hint;
  // polyhedral route: the count searches past the first for the quality floor, each with its
  // fillings (at most 3) and, unless the facets or walls held its count, its mesh; kept or not
  std::int64_t quality_meshes = 0;
  // the smallest angle of the surface triangles (degrees; of the output, after the face moves of
  // the mean shape's passes and the surface angles' pass), and (B-rep route) order 2 elements
  // whose curved boundary edge had to be made straight to keep the Jacobian positive
  double surface_min_angle = 0;
  std::int64_t straightened_edges = 0;
  // B-rep route: face pieces whose grid is made on the proxy facets' planes and mapped onto the
  // surface, the last resort when no chart of the surface takes the piece's boundary (its nodes
  // still lie on the face; the facets' edges show in the grid). 0 when every piece was meshed on
  // its true surface.
  std::int64_t facet_pieces = 0;
  std::int64_t proxy_cells = 0;  // cells filled in the proxy's geometry (proxy_fill.hpp)
  std::int64_t joined_cells = 0; // cells joined with a neighbour to be seen whole (brep_cells.hpp)
  std::int64_t recovered_cells = 0; // cells filled by Delaunay boundary recovery (tet/recovery_fill.hpp)
  std::int64_t steiner_nodes = 0;   // interior nodes that recovery added where a missing boundary triangle's hole needed one
  // cells whose star fill (smallest dihedral under 5 degrees) was replaced by a better one from
  // Delaunay boundary recovery: thin cells, whose two sides' grids are not in line
  std::int64_t refilled_cells = 0;
  // inverted tetrahedra (a last-resort cell's fold) whose neighbourhood the optimiser cut out and
  // filled again (optimize/inverted_refill.hpp)
  std::int64_t refilled_folds = 0;
  std::int64_t optimize_blocks = 0;   // blocks the optimisation's passes ran in (0: on one thread; optimize/block_pass.hpp)
  // B-rep route: the proxies tried (1: the first one meshed; each failed one costs a whole
  // decomposition, placement and filling), and when a later one meshed, what ended the first
  // (its message, naming the place): why a run took two or three times its usual time
  std::int64_t proxy_attempts = 0;
  std::string proxy_retry_reason;
  // The node placements the count search ran. B-rep route: over every proxy tried (a later
  // proxy's search starts at the spacing the one before found), the filling using the search's.
  // Polyhedral route: the search's placements of the nodes alone, and one per filling.
  std::int64_t placements = 0;
  // B-rep route: the decomposition that meshed was made again without its face corner limit (no
  // cut leaving a corner under 25 degrees in a flat face), whose cuts had ended in a region no
  // plane resolved (DecomposeOptions::min_face_corner_deg)
  bool face_corner_retry = false;
  // seconds: preparation, decomposition, node placement with face grids, cell filling,
  // optimisation with smoothing, all
  double init_geom = 0, bisect = 0, gen_nodes = 0, gen_tets = 0, optimize = 0, total = 0;
  OptimizeTimes optimize_parts;  // where the optimisation's time went
};

// Throws InputError (bad input, no element count), MeshingError (a stage could not finish,
// naming where) or Cancelled.
TetMesh generate_mesh(const PolyInput& in, const GenerateOptions& opt, GenerateStats* stats = nullptr);

// The B-rep route (ARCHITECTURE.md §1): the size field, every B-rep edge discretised once, the
// faces meshed on their true surfaces (thesis ch. 5) with the decomposition's cut lines in them,
// then the 3D pipeline on that boundary, and for order 2 mid-nodes on the true surfaces with
// every element's Jacobian positive. Triangles are tagged with their B-rep face, tetrahedra with
// their solid. Throws InputError (bad input or options, naming FreeCAD's Face<k>, Edge<k>,
// Solid<k>), MeshingError (a stage could not finish, naming where) or Cancelled.
TetMesh generate_brep_mesh(const BrepInput& in, const GenerateOptions& opt, GenerateStats* stats = nullptr);

// The --stats JSON of ARCHITECTURE.md §3: counts, times and the quality summary.
std::string generate_stats_json(const GenerateStats& s, const QualitySummary& q);

}  // namespace bisect
