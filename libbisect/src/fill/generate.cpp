#include "bisect/generate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <unordered_set>

#include "bisect/errors.hpp"
#include "bisect/polyhedral_model.hpp"
#include "domain/merge_facets.hpp"
#include "fill/cell_fill.hpp"
#include "fill/cell_nodes.hpp"
#include "fill/graded_nodes.hpp"
#include "fill/smooth3d.hpp"
#include "fill/tet_complex.hpp"
#include "mesh2d/face_grids.hpp"
#include "util/ordered_parallel.hpp"

namespace bisect {
namespace {

using Clock = std::chrono::steady_clock;
// Sliver repair works on tetrahedra whose smallest dihedral angle is under this (degrees).
constexpr double kSliverBelowDeg = 10;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The cell as a polytope: its faces' outer loops, turned to run counter-clockwise seen from
// outside, with outward planes.
fill::Polytope cell_polytope(const PolyhedralModel& m, const ConvexCell& c) {
  fill::Polytope p;
  std::vector<int> local(m.nodes.size(), -1);
  for (std::size_t k = 0; k < c.faces.size(); ++k) {
    const ModelFace& f = m.faces[c.faces[k]];
    std::vector<int> loop;
    for (Index v : f.loops[0]) {
      if (local[v] < 0) {
        local[v] = static_cast<int>(p.v.size());
        p.v.push_back(m.nodes[v]);
      }
      loop.push_back(local[v]);
    }
    if (!c.outward[k]) std::reverse(loop.begin(), loop.end());
    p.faces.push_back(std::move(loop));
    p.normal.push_back(c.outward[k] ? f.normal : Vec3(-f.normal));
    p.offset.push_back(c.outward[k] ? f.offset : -f.offset);
  }
  return p;
}

struct Built {
  std::int64_t helper_nodes = 0, helpers_removed = 0, skipped_nodes = 0, flips = 0, graded_nodes = 0;
  std::vector<Vec3> X;
  std::vector<fill::Tet> tets;
  std::vector<Index> region;
  std::size_t boundary_nodes = 0;  // face-grid nodes: fixed
  mesh2d::FaceGrids grids;
  std::vector<fill::Polytope> polys;         // per cell
  std::vector<std::vector<Index>> interior;  // per cell: its interior nodes
};

// Face grids and interior nodes at spacing np (7.4, 5.2): the nodes, not yet the tetrahedra.
// `count_only`: the faces' nodes without their triangles, enough to count them.
Built place_nodes(const Decomposition& d, double np, int threads, double grading, GenerateStats& st, bool count_only = false) {
  Built b;
  const auto t0 = Clock::now();
  mesh2d::FaceGridOptions fo;
  fo.size = np;
  fo.nodes_only = count_only;
  fo.threads = threads;
  b.grids = mesh2d::mesh_faces(d.model, fo);
  b.X = b.grids.nodes;
  b.boundary_nodes = b.X.size();
  b.interior.assign(d.cells.size(), {});
  std::vector<std::vector<Vec3>> uniform;
  for (std::size_t c = 0; c < d.cells.size(); ++c) {
    b.polys.push_back(cell_polytope(d.model, d.cells[c]));
    uniform.push_back(fill::shrink_cell_nodes(b.polys.back(), np));
  }
  // graded from the boundary's fine spacing (short edges); the shrinking's alone elsewhere
  fill::GradedNodeStats gs;
  const auto nodes = fill::graded_cell_nodes(b.polys, uniform, b.grids.nodes, b.grids.spacing, np, grading, &gs);
  b.graded_nodes = static_cast<std::int64_t>(gs.added);
  for (std::size_t c = 0; c < d.cells.size(); ++c)
    for (const Vec3& p : nodes[c]) {
      b.X.push_back(p);
      b.interior[c].push_back(static_cast<Index>(b.X.size() - 1));
    }
  st.gen_nodes += since(t0);
  return b;
}

// The nodes that tetrahedra will use, on the mesh's boundary and interfaces (the input faces)
// and elsewhere (inside the cells and on the cut faces, which the mesh does not keep as faces).
// Model nodes off every live face (left by the cuts) do not count.
enum NodeKind : char { kUnused = 0, kInside = 1, kOnInputFace = 2 };
std::vector<char> node_kinds(const PolyhedralModel& m, const Built& b) {
  std::vector<char> kind(b.X.size(), kUnused);
  for (std::size_t v = m.nodes.size(); v < b.X.size(); ++v) kind[v] = kInside;
  for (const ModelFace& f : m.faces) {
    if (!f.alive) continue;
    const char k = f.source >= 0 ? kOnInputFace : kInside;
    for (const auto& loop : f.loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Index a = loop[i], c = loop[(i + 1) % loop.size()];
        kind[a] = std::max(kind[a], k);
        const auto e = b.grids.edge_nodes.find({std::min(a, c), std::max(a, c)});
        if (e != b.grids.edge_nodes.end())
          for (Index v : e->second) kind[v] = std::max(kind[v], k);
      }
  }
  for (std::size_t v = m.nodes.size(); v < b.boundary_nodes; ++v)
    if (b.grids.face_of[v] >= 0 && m.faces[b.grids.face_of[v]].source >= 0) kind[v] = kOnInputFace;
  return kind;
}

struct NodeTally {
  double boundary = 0, interior = 0;
};
NodeTally tally_nodes(const PolyhedralModel& m, const Built& b) {
  NodeTally n;
  for (char k : node_kinds(m, b)) (k == kOnInputFace ? n.boundary : n.interior) += k != kUnused;
  return n;
}

// The count of tetrahedra that nodes make, before any filling: an interior node carries about
// 6.2 tetrahedra and a boundary node 2.65 (fitted on lug, part, flange and plate-hole at 3,000
// and 30,000 tetrahedra, where it predicts the count within 4%; a fixed ratio per node does not,
// as the boundary's share falls with the size). A filling measures `scale` for the model.
double predict_tets(const NodeTally& n, double scale) { return scale * (6.2 * n.interior + 2.65 * n.boundary); }

// The spacing whose nodes predict `want` tetrahedra: a cube-root step from `start`, then
// bisection in log Np once two spacings bracket the count (on small models the count jumps with
// the segments per edge and the shrinking layers, so it may not be met exactly). Only the nodes
// are placed (a fraction of a filling).
double search_spacing(const Decomposition& d, double start, double want, double scale, int threads, double grading, GenerateStats& st) {
  double lo = 0, hi = 0, trial = start, best = start, best_miss = 1e300;
  for (int round = 0; round < 10; ++round) {
    GenerateStats scratch;
    const double predicted = predict_tets(tally_nodes(d.model, place_nodes(d, trial, threads, grading, scratch, true)), scale);
    st.gen_nodes += scratch.gen_nodes;
    const double miss = std::abs(predicted - want);
    if (miss < best_miss) best_miss = miss, best = trial;
    if (miss <= 0.02 * want) break;
    if (predicted > want) lo = std::max(lo, trial);
    else hi = hi > 0 ? std::min(hi, trial) : trial;
    const double next = lo > 0 && hi > 0 ? std::sqrt(lo * hi) : trial * std::cbrt(predicted / want);
    if (std::abs(next / trial - 1) < 1e-3) break;
    trial = next;
  }
  return best;
}

// One cell's filling on its own copy of its nodes (so that cells fill in parallel): local ids
// follow the global ones in order, so the filling is the one the global ids would give.
struct CellFilling {
  std::vector<Index> global;  // local node -> node of b.X (a helper: -1 until committed)
  std::vector<Vec3> helper;   // the helper node, when one was added (left out of the mesh when removed again)
  std::vector<fill::Tet> tets;
  fill::CellFillStats stats;
};

CellFilling fill_cell(const Decomposition& d, const Built& b, const std::vector<Vec3>& nodes, std::size_t c, bool delaunay) {
  const ConvexCell& cell = d.cells[c];
  CellFilling out;
  std::vector<std::array<Index, 3>> boundary;
  for (std::size_t k = 0; k < cell.faces.size(); ++k)
    for (const auto& t : b.grids.face_tris[cell.faces[k]]) {
      boundary.push_back(cell.outward[k] ? t : std::array<Index, 3>{t[0], t[2], t[1]});
      out.global.insert(out.global.end(), t.begin(), t.end());
    }
  out.global.insert(out.global.end(), b.interior[c].begin(), b.interior[c].end());
  std::sort(out.global.begin(), out.global.end());
  out.global.erase(std::unique(out.global.begin(), out.global.end()), out.global.end());
  auto local = [&](Index v) { return static_cast<Index>(std::lower_bound(out.global.begin(), out.global.end(), v) - out.global.begin()); };
  std::vector<Vec3> X;
  X.reserve(out.global.size() + 1);
  for (Index v : out.global) X.push_back(nodes[v]);
  for (auto& t : boundary)
    for (Index& v : t) v = local(v);
  std::vector<Index> interior;
  for (Index v : b.interior[c]) interior.push_back(local(v));
  try {
    out.tets = fill::fill_convex_cell(X, boundary, interior, b.polys[c].centroid(), delaunay, &out.stats);
  } catch (const MeshingError& e) {
    throw MeshingError("convex cell " + std::to_string(c + 1) + " of input region " + std::to_string(cell.source_region + 1) + ": " + e.what());
  }
  if (X.size() > out.global.size()) {  // the helper (7.6)
    out.helper.push_back(X.back());
    out.global.push_back(-1);
  }
  return out;
}

// Each cell filled (7.6) from its face grids and interior nodes, on opt.threads threads; the
// tetrahedra join the mesh in cell order whatever the thread count.
void fill_cells(const Decomposition& d, Built& b, const GenerateOptions& opt, GenerateStats& st) {
  const auto t0 = Clock::now();
  const std::size_t n = d.cells.size();
  std::vector<CellFilling> made(n);
  std::vector<std::size_t> largest_first(n);  // the long jobs first: no thread waits on one at the end
  for (std::size_t c = 0; c < n; ++c) largest_first[c] = c;
  std::stable_sort(largest_first.begin(), largest_first.end(), [&](std::size_t x, std::size_t y) { return b.interior[x].size() > b.interior[y].size(); });
  const std::vector<Vec3> nodes = b.X;  // the cells read these while helpers join b.X
  util::ordered_parallel(
      n, util::thread_count(opt.threads), [&](std::size_t c) { made[c] = fill_cell(d, b, nodes, c, opt.delaunay_insertion); },
      [&](std::size_t c) {
        CellFilling& f = made[c];
        if (!f.helper.empty()) {
          b.X.push_back(f.helper.front());
          f.global.back() = static_cast<Index>(b.X.size() - 1);
        }
        b.helper_nodes += f.stats.helper;
        b.helpers_removed += f.stats.helper_removed;
        b.skipped_nodes += f.stats.skipped;
        b.flips += f.stats.flips;
        for (fill::Tet t : f.tets) {
          for (Index& v : t) v = f.global[v];
          b.tets.push_back(t);
        }
        b.region.resize(b.tets.size(), d.cells[c].source_region);
        f = {};
        if (opt.progress && !opt.progress(0.2 + 0.6 * static_cast<double>(c + 1) / static_cast<double>(n))) throw Cancelled();
      },
      largest_first);
  st.gen_tets += since(t0);
}

// Boundary triangles of the mesh, tagged with their input face: on the interfaces, the grids
// of the input faces between two regions; on the outer boundary, the complex's faces (the 2-2
// transformation may have re-triangulated them), outwards, grouped by input face.
void boundary_triangles(const PolyhedralModel& m, const mesh2d::FaceGrids& g, const fill::TetComplex& cx, TetMesh& out) {
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const ModelFace& face = m.faces[f];
    if (!face.alive || face.source < 0 || face.front < 0 || face.back < 0) continue;
    for (const auto& t : g.face_tris[f]) {
      out.tris.insert(out.tris.end(), t.begin(), t.end());
      out.tri_tag.push_back(face.source);
    }
  }
  std::vector<std::pair<Index, std::array<Index, 3>>> outer;
  for (std::size_t t = 0; t < cx.tet.size(); ++t)
    if (cx.alive[t])
      for (int f = 0; f < 4; ++f)
        if (cx.nb[t][f] < 0) {
          const auto fv = cx.face(static_cast<Index>(t), f);
          const auto tag = cx.surface_tag.find(fill::face_key(fv[0], fv[1], fv[2]));
          if (tag == cx.surface_tag.end()) throw MeshingError("a boundary face of the mesh lies on no input face (nodes " + std::to_string(fv[0] + 1) + ", " + std::to_string(fv[1] + 1) + ", " + std::to_string(fv[2] + 1) + ")");
          outer.push_back({tag->second, fv});
        }
  std::stable_sort(outer.begin(), outer.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const auto& [tag, fv] : outer) {
    out.tris.insert(out.tris.end(), fv.begin(), fv.end());
    out.tri_tag.push_back(tag);
  }
}

}  // namespace

TetMesh generate_mesh(const PolyInput& original, const GenerateOptions& opt, GenerateStats* stats) {
  const auto t_all = Clock::now();
  GenerateStats st;
  const PolyInput in = opt.merge_coplanar ? merge_coplanar_triangles(original) : original;
  if (opt.order != 1 && opt.order != 2) throw InputError("element order " + std::to_string(opt.order) + ": give 1 (4-node) or 2 (10-node tetrahedra)");
  const std::int64_t want = opt.elements > 0 ? opt.elements : in.required_elements;
  if (opt.size <= 0 && want <= 0) throw InputError(in.source + ": no required number of elements (give -n or -s)");
  DecomposeOptions dopt;
  // progress: decomposition to 0.2, each filling of the cells to 0.8 (a calibration round
  // starts again from 0.2: the fraction shown never goes back), the optimisation to 1
  GenerateOptions run = opt;
  double shown = 0;
  if (opt.progress)
    run.progress = [&](double x) {
      shown = std::max(shown, x);
      return opt.progress(shown);
    };
  if (run.progress) dopt.progress = [&](double x) { return run.progress(0.2 * x); };
  const Decomposition d = decompose(in, dopt);
  st.init_geom = d.stats.prepare_seconds;
  st.bisect = d.stats.bisect_seconds;
  st.convex_cells = static_cast<std::int64_t>(d.cells.size());
  std::vector<Index> meshed;  // input regions that got cells (cavities get none)
  for (const ConvexCell& c : d.cells)
    if (std::find(meshed.begin(), meshed.end(), c.source_region) == meshed.end()) meshed.push_back(c.source_region);
  st.regions = static_cast<std::int64_t>(meshed.size());
  double volume = 0;
  for (const ConvexCell& c : d.cells) volume += cell_polytope(d.model, c).volume();
  // 6.11 and A2: the ideal spacing (real meshes hold more tetrahedra than V / (Np^3 / 8), so
  // the count is corrected below)
  double np = opt.size > 0 ? opt.size : std::cbrt(8 * volume / static_cast<double>(want));
  // The count: the spacing is searched on the count its nodes predict, the cells are filled,
  // and when the count misses R by more than 5% the filling's own ratio corrects the prediction
  // and the cells are filled again (at most three fillings; the closest count wins).
  Built b;
  double used = np, last = -1, scale = 1, best_miss = 1e300;
  const double target = static_cast<double>(want);
  for (int fill_round = 0; fill_round < 3; ++fill_round) {
    const double spacing = opt.size > 0 ? opt.size : search_spacing(d, np, target, scale, run.threads, run.grading, st);
    if (last > 0 && std::abs(spacing / last - 1) < 1e-3) break;  // nothing new to try
    last = spacing;
    Built again = place_nodes(d, spacing, run.threads, run.grading, st);
    fill_cells(d, again, run, st);
    ++st.fillings;
    const double count = static_cast<double>(again.tets.size());
    const double miss = std::abs(count - target);
    scale = count / predict_tets(tally_nodes(d.model, again), 1);
    if (miss < best_miss) best_miss = miss, b = std::move(again), used = spacing;
    if (opt.size > 0 || best_miss <= 0.05 * target) break;
    np = spacing;  // the next search starts here
  }
  if (opt.size <= 0 && best_miss > 0.2 * target) {
    // out of reach: tell what the input allows (the count at a spacing the size of the model,
    // where only the input's own nodes and edges are left), as measured by the last filling
    GenerateStats scratch;
    double reach = 0;  // at least half the model's diameter
    for (const Vec3& p : d.model.nodes) reach = std::max(reach, (p - d.model.nodes.front()).norm());
    const Built coarsest = place_nodes(d, 2 * reach, run.threads, run.grading, scratch, true);
    st.count_floor = std::llround(predict_tets(tally_nodes(d.model, coarsest), scale));
  }
  st.helper_nodes = b.helper_nodes, st.helpers_removed = b.helpers_removed, st.skipped_nodes = b.skipped_nodes, st.flips = b.flips;
  st.graded_nodes = b.graded_nodes;
  st.spacing = used;
  // 7.5 over the whole mesh (cut faces are no constraint any more), then smoothing
  const auto t_opt = Clock::now();
  fill::TetComplex cx(b.X);
  cx.build(std::move(b.tets), std::move(b.region));
  {
    // input faces hold; those of the outer boundary may take the 2-2 transformation (7.5)
    // within their input face
    std::unordered_set<fill::FaceKey, fill::FaceKeyHash> input_faces;
    for (std::size_t f = 0; f < d.model.faces.size(); ++f) {
      const ModelFace& face = d.model.faces[f];
      if (!face.alive || face.source < 0) continue;
      for (const auto& t : b.grids.face_tris[f]) {
        input_faces.insert(fill::face_key(t[0], t[1], t[2]));
        if (face.front < 0 || face.back < 0) cx.surface_tag[fill::face_key(t[0], t[1], t[2])] = face.source;
      }
    }
    cx.constrain(input_faces);
    cx.boundary_flips = opt.boundary_flips;
  }
  // transformations and smoothing in turn: each opens moves for the other; then the slivers
  // they leave (nodes on input faces stay where they are)
  std::vector<char> fixed = node_kinds(d.model, b);
  for (char& k : fixed) k = k != kInside;
  for (int pass = 0; pass < std::max(opt.optimize_passes, opt.smooth_passes); ++pass) {
    if (pass < opt.optimize_passes) st.flips += cx.improve_all(std::numeric_limits<std::int64_t>::max());
    if (pass < opt.smooth_passes) {
      fill::smooth_interior(b.X, cx.tets(), fixed, 1);
      cx.refresh_quality();
    }
  }
  if (opt.sliver_rounds > 0) st.sliver_moves = static_cast<std::int64_t>(fill::repair_slivers(cx, b.X, fixed, kSliverBelowDeg, opt.sliver_rounds));
  const std::vector<fill::Tet> tets = cx.tets();
  const std::vector<Index> region = cx.tags();
  if (run.progress && !run.progress(1.0)) throw Cancelled();
  st.optimize = since(t_opt);
  // the mesh: used nodes only, in their order (dead model nodes, skipped nodes and removed
  // helpers drop out)
  TetMesh out;
  std::vector<Index> id(b.X.size(), -1);
  for (const auto& t : tets)
    for (Index v : t) id[v] = 0;
  for (std::size_t v = 0; v < b.X.size(); ++v)
    if (id[v] == 0) {
      id[v] = static_cast<Index>(out.nodes.size());
      out.nodes.push_back(b.X[v]);
    }
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const Index v[4] = {id[tets[t][0]], id[tets[t][1]], id[tets[t][2]], id[tets[t][3]]};
    out.add_tet(v, region[t]);
  }
  boundary_triangles(d.model, b.grids, cx, out);
  for (Index& v : out.tris) v = id[v];
  if (opt.order == 2) out = to_second_order(out);
  st.nodes = static_cast<std::int64_t>(out.nodes.size());
  st.tets = static_cast<std::int64_t>(out.num_tets());
  st.total = since(t_all);
  if (stats) *stats = st;
  return out;
}

std::string generate_stats_json(const GenerateStats& s, const QualitySummary& q) {
  std::ostringstream o;
  o << "{\"nodes\": " << s.nodes << ", \"tets\": " << s.tets << ", \"regions\": " << s.regions << ", \"convex_cells\": " << s.convex_cells
    << ", \"spacing\": " << s.spacing << ", \"helper_nodes\": " << s.helper_nodes << ", \"helpers_removed\": " << s.helpers_removed
    << ", \"skipped_nodes\": " << s.skipped_nodes << ", \"flips\": " << s.flips << ", \"sliver_moves\": " << s.sliver_moves << ", \"fillings\": " << s.fillings << ", \"graded_nodes\": " << s.graded_nodes << ", \"count_floor\": " << s.count_floor << ", \"times\": {\"init_geom\": " << s.init_geom
    << ", \"bisect\": " << s.bisect << ", \"gen_nodes\": " << s.gen_nodes << ", \"gen_tets\": " << s.gen_tets
    << ", \"optimize\": " << s.optimize << ", \"total\": " << s.total << "}, \"quality\": " << quality_json(q) << "}";
  return o.str();
}

}  // namespace bisect
