// The 3D generator's stage sequence for polyhedral inputs (thesis 6.9.2): preparation and
// convex decomposition, the count calibration with node placement and cell filling, the global
// optimisation, the mesh assembly. Each stage lives in its own file of this folder (or of
// nodes/, tet/, optimize/); this one wires them and keeps the progress and the stage times.
#include "bisect/generate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "bisect/brep_input.hpp"  // point_name
#include "bisect/errors.hpp"
#include "bisect/json_text.hpp"
#include "bisect/quality.hpp"
#include "bisect/polyhedral_model.hpp"
#include "domain/merge_facets.hpp"
#include "geom/recentre.hpp"
#include "optimize/inverted_refill.hpp"
#include "optimize/mean_shape.hpp"
#include "optimize/optimize_mesh.hpp"
#include "pipeline/count_calibration.hpp"
#include "pipeline/mesh_assembly.hpp"
#include "pipeline/quality_floor.hpp"

namespace bisect {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Per node: the unit normal of the input face it lies inside, for the node moves within it
// (optimize/mean_shape.hpp), when the grids of that input face alone hold it (cut faces aside:
// gone once the cells are filled); zero for a node on an input edge or vertex, between two input
// faces, or inside.
std::vector<Vec3> one_face_normals(const PolyhedralModel& m, const pipeline::Built& b) {
  constexpr Index kNone = -1, kMany = -2;
  std::vector<Index> source(b.X.size(), kNone);
  std::vector<Vec3> normal(b.X.size(), Vec3::Zero());
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const ModelFace& face = m.faces[f];
    if (!face.alive || face.source < 0) continue;
    for (const auto& t : b.grids.face_tris[f])
      for (Index v : t) {
        if (source[v] == kNone) source[v] = face.source, normal[v] = optimize::slide_normal(face.normal);
        else if (source[v] != face.source) source[v] = kMany;
      }
  }
  for (std::size_t v = 0; v < normal.size(); ++v)
    if (source[v] < 0) normal[v] = Vec3::Zero();
  return normal;
}

// The work a mesh not kept cost, added to the figures of the one kept: stage seconds, node
// placements, fillings, meshes made for the quality floor.
void carry_work(const GenerateStats& from, GenerateStats& to) {
  to.gen_nodes = from.gen_nodes, to.gen_tets = from.gen_tets, to.optimize = from.optimize;
  to.optimize_parts = from.optimize_parts;
  to.placements = from.placements, to.fillings = from.fillings, to.quality_meshes = from.quality_meshes;
}

void add_times(OptimizeTimes& to, const OptimizeTimes& t) {
  to.build += t.build, to.blocks += t.blocks, to.flips += t.flips, to.smooth += t.smooth;
  to.refill += t.refill, to.slivers += t.slivers, to.mean += t.mean;
}

// 7.5 over the whole mesh of the filled cells (cut faces are no constraint any more), smoothing,
// the sliver repair and the mean shape, then the output mesh. Sets the figures of this mesh in
// st and adds the optimisation's seconds to its times.
TetMesh optimise_and_assemble(const Decomposition& d, pipeline::Calibrated& cal, const GenerateOptions& opt,
                              const std::function<bool(double)>& progress, GenerateStats& st) {
  pipeline::Built& b = cal.built;
  st.helper_nodes = b.helper_nodes, st.helpers_removed = b.helpers_removed, st.skipped_nodes = b.skipped_nodes, st.flips = b.flips;
  st.refilled_cells = b.refilled_cells;
  st.graded_nodes = b.graded_nodes;
  st.spacing = cal.spacing;
  const auto t_opt = Clock::now();
  tet::TetComplex cx(b.X);
  optimize::FilledMesh filled{std::move(b.tets), std::move(b.region), {}, {}, {}};
  // input faces hold; those of the outer boundary may take the 2-2 transformation (7.5) within
  // their input face
  for (std::size_t f = 0; f < d.model.faces.size(); ++f) {
    const ModelFace& face = d.model.faces[f];
    if (!face.alive || face.source < 0) continue;
    for (const auto& t : b.grids.face_tris[f]) {
      filled.held.insert(tet::face_key(t[0], t[1], t[2]));
      if (face.front < 0 || face.back < 0) filled.surface_tag[tet::face_key(t[0], t[1], t[2])] = face.source;
    }
  }
  // nodes on input faces stay where they are, but for moves within the one face they lie inside
  std::vector<char> fixed = pipeline::node_kinds(d.model, b);
  for (char& k : fixed) k = k != pipeline::kInside;
  filled.slides.plane = one_face_normals(d.model, b);
  std::function<bool(double)> optimize_progress;
  if (progress) optimize_progress = [&](double x) { return progress(0.8 + 0.2 * x); };
  const optimize::OptimizeCounts oc =
      optimize::optimize_filled(cx, std::move(filled), b.X, fixed, opt.optimize, optimize_progress, opt.threads);
  add_times(st.optimize_parts, oc.times);
  st.flips += oc.flips;
  st.sliver_moves = oc.sliver_moves;
  st.surface_moves = oc.surface_moves;
  st.mean_changes = oc.mean_changes;
  st.refilled_folds = oc.refilled_folds;
  st.optimize_blocks = oc.blocks;
  Vec3 fold;
  Index fold_region = 0;
  if (oc.folds_left > 0 && optimize::find_fold(cx, b.X, &fold, &fold_region))  // never a mesh with a fold
    throw MeshingError(d.model.source + ": a tetrahedron at " + point_name(fold) + " came out inside out (a defect of the mesher)");
  st.optimize += since(t_opt);
  return pipeline::assemble_mesh(d.model, b.grids, cx, b.X, opt.order);
}

}  // namespace

double nominal_spacing(double volume, double elements) { return std::cbrt(8 * volume / elements); }

TetMesh generate_mesh(const PolyInput& original, const GenerateOptions& opt, GenerateStats* stats) {
  const Vec3 shift = geom::recentring_shift(original.nodes);  // a part far from the origin: near it
  if (shift != Vec3::Zero()) {
    PolyInput near = original;
    for (Vec3& p : near.nodes) p -= shift;
    TetMesh m = generate_mesh(near, opt, stats);
    for (Vec3& p : m.nodes) p += shift;
    return m;
  }
  const auto t_all = Clock::now();
  GenerateStats st;
  const PolyInput in = opt.merge_coplanar ? merge_coplanar_triangles(original) : original;
  if (opt.order != 1 && opt.order != 2) throw InputError("element order " + std::to_string(opt.order) + ": give 1 (4-node) or 2 (10-node tetrahedra)");
  const std::int64_t want = opt.sizing.elements > 0 ? opt.sizing.elements : in.required_elements;
  if (opt.sizing.size <= 0 && want <= 0) throw InputError(in.source + ": no required number of elements (give -n or -s)");
  // progress: decomposition to 0.2, each filling of the cells to 0.8 (a calibration round
  // starts again from 0.2: the fraction shown never goes back), the optimisation to 1
  double shown = 0;
  std::function<bool(double)> progress;
  if (opt.progress)
    progress = [&](double x) {
      shown = std::max(shown, x);
      return opt.progress(shown);
    };
  DecomposeOptions dopt = opt.decompose;
  dopt.curved_faces.clear();  // the B-rep route's, by its proxy's faces: a polyhedral input's facets are its surface
  if (progress) dopt.progress = [&](double x) { return progress(0.2 * x); };
  dopt.split_size = opt.sizing.size, dopt.split_elements = static_cast<double>(want);
  const Decomposition d = decompose(in, dopt);
  st.init_geom = d.stats.prepare_seconds;
  st.bisect = d.stats.bisect_seconds;
  st.convex_cells = static_cast<std::int64_t>(d.cells.size());
  std::vector<Index> meshed;  // input regions that got cells (cavities get none)
  for (const ConvexCell& c : d.cells)
    if (std::find(meshed.begin(), meshed.end(), c.source_region) == meshed.end()) meshed.push_back(c.source_region);
  st.regions = static_cast<std::int64_t>(meshed.size());
  double volume = 0;
  for (const ConvexCell& c : d.cells) volume += pipeline::cell_polytope(d.model, c).volume();
  double area = 0;  // of the input's faces (an interface between regions once)
  for (std::size_t f = 0; f < d.model.faces.size(); ++f)
    if (d.model.faces[f].alive && d.model.faces[f].source >= 0) area += d.model.face_area(static_cast<Index>(f));
  // where the count search starts (count_calibration.hpp's kPolyhedralNodes)
  const double start = opt.sizing.size > 0 ? opt.sizing.size : pipeline::expected_spacing(volume, area, static_cast<double>(want), pipeline::kPolyhedralNodes);
  std::function<bool(double)> fill_progress;
  if (progress) fill_progress = [&](double x) { return progress(0.2 + 0.6 * x); };
  pipeline::Calibrated cal = pipeline::fill_to_count(d, start, opt.sizing.size, want, opt, fill_progress, st);
  st.fillings = cal.fillings;
  st.count_floor = cal.count_floor;
  if (st.count_floor > 0) {
    // cells' walls kept their spacing below R's, else the input's own nodes and edges
    st.count_floor_reason = cal.floor_by_walls ? pipeline::walls_floor_reason(cal.thinnest_wall) : "facets";
  }
  TetMesh out = optimise_and_assemble(d, cal, opt, progress, st);
  // the count floor for quality's sake (pipeline/quality_floor.hpp), from the count made for R
  // (which the facets or walls may have held above it); not when a size was given
  const std::int64_t made = static_cast<std::int64_t>(out.num_tets());
  if (opt.quality_floor && opt.sizing.size <= 0 && made <= pipeline::kQualityFloorMaxTets) {
    const pipeline::QualityBars bars = pipeline::quality_bars(std::max(want, made));
    const QualitySummary at_asked = summarize_quality(element_quality(out, {}, opt.threads));
    if (!pipeline::meets_mean_bar(at_asked, bars)) {
      double spacing = cal.spacing;
      std::int64_t last = made;
      for (const std::int64_t more : pipeline::quality_floor_counts(made)) {
        if (more <= last) continue;  // the count already holds that many
        GenerateStats trial = st;
        const double from = spacing * std::cbrt(static_cast<double>(last) / static_cast<double>(more));
        pipeline::Calibrated again;
        TetMesh m;
        try {  // the mesh at R is made: a trial that cannot finish (the memory bound, a stage) ends the floor
          again = pipeline::fill_to_count(d, from, 0, more, opt, fill_progress, trial);
          trial.fillings += again.fillings;
          ++trial.quality_meshes;
          if (again.count_floor > 0) {  // out of reach: the facets or walls hold the count
            carry_work(trial, st);
            break;
          }
          m = optimise_and_assemble(d, again, opt, progress, trial);
        } catch (const InputError&) {
          carry_work(trial, st);
          break;
        } catch (const MeshingError&) {
          carry_work(trial, st);
          break;
        }
        const QualitySummary q = summarize_quality(element_quality(m, {}, opt.threads));
        last = static_cast<std::int64_t>(m.num_tets()), spacing = again.spacing;
        if (pipeline::floor_keeps(q, at_asked, bars)) {
          trial.count_floor = last;
          trial.count_floor_reason = pipeline::quality_floor_reason(want, at_asked, bars, last, q);
          st = trial, out = std::move(m);
          break;
        }
        carry_work(trial, st);  // not kept: the mesh at R stays, with its figures
      }
    }
  }
  if (progress && !progress(1.0)) throw Cancelled();
  st.nodes = static_cast<std::int64_t>(out.nodes.size());
  st.tets = static_cast<std::int64_t>(out.num_tets());
  st.surface_min_angle = surface_min_angle_deg(out);
  st.total = since(t_all);
  if (stats) *stats = st;
  return out;
}

std::string generate_stats_json(const GenerateStats& s, const QualitySummary& q) {
  std::ostringstream o;
  o << "{\"nodes\": " << s.nodes << ", \"tets\": " << s.tets << ", \"regions\": " << s.regions << ", \"convex_cells\": " << s.convex_cells
    << ", \"spacing\": " << s.spacing << ", \"helper_nodes\": " << s.helper_nodes << ", \"helpers_removed\": " << s.helpers_removed
    << ", \"skipped_nodes\": " << s.skipped_nodes << ", \"flips\": " << s.flips << ", \"sliver_moves\": " << s.sliver_moves << ", \"mean_changes\": " << s.mean_changes << ", \"surface_moves\": " << s.surface_moves << ", \"surface_flips\": " << s.surface_flips
    << ", \"fillings\": " << s.fillings << ", \"graded_nodes\": " << s.graded_nodes << ", \"count_floor\": " << s.count_floor << ", \"quality_meshes\": " << s.quality_meshes
    << ", \"coplanar_triangles\": " << s.coplanar_triangles << ", \"coplanar_hint\": " << json_string(s.coplanar_hint)
    << ", \"count_floor_reason\": " << json_string(s.count_floor_reason) << ", \"surface_min_angle\": " << s.surface_min_angle
    << ", \"straightened_edges\": " << s.straightened_edges << ", \"facet_pieces\": " << s.facet_pieces << ", \"proxy_cells\": " << s.proxy_cells << ", \"joined_cells\": " << s.joined_cells << ", \"recovered_cells\": " << s.recovered_cells << ", \"steiner_nodes\": " << s.steiner_nodes << ", \"refilled_cells\": " << s.refilled_cells
    << ", \"refilled_folds\": " << s.refilled_folds << ", \"optimize_blocks\": " << s.optimize_blocks << ", \"proxy_attempts\": " << s.proxy_attempts << ", \"placements\": " << s.placements
    << ", \"proxy_retry_reason\": " << json_string(s.proxy_retry_reason) << ", \"face_corner_retry\": " << (s.face_corner_retry ? "true" : "false")
    << ", \"times\": {\"init_geom\": " << s.init_geom << ", \"bisect\": " << s.bisect << ", \"gen_nodes\": " << s.gen_nodes
    << ", \"gen_tets\": " << s.gen_tets << ", \"optimize\": " << s.optimize << ", \"total\": " << s.total
    << "}, \"optimize_parts\": {\"build\": " << s.optimize_parts.build << ", \"blocks\": " << s.optimize_parts.blocks
    << ", \"flips\": " << s.optimize_parts.flips
    << ", \"smooth\": " << s.optimize_parts.smooth << ", \"refill\": " << s.optimize_parts.refill << ", \"slivers\": " << s.optimize_parts.slivers
    << ", \"mean\": " << s.optimize_parts.mean << "}, \"quality\": " << quality_json(q) << "}";
  return o.str();
}

}  // namespace bisect
