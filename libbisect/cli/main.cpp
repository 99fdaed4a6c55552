// bisect-mesh: the command-line face of the library. Exit codes (ARCHITECTURE.md §3): 0 done;
// 2 bad input or options, with one line on stderr naming what and where; 3 the mesher could not
// finish. No exception escapes: every failure becomes such a line.
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "bisect/errors.hpp"
#include "commands.hpp"
#include "option_values.hpp"

namespace {

using bisect::cli::parse_real;
using bisect::cli::parse_whole;

// The most elements a mesh can number (32-bit indices).
constexpr std::int64_t kMaxElements = 2147483647;

// --grading: 0 (off) or this range. The graded candidates around each fine boundary node grow
// as 1/G^3 (graded_nodes.cpp: a shell every 0.85 h out to (Np - h)/G, each of 4 pi r^2 / (0.8 h)^2
// points: 24,000 per node at G = 0.2 where Np is 10^4 times the node's size, 1.8e5 at 0.1,
// unbounded as G -> 0, so that --grading 1e-300 never ended), and each candidate's size is
// taken over every fine node within that reach.
constexpr double kMinGrading = 0.2;
constexpr double kMaxGrading = 10;
const std::string kGradingRange = "0 (off) or a number from 0.2 to 10";
// --size-grading: how fast the B-rep size field may grow per unit of distance. Below 0.05 the
// sizes hardly grow away from the finest feature, so the count explodes; above 10 the field no
// longer grades at all (a jump from the finest to the coarsest size within one element).
constexpr double kMinSizeGrading = 0.05;
constexpr double kMaxSizeGrading = 10;

const char* kUsage =
    "usage: bisect-mesh INPUT -o OUTPUT [OPTIONS]\n"
    "       bisect-mesh COMMAND [OPTIONS] FILE\n"
    "\n"
    "main job:\n"
    "  INPUT           .poly (thesis 6.13), .stl or .off polyhedral input; .brep, .step/.stp or\n"
    "                  .iges/.igs B-rep, meshed on its true surfaces (.inp: per B-rep face\n"
    "                  Face<k>, as FreeCAD numbers them, an NSET Face<k>, an ELSET\n"
    "                  Face<k>_Elements and a SURFACE Face<k>_Surface); or .poly2 (thesis\n"
    "                  4.6.1) 2D input, meshed into triangles (written as .vtu)\n"
    "  -o OUTPUT       where the result goes\n"
    "  -n ELEMENTS     the required number of elements (default: the input's own R)\n"
    "  -s SIZE         the nodal spacing itself (an absolute element size) instead of -n\n"
    "  --order K       1: 4-node tetrahedra (default); 2: 10-node tetrahedra, mid-edge nodes\n"
    "                  at the middle of the straight edges\n"
    "  --optimize N    passes of min-max local transformations over the whole mesh (default 3)\n"
    "  --smooth N      passes of Laplace smoothing of interior nodes (default 3)\n"
    "  --slivers N     rounds of node moves on tetrahedra under 10 degrees (default 8)\n"
    "  --mean-shape N  rounds of transformations and node moves for the mean alpha after\n"
    "                  those, keeping every smallest angle (default 2)\n"
    "  --no-face-moves  in those rounds, keep the nodes inside input faces where the face\n"
    "                  grids put them (by default they may move within their face)\n"
    "  --no-quality-floor  keep the count R asks even when its elements miss the quality bars\n"
    "                  (polyhedral inputs, R up to 5000: by default up to 4 R are used)\n"
    "  --threads N     threads for the face grids, the cells' nodes and fillings and the\n"
    "                  optimisation (default 0: one per core); the mesh is the same for\n"
    "                  every N\n"
    "  --grading G     interior spacing grows from a short boundary edge's by G per unit of\n"
    "                  distance, up to Np (default 0: uniform Np inside; else 0.2 to 10)\n"
    "  --min-size H    B-rep: no element edge shorter than H, even on small features and\n"
    "                  tight curvature (default 0: no bound)\n"
    "  --max-size H    B-rep: no element edge longer than H (default 0: no bound)\n"
    "  --curvature-elements K  B-rep: at least K elements per full turn on curved faces and\n"
    "                  edges (default 12; 0: no bound; else at least 3)\n"
    "  --chord-deviation D  B-rep: element edges on curved faces at most D from the surface\n"
    "                  (default 0: no bound)\n"
    "  --size-grading G  B-rep: element sizes grow by at most G per unit of distance from a\n"
    "                  small one (default 0.3; 0.05 to 10)\n"
    "  --boundary-flips  also re-triangulate the outer boundary within each input face by the\n"
    "                  2-2 transformation (thesis 7.5; off by default)\n"
    "  --insertion M   how each cell's nodes go in: minmax (thesis 7.6: local min-max\n"
    "                  improvement after each node) or delaunay (Delaunay cavities, min-max\n"
    "                  improvement at the end)\n"
    "  --quads         2D: pair triangles into quadrilaterals (no angle under 20 degrees)\n"
    "  --cells-only    stop after the convex decomposition and write the convex cells as a\n"
    "                  .poly file, one region per cell, cells sharing their faces\n"
    "  --max-memory MB refuse, before meshing, a job whose estimated memory exceeds MB\n"
    "                  megabytes (default: half of the physical memory)\n"
    "  --stats FILE    write statistics as JSON: nodes, tets, regions, convex_cells, times\n"
    "                  (init_geom, bisect, gen_nodes, gen_tets, optimize, total), quality;\n"
    "                  --cells-only: convex_cells, bisections by method, rejected_planes by\n"
    "                  reason, deferred_edges, narrow_margin_retry, face_corner_retry,\n"
    "                  times (init_geom, bisect);\n"
    "                  2D: nodes, triangles, quads, convex_pieces, min_angle, max_angle, times\n"
    "\n"
    "commands:\n"
    "  info INPUT      read and check a polyhedral input (.poly, .stl, .off) or a 2D input\n"
    "                  (.poly2); print its regions, faces, nodes, bounding box and volume\n"
    "  quality MESH    read a tetrahedral mesh (.vtu, .msh, .inp), check its validity and print\n"
    "                  its quality summary; exit 2 when the mesh is invalid\n"
    "\n"
    "options:\n"
    "  --json          print machine-readable JSON instead of text\n"
    "  --quiet         print nothing but errors (the exit code tells the result)\n"
    "  -h, --help      print this help\n"
    "  --version       print the version\n"
    "\n"
    "exit codes: 0 done; 2 bad input or options (also: a job over --max-memory, an input or\n"
    "            output path that cannot be used, a file that could not be written whole);\n"
    "            3 the mesher could not finish\n";

// The last value given for FLAG, as typed (for messages that quote two flags).
std::string args_value(const std::vector<std::string>& args, const std::string& flag) {
  std::string v;
  for (std::size_t i = 0; i + 1 < args.size(); ++i)
    if (args[i] == flag) v = args[i + 1];
  return v;
}

int usage_error(const std::string& what) {
  std::cerr << "bisect-mesh: " << what << " (see bisect-mesh --help)\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  bisect::cli::CommonOptions opt;
  bisect::cli::MeshOptions mesh;
  std::vector<std::string> positional;
  std::string bad;  // why a value was refused
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](std::string* dst) {
      if (i + 1 >= args.size()) return false;
      *dst = args[++i];
      return true;
    };
    if (a == "-h" || a == "--help") {
      std::cout << kUsage;
      return 0;
    } else if (a == "--version") {
      std::cout << "bisect-mesh 0.1.0\n";
      return 0;
    } else if (a == "--json") {
      opt.json = true;
    } else if (a == "--quiet" || a == "-q") {
      opt.quiet = mesh.quiet = true;
    } else if (a == "--cells-only") {
      mesh.cells_only = true;
    } else if (a == "-o" || a == "--output") {
      if (!value(&mesh.output)) return usage_error(a + " needs a file name");
    } else if (a == "--stats") {
      if (!value(&mesh.stats)) return usage_error(a + " needs a file name");
    } else if (a == "--quads") {
      mesh.quads = true;
    } else if (a == "-n" || a == "--elements") {
      std::string v;
      if (!value(&v)) return usage_error(a + " needs a number of elements");
      const auto n = parse_whole(a, v, 1, kMaxElements, "a positive whole number", &bad);
      if (!n) return usage_error(bad);
      mesh.elements = *n;
    } else if (a == "-s" || a == "--size") {
      std::string v;
      if (!value(&v)) return usage_error(a + " needs a size");
      const auto x = parse_real(a, v, 0, true, 1e300, false, "a positive size", &bad);
      if (!x) return usage_error(bad);
      mesh.size = *x;
    } else if (a == "--max-memory") {
      std::string v;
      if (!value(&v)) return usage_error(a + " needs a number of megabytes");
      const auto x = parse_real(a, v, 1, false, 1e12, false, "a number of megabytes from 1 to 1e12", &bad);
      if (!x) return usage_error(bad);
      mesh.max_memory_mb = *x;
    } else if (a == "--insertion") {
      std::string v;
      if (!value(&v) || (v != "minmax" && v != "delaunay")) return usage_error(a + " needs minmax or delaunay");
      mesh.delaunay_insertion = v == "delaunay";
    } else if (a == "--optimize" || a == "--smooth" || a == "--slivers" || a == "--mean-shape") {
      std::string v;
      if (!value(&v)) return usage_error(a + " needs a number of passes");
      const auto n = parse_whole(a, v, 0, 100, "a number of passes", &bad);
      if (!n) return usage_error(bad);
      (a == "--optimize"  ? mesh.optimize_passes
       : a == "--smooth"  ? mesh.smooth_passes
       : a == "--slivers" ? mesh.sliver_rounds
                          : mesh.mean_rounds) = static_cast<int>(*n);
    } else if (a == "--grading") {
      std::string v;
      if (!value(&v)) return usage_error(a + " needs a number");
      const auto g = parse_real(a, v, kMinGrading, false, kMaxGrading, true, kGradingRange, &bad);
      if (!g) return usage_error(bad);
      mesh.grading = *g;
    } else if (a == "--min-size" || a == "--max-size" || a == "--chord-deviation") {
      std::string v;
      if (!value(&v)) return usage_error(a + " needs a length");
      const auto x = parse_real(a, v, 0, true, 1e300, true, "0 (no bound) or a positive length", &bad);
      if (!x) return usage_error(bad);
      (a == "--min-size" ? mesh.min_size : a == "--max-size" ? mesh.max_size : mesh.chord_deviation) = *x;
      mesh.brep_sizing.push_back(a);
    } else if (a == "--curvature-elements") {
      std::string v;
      if (!value(&v)) return usage_error(a + " needs a number of elements per turn");
      const auto x = parse_real(a, v, 3, false, 1e4, true, "0 (no bound) or a number of elements per turn from 3 to 10000", &bad);
      if (!x) return usage_error(bad);
      mesh.curvature_elements = *x;
      mesh.brep_sizing.push_back(a);
    } else if (a == "--size-grading") {
      std::string v;
      if (!value(&v)) return usage_error(a + " needs a number");
      const auto g = parse_real(a, v, kMinSizeGrading, false, kMaxSizeGrading, false, "a number from 0.05 to 10", &bad);
      if (!g) return usage_error(bad);
      mesh.size_grading = *g;
      mesh.brep_sizing.push_back(a);
    } else if (a == "--boundary-flips") {
      mesh.boundary_flips = true;
    } else if (a == "--no-face-moves") {
      mesh.face_moves = false;
    } else if (a == "--no-quality-floor") {
      mesh.quality_floor = false;
    } else if (a == "--order") {
      std::string v;
      if (!value(&v) || (v != "1" && v != "2")) return usage_error(a + " needs 1 or 2");
      mesh.order = v == "2" ? 2 : 1;
    } else if (a == "--threads") {
      std::string v;
      if (!value(&v)) return usage_error(a + " needs a number of threads");
      const auto n = parse_whole(a, v, 0, 1024, "a number of threads (0: one per core)", &bad);
      if (!n) return usage_error(bad);
      mesh.threads = static_cast<int>(*n);
    } else if (a.size() > 1 && a[0] == '-') {
      return usage_error("unknown option '" + a + "'");
    } else {
      positional.push_back(a);
    }
  }
  if (positional.empty()) return usage_error("no command or input given");
  if (mesh.max_size > 0 && mesh.min_size > mesh.max_size)
    return usage_error("--min-size " + args_value(args, "--min-size") + " exceeds --max-size " + args_value(args, "--max-size"));
  const std::string& cmd = positional[0];
  const bool command = cmd == "info" || cmd == "quality";
  if (!command) {
    if (positional.size() != 1) return usage_error("one input file at a time ('" + positional[1] + "' is extra)");
  } else if (positional.size() != 2) {
    return usage_error(cmd + " takes exactly one file");
  }
  int code = 0;
  try {
    if (!command) code = bisect::cli::run_mesh(cmd, mesh, std::cout, std::cerr);
    else if (cmd == "info") code = bisect::cli::run_info(positional[1], opt, std::cout, std::cerr);
    else code = bisect::cli::run_quality(positional[1], opt, std::cout, std::cerr);
  } catch (const bisect::InputError& e) {
    std::cerr << "bisect-mesh: " << e.what() << "\n";
    return 2;
  } catch (const bisect::MeshingError& e) {
    std::cerr << "bisect-mesh: " << e.what() << "\n";
    return 3;
  } catch (const std::bad_alloc&) {
    std::cerr << "bisect-mesh: out of memory\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "bisect-mesh: internal error: " << e.what() << "\n";
    return 3;
  }
  // what was printed must have arrived too (`bisect-mesh info x.stl > /dev/full`)
  errno = 0;
  std::cout.flush();
  if (!std::cout) {
    std::cerr << "bisect-mesh: standard output: write failed: " << std::strerror(errno ? errno : EIO) << "\n";
    return 2;
  }
  return code;
}
