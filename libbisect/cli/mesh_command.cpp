// `bisect-mesh INPUT -o OUTPUT`: a tetrahedral mesh of a polyhedral input (the whole generator,
// thesis 6.9.2) or of a B-rep (.brep, .step, .iges: the true-surface route), the convex cells alone (--cells-only), or a planar mesh of a .poly2 input.
#include <cstdio>
#include <exception>
#include <ostream>

#include "bisect/errors.hpp"
#include "bisect/generate.hpp"
#include "bisect/io.hpp"
#include "bisect/occ.hpp"
#include "bisect/poly_input.hpp"
#include "bisect/polyhedral_model.hpp"
#include "io/file_paths.hpp"
#include "mesh2d/planar_mesher.hpp"
#include "commands.hpp"
#include "work_estimate.hpp"

namespace bisect::cli {
namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string required_count(const std::string& input, std::int64_t r) {
  return input + ": its required element count R = " + std::to_string(r);
}

// The tetrahedral job's memory, checked before meshing (work_estimate.hpp): from -s and the
// volume, else from -n, else from the input's own R.
void check_job(double volume, std::int64_t required, const MeshOptions& opt, const std::string& input = "") {
  const std::int64_t r = opt.elements > 0 ? opt.elements : required;
  if (opt.size <= 0 && r <= 0) return;  // the generator refuses a job with no count
  char size[40];
  std::snprintf(size, sizeof size, "-s %g", opt.size);
  const std::string cause = opt.size > 0 ? std::string(size) : opt.elements > 0 ? "-n " + std::to_string(r) : required_count(input, r);
  check_memory(estimate_tet_mesh(volume, r, opt.size, opt.order, cause), opt.max_memory_mb);
}

// The planar mesher's deeper stages (bisect2d, convex_decompose) say what failed but not in
// which file: every 2D failure the CLI prints starts with the input's name.
template <class F>
auto named_2d_failures(const std::string& input, F&& mesh) {
  const auto named = [&](const std::exception& e) {
    const std::string what = e.what();
    return what.compare(0, input.size(), input) == 0 ? what : input + ": 2D mesh: " + what;
  };
  try {
    return mesh();
  } catch (const InputError& e) {
    throw InputError(named(e));
  } catch (const MeshingError& e) {
    throw MeshingError(named(e));
  }
}

}  // namespace

int run_mesh(const std::string& input, const MeshOptions& opt, std::ostream& out, std::ostream& err) {
  (void)err;
  if (opt.output.empty()) throw InputError("no output file given (-o OUTPUT)");
  // the paths first: a directory or a missing file as input, or an output that cannot be
  // written, is one line now rather than an error after the meshing
  io::check_readable_file(input);
  io::check_output_path(opt.output);
  if (!opt.stats.empty()) io::check_output_path(opt.stats);
  if (!is_brep_path(input) && !opt.brep_sizing.empty())
    throw InputError(opt.brep_sizing.front() + " sets the size field of B-rep inputs (.brep, .step, .iges); " + input +
                     " is meshed on its own facets (use -s or -n)");
  if (ends_with(input, ".poly2")) {  // a planar mesh (thesis ch. 4)
    if (opt.cells_only) throw InputError("--cells-only is for polyhedral inputs; " + input + " is a 2D input");
    if (!ends_with(opt.output, ".vtu")) throw InputError(opt.output + ": 2D meshes are written as .vtu");
    const Poly2Input in = read_poly2(input);
    if (const std::int64_t r = opt.elements > 0 ? opt.elements : in.required_elements; r > 0)
      check_memory(estimate_planar_mesh(r, opt.elements > 0 ? "-n " + std::to_string(r) : required_count(input, r)),
                   opt.max_memory_mb);
    mesh2d::PlanarOptions po;
    po.elements = opt.elements;
    po.quads = opt.quads;
    mesh2d::PlanarStats st;
    const mesh2d::TriMesh2 m = named_2d_failures(input, [&] { return mesh2d::mesh_planar(in, po, &st); });
    mesh2d::write_tri_vtu(m, opt.output);
    if (!opt.stats.empty()) {
      io::write_output_file(opt.stats, [&](std::ostream& s) { s << mesh2d::planar_stats_json(st) << '\n'; });
    }
    if (!opt.quiet)
      out << opt.output << ": " << st.triangles << " triangles, " << st.quads << " quadrilaterals, " << st.nodes
          << " nodes, angles " << st.min_angle_deg << " to " << st.max_angle_deg << " degrees, " << st.seconds_total << " s\n";
    return 0;
  }
  const bool brep = is_brep_path(input);
  if (brep && opt.cells_only) throw InputError("--cells-only is for polyhedral inputs (.poly, .stl, .off); " + input + " is a B-rep");
  if (!opt.cells_only) {
    if (ends_with(opt.output, ".poly")) throw InputError(opt.output + ": a tetrahedral mesh is written as .vtu, .msh, .inp or .unv");
    check_mesh_format(opt.output);  // any other extension no writer takes: now, not after the meshing
    GenerateOptions go;
    go.sizing.elements = opt.elements;
    go.sizing.size = opt.size;
    go.optimize.passes = opt.optimize_passes;
    go.optimize.smooth_passes = opt.smooth_passes;
    go.optimize.sliver_rounds = opt.sliver_rounds;
    go.optimize.mean_rounds = opt.mean_rounds;
    go.delaunay_insertion = opt.delaunay_insertion;
    go.threads = opt.threads;
    go.order = opt.order;
    go.optimize.boundary_flips = opt.boundary_flips;
    go.optimize.face_moves = opt.face_moves;
    go.quality_floor = opt.quality_floor;
    go.sizing.grading = opt.grading;
    go.sizing.min_size = opt.min_size;
    go.sizing.max_size = opt.max_size;
    go.sizing.curvature_elements = opt.curvature_elements;
    go.sizing.chord_deviation = opt.chord_deviation;
    go.sizing.size_grading = opt.size_grading;
    // what the walls and features make, checked again once the nodes are placed
    go.max_elements = tets_within(opt.max_memory_mb, opt.order, &go.limit_cause);
    GenerateStats st;
    // a B-rep (.brep, .step, .iges) goes the true-surface route, a polyhedral input the thesis's
    TetMesh mesh;
    if (brep) {
      const BrepInput in = load_brep_file(input);
      const Vec3 box = in.bbox_max - in.bbox_min;  // the true volume is not known before the surfaces are meshed
      check_job(box.x() * box.y() * box.z(), 0, opt);
      mesh = generate_brep_mesh(in, go, &st);
    } else {
      const PolyInput in = read_polyhedral(input);
      check_job(summarize(in).volume, in.required_elements, opt, input);
      mesh = generate_mesh(in, go, &st);
    }
    write_mesh(mesh, opt.output);
    const QualitySummary q = summarize_quality(element_quality(mesh, {}, opt.threads));
    if (!opt.stats.empty()) {
      io::write_output_file(opt.stats, [&](std::ostream& s) { s << generate_stats_json(st, q) << '\n'; });
    }
    if (!opt.quiet)
      out << opt.output << ": " << st.tets << " tetrahedra, " << st.nodes << " nodes, " << st.convex_cells << " convex cells, "
          << "min dihedral " << q.dihedral_min.min << " degrees, mean alpha " << q.alpha.mean << ", " << st.total << " s\n";
    return 0;
  }
  if (!ends_with(opt.output, ".poly"))
    throw InputError(opt.output + ": --cells-only writes the thesis .poly format; name the output *.poly");
  const PolyInput in = read_polyhedral(input);
  DecomposeOptions dopt;  // the mesher's cells: with -n, -s or the input's R, slender ones cut again
  dopt.split_size = opt.size;
  dopt.split_elements = static_cast<double>(opt.elements > 0 ? opt.elements : in.required_elements);
  const Decomposition d = decompose(in, dopt);
  write_cells_poly(d, opt.output);
  if (!opt.stats.empty()) {
    io::write_output_file(opt.stats, [&](std::ostream& s) { s << decompose_stats_json(d.stats) << '\n'; });
  }
  if (!opt.quiet)
    out << opt.output << ": " << d.cells.size() << " convex cells from " << in.regions.size() << " region(s) in "
        << d.stats.prepare_seconds + d.stats.bisect_seconds << " s\n";
  return 0;
}

}  // namespace bisect::cli
