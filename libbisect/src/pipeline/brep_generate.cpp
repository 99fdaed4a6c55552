// The B-rep route's stage sequence (ARCHITECTURE.md §1): the proxy and its convex decomposition,
// the size field, the surface grids on the true surfaces with the cut lines in them, the morph of
// the cut faces and interior nodes onto the true geometry, the cell fill, the global
// optimisation, the mesh assembly and, for order 2, the curved mid-nodes.
#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <cstdio>
#include <cmath>
#include <set>
#include <string>

#include "bisect/errors.hpp"
#include "bisect/generate.hpp"
#include "bisect/quality.hpp"
#include "optimize/inverted_refill.hpp"
#include "optimize/mean_shape.hpp"
#include "optimize/optimize_mesh.hpp"
#include "optimize/surface_angles.hpp"
#include "pipeline/brep_bodies.hpp"
#include "pipeline/brep_boundary.hpp"
#include "pipeline/brep_closure.hpp"
#include "pipeline/brep_placement.hpp"
#include "pipeline/brep_grids.hpp"
#include "pipeline/brep_order2.hpp"
#include "pipeline/brep_proxy.hpp"
#include "pipeline/brep_surface_flips.hpp"
#include "pipeline/cell_filling.hpp"
#include "pipeline/count_calibration.hpp"
#include "pipeline/node_placement.hpp"
#include "size/brep_sizes.hpp"
#include "util/progress_poll.hpp"

namespace bisect {
namespace {

// Where each stage ends on the progress bar, so that the bar moves with the time (issue 19):
// measured on a filleted block with a hole at 2e5 tetrahedra, tetra4 and tetra10 (the stage
// times of tests/freecad/gui_stall.py's run; the order-2 assembly reports no steps of its own,
// the complex's build is the optimisation's). The optimisation's end came from 0.88 to 0.84 when
// its passes went to blocks on two threads: the bar was 0.11 ahead of the time at its end.
struct BarShares {
  double decomposed, placed, jobs, filled, optimized;
};
constexpr BarShares kBar{0.02, 0.16, 0.26, 0.36, 0.84};

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The tetrahedra the size field asks for over the cells, before any node is placed: the
// nominal count 8 / h(x)^3 (thesis 6.11 with h varying) summed over a grid in each cell's box,
// about 2 * 10^4 points in all shared by volume, at least 2 along each axis (a thin sheet's
// thickness too), the points inside the cell counted, plus the boundary layer that grid cannot
// see (boundary_layer_count). For the element bound: placing the nodes of a 100 x 100 x 1 sheet
// at its walls' spacing took 5 s before the bound could refuse it.
constexpr double kFieldSamples = 2e4;

// The area of the proxy's faces (its tessellation's triangles): count_calibration.hpp's
// expected_spacing takes it for the boundary's share of the nodes, boundary_layer_count for
// its samples.
double tessellation_area(const BrepTessellation& tess) {
  double area = 0;
  for (const BrepTessellation::Face& f : tess.faces)
    for (const auto& t : f.tris) area += 0.5 * (tess.nodes[t[1]] - tess.nodes[t[0]]).cross(tess.nodes[t[2]] - tess.nodes[t[0]]).norm();
  return area;
}

// The tetrahedra of the graded layer under the surface that the volume grid (points `unit`
// apart) misses: where the surface asks for h0 much finer than the grid (a chord deviation of
// 3e-5 on a 5 mm cylinder: h0 = 0.035, grid points 0.4 apart), the size grows as h0 + g t with
// the depth t, and the layer holds nearly all the elements: the grid alone predicted 2e6
// tetrahedra where the surface grids alone would have taken minutes to place. Per unit of area,
// the count 8 / h^3 integrated over the depth of one grid step, less what the grid counts there
// (the size at half that depth): nought where h0 is the grid's own scale. area: tess's
// (tessellation_area).
double boundary_layer_count(const BrepInput& in, const BrepTessellation& tess, double area, const size::SizeField& h, double unit) {
  const double g = h.grading(), base = h.base();
  if (!(area > 0) || !(unit > 0) || !(g > 0)) return 0;
  const double step = std::sqrt(area / kFieldSamples);  // about as many samples as the volume grid
  auto per_area = [&](double h0) {
    const double deep = std::clamp((base - h0) / g, 0.0, unit);  // where the size reaches the base
    const double layer = 4 / g * (1 / (h0 * h0) - 1 / ((h0 + g * deep) * (h0 + g * deep))) + 8 * (unit - deep) / (base * base * base);
    const double grid = std::min(base, h0 + 0.5 * g * unit);
    return std::max(0.0, layer - 8 * unit / (grid * grid * grid));
  };
  double count = 0;
  for (std::size_t face = 0; face < tess.faces.size(); ++face) {
    const BrepTessellation::Face& f = tess.faces[face];
    const ParametricSurface* surface = face < in.faces.size() ? in.faces[face].surface.get() : nullptr;
    for (std::size_t k = 0; k < f.tris.size(); ++k) {
      const auto& t = f.tris[k];
      const Vec3 &a = tess.nodes[t[0]], &b = tess.nodes[t[1]], &c = tess.nodes[t[2]];
      const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
      const int n = static_cast<int>(std::clamp(std::ceil(longest / step), 1.0, 64.0));
      const double sub = 0.5 * (b - a).cross(c - a).norm() / (n * n);
      // at barycentric (x, y) on the true surface (the size there: a chord of a 30 degree proxy
      // lies a sagitta deep, where the size has grown), on the chord where no surface is known
      auto size_at = [&](double x, double y) {
        if (surface && k < f.uv.size()) {
          const std::array<Vec2, 3>& uv = f.uv[k];
          return std::max(h.at(surface->point(uv[0] + (uv[1] - uv[0]) * x + (uv[2] - uv[0]) * y)), 1e-300);
        }
        return std::max(h.at(a + (b - a) * x + (c - a) * y), 1e-300);
      };
      // the n^2 sub-triangles' centres, at barycentric ((i + 1/3) / n, (j + 1/3) / n) and their mirror images
      for (int i = 0; i < n; ++i)
        for (int j = 0; i + j < n; ++j) {
          count += sub * per_area(size_at((i + 1.0 / 3) / n, (j + 1.0 / 3) / n));
          if (i + j + 1 < n) count += sub * per_area(size_at((i + 2.0 / 3) / n, (j + 2.0 / 3) / n));
        }
    }
  }
  return count;
}

// The count the size field predicts over the cells: a grid of about kFieldSamples points over
// the volume, and the boundary's layer. Where even every sample at the field's smallest size
// would predict no more than `limit`, that bound is returned without sampling: the element bound
// cannot refuse, and the samples are the field's slowest queries (its growth from thousands of
// sources prunes little): corpus/x_as1_tu_203.brep, 18 solids meshed body by body, spent 15 of
// its 38 s at 2*10^4 here.
double field_count(const BrepInput& in, const Decomposition& d, const size::SizeField& h, const BrepTessellation& tess, double limit) {
  struct Cell {
    nodes::Polytope p;
    Vec3 lo, hi;  // its box
  };
  std::vector<Cell> cells;
  double total_volume = 0, boxes = 0;
  for (const ConvexCell& c : d.cells) {
    Cell cell{pipeline::cell_polytope(d.model, c), Vec3::Zero(), Vec3::Zero()};
    if (cell.p.v.empty()) continue;
    cell.lo = cell.hi = cell.p.v[0];
    for (const Vec3& v : cell.p.v) cell.lo = cell.lo.cwiseMin(v), cell.hi = cell.hi.cwiseMax(v);
    total_volume += cell.p.volume();
    boxes += std::max(0.0, (cell.hi - cell.lo).prod());
    cells.push_back(std::move(cell));
  }
  if (!(total_volume > 0)) return 0;
  const double unit = std::cbrt(total_volume / kFieldSamples);  // the layer's depth (boundary_layer_count)
  // every sample weighs 8 dv / h^3 with h at least h.smallest(): the grid's at most 8 / h^3 over
  // the cells' boxes, the layer's at most 8 unit / h^3 per unit of area
  const double s = h.smallest(), area = tessellation_area(tess);
  const double bound = 8 * (boxes + area * unit) / (s * s * s);
  if (bound <= limit) return bound;
  double count = 0;
  for (const Cell& cell : cells) {
    const nodes::Polytope& p = cell.p;
    const Vec3 extent = cell.hi - cell.lo;
    const double box = extent.prod();
    if (!(box > 0)) continue;
    const double points = std::max(8.0, kFieldSamples * p.volume() / total_volume), step = std::cbrt(box / points);
    int n[3];
    for (int a = 0; a < 3; ++a) n[a] = static_cast<int>(std::clamp(std::ceil(extent[a] / step), 2.0, 1000.0));
    const double dv = box / (static_cast<double>(n[0]) * n[1] * n[2]);
    for (int i = 0; i < n[0]; ++i)
      for (int j = 0; j < n[1]; ++j)
        for (int k = 0; k < n[2]; ++k) {
          const Vec3 x = cell.lo + extent.cwiseProduct(Vec3((i + 0.5) / n[0], (j + 0.5) / n[1], (k + 0.5) / n[2]));
          bool inside = true;
          for (std::size_t f = 0; f < p.normal.size() && inside; ++f) inside = p.normal[f].dot(x) <= p.offset[f];
          if (!inside) continue;
          const double hx = h.at(x);
          count += 8 * dv / (hx * hx * hx);
        }
  }
  return count + boundary_layer_count(in, tess, area, h, unit);
}

// What keeps the elements smaller than R asks, for the element bound's message.
std::string element_bound_why(const size::BrepSizeReport& sizes) {
  if (sizes.thinnest_wall > 0) return pipeline::walls_why(sizes.thinnest_wall);
  if (!(sizes.smallest_edge > 0)) return "";
  char why[64];
  std::snprintf(why, sizeof why, "B-rep edges down to %.3g long", sizes.smallest_edge);
  return why;
}

// The proxy's angular deflection: about twice the angle the curvature bound gives an element,
// between 25 and 60 degrees. Coarser than the elements, so that a concave face's facets (each
// its own cell side) are no narrower than an element; fine enough that a cell whose faces move
// onto the true surface stays star-shaped.
double proxy_angle(const SizeOptions& o) {
  const double element = o.curvature_elements > 0 ? 2 * M_PI / o.curvature_elements : M_PI / 3;
  return std::clamp(2 * element, 25 * M_PI / 180, 60 * M_PI / 180);
}

// The proxy and its decomposition. A proxy whose facets cross (a thin wall between two curved
// faces tessellated coarsely) is made again finer, up to three times. With keep_angle, the first
// proxy is made again at the linear deflection that keeps the angle on every curved face
// (pipeline::angle_keeping_deflection), when that is finer by more than a third.
struct Decomposed {
  pipeline::BrepProxy proxy;
  Decomposition d;
  bool angle_kept = true;  // the first proxy kept the angle on every curved face
};
Decomposed decompose_brep(const BrepInput& in, const GenerateOptions& opt, double angle, bool keep_angle, bool mend_flat, bool& flat_seen,
                          const std::function<bool(double)>& progress) {
  const double diag = (in.bbox_max - in.bbox_min).norm();
  double linear = 0.05 * diag;
  for (int attempt = 0;; ++attempt) {
    Decomposed out;
    out.proxy = pipeline::make_proxy(in, linear, angle, mend_flat);
    if (attempt == 0) {
      // no finer than a thousandth of the diagonal
      const double keeping = std::max(pipeline::angle_keeping_deflection(in, out.proxy), 1e-3 * diag);
      out.angle_kept = keeping >= 0.7 * linear;
      if (keep_angle && !out.angle_kept) {
        linear = keeping;
        out.proxy = pipeline::make_proxy(in, linear, angle, mend_flat);
      }
    }
    flat_seen = flat_seen || out.proxy.flat_facets > 0;
    DecomposeOptions dopt = opt.decompose;
    if (progress) dopt.progress = progress;
    dopt.split_size = opt.sizing.size, dopt.split_elements = static_cast<double>(opt.sizing.elements);
    // A proxy edge is reflex only when it turns in by more than a degree: a tessellation's fans
    // round a sphere's pole are convex on the true surface but lie flat to round-off, and cuts
    // through them (the thesis's tolerance is a thousandth of a degree) leave slivers at the pole.
    // A cell a degree short of convex is still seen whole from inside.
    dopt.reflex_tol_deg = std::max(dopt.reflex_tol_deg, 1.0);
    // No cut may leave a corner under 25 degrees in a flat face or a cut face (DecomposeOptions::
    // min_face_corner_deg): the face grids are to have no angle under 20. Flange at 10^5 had a
    // piece of its top face 12.6 degrees wide at a corner (two cut lines from one point), and its
    // surface grid 12.6 degrees there.
    dopt.min_face_corner_deg = std::max(dopt.min_face_corner_deg, 25.0);
    dopt.curved_faces.assign(out.proxy.face_tri.size(), 0);
    for (std::size_t f = 0; f < out.proxy.face_tri.size(); ++f) dopt.curved_faces[f] = out.proxy.face_tri[f] >= 0;
    try {
      out.d = decompose(out.proxy.input, dopt);
      return out;
    } catch (const InputError& e) {
      // the proxy's own fault (its coarse facets meet): finer; the shape's fault shows again
      if (attempt >= 3) {
        char degrees[32];
        std::snprintf(degrees, sizeof degrees, "%.3g", angle * 180 / M_PI);
        // either the shape's faces meet there, or the proxy folds where the shape is sound: the
        // message says both. corpus/Block.brep is refused so: round its countersinks' half cone
        // apexes the flips towards the surface make fans of facets flat in space that lie over
        // each other (Face478's 48 pairs). Made with mend_flat, its first proxy has none, but its
        // decomposition ran past 15 minutes (build_section), so a quick refusal is kept here.
        throw InputError(in.source + ": the shape's tessellation is not a valid solid even at an angular deflection of " + degrees +
                         " degrees (" + e.what() + "); either the shape's faces meet there, or OpenCASCADE's tessellation folds where " +
                         "the shape is sound (it does at a cone's apex)");
      }
      angle *= 0.5, linear *= 0.5;
    }
  }
}

// The grid nodes that may move within the B-rep face they lie inside (optimize::FaceSlides): in
// the plane of a flat face (its normal as optimize::slide_normal makes it), or on a curved face,
// back onto which each trial position is taken by the face's closest point from the node's own
// (u, v). Nodes on edges and vertices stay.
optimize::FaceSlides face_slides(const BrepInput& in, const pipeline::BrepGrids& grids) {
  optimize::FaceSlides s;
  const std::size_t n = grids.nodes.on.size();
  s.plane.assign(n, Vec3::Zero());
  s.curved.assign(n, 0);
  std::vector<Vec3> flat(in.faces.size(), Vec3::Zero());
  for (std::size_t f = 0; f < in.faces.size(); ++f) {
    if (!in.faces[f].planar || !in.faces[f].surface) continue;
    const ParametricSurface& surf = *in.faces[f].surface;
    flat[f] = optimize::slide_normal(surf.normal(0.5 * (surf.uv_min() + surf.uv_max())));
  }
  auto face = std::make_shared<std::vector<Index>>(n, -1);
  auto uv = std::make_shared<std::vector<Vec2>>(n, Vec2::Zero());
  for (const pipeline::FacePiece& piece : grids.pieces)
    for (std::size_t k = 0; k < piece.tris.size(); ++k)
      for (int i = 0; i < 3; ++i) (*uv)[piece.tris[k][i]] = piece.tri_uv[k][i];
  for (std::size_t v = 0; v < n; ++v) {
    const pipeline::PointOn& on = grids.nodes.on[v];
    if (on.kind != pipeline::PointOn::kFace || !in.faces[on.id].surface) continue;
    if (in.faces[on.id].planar) {
      s.plane[v] = flat[on.id];
    } else {
      s.curved[v] = 1;
      (*face)[v] = on.id;
    }
  }
  s.onto = [&in, face, uv](Index v, const Vec3& p, Vec3* normal) {
    const ParametricSurface& surf = *in.faces[(*face)[v]].surface;
    const Vec2 at = surf.closest_point(p, (*uv)[v]);
    if (normal) *normal = surf.normal(at);
    return surf.point(at);
  };
  // nodes inside B-rep edges, for the surface angles' pass: along the edge's curve from the
  // node's own parameter, never across to a closed edge's far end
  s.edge.assign(n, 0);
  auto edge = std::make_shared<std::vector<Index>>(n, -1);
  auto param = std::make_shared<std::vector<double>>(n, 0.0);
  for (std::size_t v = 0; v < n; ++v) {
    const pipeline::PointOn& on = grids.nodes.on[v];
    if (on.kind != pipeline::PointOn::kEdge || in.edges[on.id].degenerate || !in.edges[on.id].curve) continue;
    s.edge[v] = 1;
    (*edge)[v] = on.id, (*param)[v] = on.t;
  }
  s.along = [&in, edge, param](Index v, const Vec3& p, Vec3* tangent) -> Vec3 {
    const ParametricCurve& curve = *in.edges[(*edge)[v]].curve;
    const double was = (*param)[v], t = curve.closest_parameter(p, was);
    if (std::abs(t - was) > 0.25 * (curve.t_max() - curve.t_min())) return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
    if (tangent) *tangent = curve.derivative(t).normalized();
    return curve.point(t);
  };
  return s;
}

// After the optimisation: the (u, v) of every corner whose node slid in its face or along its
// edge, and such a node's edge parameter, from its new position (the order-2 mid-nodes are placed
// from them), the grids' own copy of it, and their smallest angle (degrees) as the moves left it.
void follow_slid_nodes(const BrepInput& in, const std::vector<Vec3>& before, pipeline::BrepPlacement* best) {
  double smallest = 180;
  for (pipeline::FacePiece& piece : best->grids.pieces) {
    for (const auto& t : piece.tris)
      smallest = std::min(smallest, triangle_min_angle_deg(best->X[t[0]], best->X[t[1]], best->X[t[2]]));
    const ParametricSurface& surf = *in.faces[piece.face].surface;
    for (std::size_t k = 0; k < piece.tris.size(); ++k)
      for (int i = 0; i < 3; ++i) {
        const Index v = piece.tris[k][i];
        if (static_cast<std::size_t>(v) >= before.size() || best->X[v] == before[v]) continue;
        piece.tri_uv[k][i] = surf.closest_point(best->X[v], piece.tri_uv[k][i]);
        best->grids.nodes.x[v] = best->X[v];
      }
  }
  for (std::size_t v = 0; v < before.size(); ++v) {
    pipeline::PointOn& on = best->grids.nodes.on[v];
    if (on.kind == pipeline::PointOn::kEdge && best->X[v] != before[v]) on.t = in.edges[on.id].curve->closest_parameter(best->X[v], on.t);
  }
  best->grids.min_angle_deg = smallest;
}

// The surface's edge flips and the moves after them: goes of both, and rounds within each.
constexpr int kSurfaceFlipGoes = 2;
constexpr int kSurfaceFlipRounds = 2;

// The global optimisation (7.5 over the whole mesh) and the output's assembly, checked: a
// tetrahedron inside out is a MeshingError naming the place, never a mesh.
TetMesh optimise_and_assemble(const BrepInput& in, const GenerateOptions& opt, pipeline::BrepPlacement* best, pipeline::FilledCells& filled,
                              GenerateStats* st, const std::function<bool(double)>& progress) {
  best->on_boundary.resize(best->X.size(), 0);  // helpers the cells kept are inside
  st->graded_nodes = best->graded_nodes;
  st->helper_nodes = filled.helper_nodes, st->helpers_removed = filled.helpers_removed;
  st->refilled_cells = filled.refilled, st->steiner_nodes = filled.steiner_nodes;
  st->skipped_nodes = filled.skipped_nodes, st->flips = filled.flips;
  // 7.5 over the whole mesh: only the B-rep faces (and the interfaces on them) hold
  const auto t_opt = Clock::now();
  tet::TetComplex cx(best->X);
  optimize::FilledMesh mesh{std::move(filled.tets), std::move(filled.region), {}, {}, {}};
  for (const pipeline::FacePiece& piece : best->grids.pieces)
    for (const auto& t : piece.tris) {
      mesh.held.insert(tet::face_key(t[0], t[1], t[2]));
      if (piece.cell_in < 0) mesh.surface_tag[tet::face_key(t[0], t[1], t[2])] = piece.face;
    }
  // nodes inside a B-rep face may move in it in the passes for the mean shape
  mesh.slides = face_slides(in, best->grids);
  mesh.surface_trades = true;
  const std::vector<Vec3> before(best->X.begin(), best->X.begin() + static_cast<std::ptrdiff_t>(mesh.slides.plane.size()));
  // the surface grid is the true surface's: it stays as meshed (no 2-2 transformation)
  OptimizeOptions oo = opt.optimize;
  oo.boundary_flips = false;
  std::function<bool(double)> optimize_progress;
  if (progress) optimize_progress = [&](double x) { return progress(kBar.filled + (kBar.optimized - kBar.filled) * x); };
  const optimize::OptimizeCounts oc =
      optimize::optimize_filled(cx, std::move(mesh), best->X, best->on_boundary, oo, optimize_progress, opt.threads);
  st->surface_moves = oc.surface_moves;
  // what node moves cannot mend, edge flips within the faces (brep_surface_flips.hpp), and the
  // surface angles' moves again round what they changed, while the flips find something
  if (oo.face_moves && oc.folds_left == 0)
    for (int go = 0; go < kSurfaceFlipGoes; ++go) {
      const std::int64_t flips = pipeline::flip_surface_edges(in, best->grids, cx, best->X, kSurfaceFlipRounds);
      st->surface_flips += flips;
      if (flips == 0) break;
      st->surface_moves += optimize::improve_surface_angles(cx, best->X, best->on_boundary, face_slides(in, best->grids), kSurfaceFlipRounds, true);
    }
  follow_slid_nodes(in, before, best);
  st->surface_min_angle = best->grids.min_angle_deg;
  st->facet_pieces = best->grids.facet_pieces;
  st->optimize_parts = oc.times;
  st->flips += oc.flips;
  st->sliver_moves = oc.sliver_moves;
  st->mean_changes = oc.mean_changes;
  st->refilled_folds = oc.refilled_folds;
  st->optimize_blocks = oc.blocks;
  st->optimize = since(t_opt);
  // the place, and the B-rep faces beside it (what a user can find in FreeCAD)
  const auto inside_out = [&](Index region, const Vec3& m, const std::set<Index>& faces) {
    return MeshingError(in.source + ": " + solid_name(in, region) + ": a tetrahedron at " + point_name(m) + beside_faces(faces) +
                        " came out inside out (a defect of the mesher)");
  };
  Vec3 fold;
  Index fold_region = 0;
  tet::Tet fold_nodes{};
  if (oc.folds_left > 0 && optimize::find_fold(cx, best->X, &fold, &fold_region, &fold_nodes)) {
    std::set<Index> faces;  // those the fold's nodes lie on (the grids' node ids are the complex's)
    for (const pipeline::FacePiece& piece : best->grids.pieces)
      for (const auto& t : piece.tris)
        for (Index v : t)
          if (std::find(fold_nodes.begin(), fold_nodes.end(), v) != fold_nodes.end()) faces.insert(piece.face);
    throw inside_out(fold_region, fold, faces);
  }
  if (progress && !progress(kBar.optimized)) throw Cancelled();
  util::ProgressPoll assembly_poll(progress);
  assembly_poll.at(kBar.optimized);
  return pipeline::assemble_brep_mesh(best->grids, cx, best->X, in, opt.order, &st->straightened_edges,
                                      [&assembly_poll] { return assembly_poll.cancelled(); });
}

}  // namespace

namespace pipeline {

TetMesh generate_connected_solids(const BrepInput& in, const GenerateOptions& opt, GenerateStats* stats) {
  const auto t_all = Clock::now();
  GenerateStats st;
  if (opt.order != 1 && opt.order != 2) throw InputError("element order " + std::to_string(opt.order) + ": give 1 (4-node) or 2 (10-node tetrahedra)");
  if (in.solids.empty()) throw InputError(in.source + ": the shape has no solid to mesh");
  if (opt.sizing.size <= 0 && opt.sizing.elements <= 0) throw InputError(in.source + ": give a number of elements or an element size");
  pipeline::check_solids_closed(in);
  double shown = 0;
  std::function<bool(double)> progress;
  if (opt.progress)
    progress = [&](double x) {
      shown = std::max(shown, x);
      return opt.progress(shown);
    };
  const double want = static_cast<double>(opt.sizing.elements);
  const double diag = (in.bbox_max - in.bbox_min).norm();
  size::BrepSizeReport sizes;
  pipeline::BrepPlacement best;
  pipeline::FilledCells filled;
  // A cell narrower than the true surface's bulge over the proxy's facets may not be star-shaped
  // even joined with its neighbours (brep_cells.hpp): the whole route then runs again on a finer
  // proxy, whose facets bulge less.
  const double first_angle = proxy_angle(opt.sizing);
  // The last resort (a cell's tetrahedra left inverted for the global optimisation's flips and
  // fold refill, brep_cells.hpp, optimize/inverted_refill.hpp) is allowed on every proxy: a
  // finer proxy has more cells, and more cut lines across the curved faces make worse surface
  // angles (sphere-in-box.brep at 1e5: 1,425 cells on the third proxy, surface angle 1.4 deg,
  // 0.21% of the tetrahedra under 10 deg, 14.6 s; 618 cells on the second with the last resort,
  // 3.8 deg, 0.02%, 6.2 s). A fold the refill cannot mend, or an order-2 element no straightening
  // makes positive, sends the route on to the next proxy too (corpus/Cone_1.brep at order 2
  // meshes so: its first proxy leaves a nearly flat tetrahedron at the apex).
  constexpr int kProxyAttempts = 3;  // the proxy's angle, a half and a third of it
  // When all three fail and the first proxy's linear deflection, not its angle, governed a curved
  // face (a B-spline face curved tighter than a twentieth of the shape's diagonal), one more at
  // the first angle and the deflection that keeps it there (decompose_brep's keep_angle). Only
  // then: made so from the start, corpus/x_ring.brep, whose second proxy meshes at 10.7 degrees,
  // came out at 3.6 on its first (728 cells instead of 356), and wrenchnut's three finer proxies
  // took 18 to 34 s each where the coarse ones took 3 (and still failed). A helical spring's
  // (a 3 mm wire round a helix of radius 15: its proxy at 4.9 mm held 62% of its volume) meshes
  // on it.
  bool keep_angle = false, angle_kept = true;
  // The walls' cap (size/wall_thickness.hpp) makes finer grids beside curved faces, which can
  // leave a cell that none of the fills above takes (FreeCAD's constraint_tie at 6,044); when
  // the first two proxies have failed with it, the attempts start again without it, so that the
  // cap improves a mesh and never costs one. Where no wall was found thin enough to cap anything,
  // that second round would only repeat the first; after a failure past the fill (a fold, an
  // order-2 element) it is not tried: the cap is not what folds (corpus/Zylkopf.brep at order 2
  // failed six times over, 176 s; now three, 185 s, as each costs a whole mesh: FreeCAD's
  // constraint_tie at 6,044, order 2, meshes only on its third proxy).
  bool use_walls = true, walls_found = false;
  // When every proxy has failed and one of them had facets flat in space (pipeline::make_proxy),
  // the attempts start once more on proxies without them. Round a drilled hole's conical point
  // (a box with a blind hole of radius 1.5 and a 118 degree point, split into half faces as STEP
  // files have them) they left a reflex edge at the apex that no plane resolved, at 24 and 48
  // curvature elements on every proxy; mended, the first meshes (24,550 tetrahedra, 10.1 degrees;
  // 46,575, 10.5). Only then, since corpus/Kurbelwelle.brep's first proxy fails so too and its
  // later ones mesh better as they are than its first mended (at 2*10^4: 45,032 tetrahedra and
  // 3.1 degrees against 64,878 and 2.0).
  bool mend_round = false, flat_seen = false;
  // What the last attempt's count search found (its spacing, and its filling's ratio of the count
  // to the prediction): a proxy made again finer has nearly the same nodes at a spacing, so the
  // next attempt's search starts there instead of where the first began (corpus/x_ring.brep at
  // 2*10^4, whose first proxy fails in the cell fill: 9 node placements instead of 10)
  double carried_np = 0, carried_scale = 1;
  // when every attempt fails, the first one's message: on the proxy the user's shape is tessellated
  // to, it names the B-rep faces where to look (a finer proxy can fail otherwise, in its own
  // numbering: corpus/Kurbelwelle.brep's third ends in the decomposition, naming proxy nodes)
  std::string first_error;
  TetMesh out;
  for (int attempt = 0;; ++attempt) {
    const double angle = first_angle / (1 + attempt);
    bool filled_cells = false;  // a failure after the fill: a fold or an order-2 element
    try {
    const auto t_dec = Clock::now();
    std::function<bool(double)> dec_progress;
    if (progress) dec_progress = [&](double x) { return progress(kBar.decomposed * x); };
    const Decomposed dc = decompose_brep(in, opt, angle, keep_angle, mend_round, flat_seen, dec_progress);
    if (!keep_angle && attempt == 0) angle_kept = dc.angle_kept;
    st.init_geom = dc.d.stats.prepare_seconds;
    st.bisect = since(t_dec) - st.init_geom;
    st.convex_cells = static_cast<std::int64_t>(dc.d.cells.size());
    st.face_corner_retry = dc.d.stats.face_corner_retry;
    st.regions = static_cast<std::int64_t>(in.solids.size());
    double volume = 0;
    for (const ConvexCell& c : dc.d.cells) volume += pipeline::cell_polytope(dc.d.model, c).volume();
    const double want = static_cast<double>(opt.sizing.elements);
    // The count (6.11): the spacing is searched on the count the nodes predict before any filling
    // (pipeline/count_calibration.hpp's rule: 6.2 tetrahedra per node inside, 2.65 per node on the
    // boundary), the cells are filled, and when the count still misses R by more than 10% the
    // filling's own ratio corrects the prediction and the search runs again (at most two fillings).
    // The first proxy's search starts at the spacing the volume and the faces' area predict
    // (count_calibration.hpp's expected_spacing: most searches at 10^5 and 10^6 then place their
    // nodes once), a later one's where the one before ended.
    double scale = carried_scale;
    double np = opt.sizing.size > 0 ? opt.sizing.size
                : carried_np > 0    ? carried_np
                                    : pipeline::expected_spacing(volume, tessellation_area(dc.proxy.tess), want, pipeline::kBrepNodes);
    // the walls' thickness, once per decomposition: up to four times the first spacing, room for
    // the count search's coarser rounds (kWallSizeFactor: elements no larger than a wall is thick)
    const std::vector<size::WallSample> walls =
        use_walls ? size::wall_thickness(in, dc.proxy.tess, 4 * np / size::kWallSizeFactor) : std::vector<size::WallSample>{};
    walls_found = walls_found || !walls.empty();
    size::SizeSamplingCache sampling;  // the geometry's samples, evaluated once for every round below
    double best_miss = 1e300;
    for (int filling = 0; filling < 2; ++filling) {
      pipeline::BrepPlacement placed;
      double placed_miss = 1e300, placed_np = np;
      // the search's steps (count_calibration.hpp), stopping within 5% of R, at a bracket under
      // 2% wide or at the floor (the curvature bound and the smallest features keep the count up)
      pipeline::CountSearch search(want, 0.05, diag);
      for (int round = 0; round < 6; ++round) {
        const auto t_nodes = Clock::now();
        // the search's rounds share the placement's part of the bar (most end within three)
        const auto placed_at = [&](double rounds) {
          return kBar.decomposed + (kBar.placed - kBar.decomposed) * std::min(1.0, rounds / 3);
        };
        util::ProgressPoll field_poll(progress);
        field_poll.at(placed_at(round));
        const size::SizeField h =
            size::brep_size_field(in, dc.proxy.tess, np, opt.sizing, &sizes, &walls, &sampling, [&] { return field_poll.cancelled(); });
        // walls, features or a maximum size under the spacing: bounded first (Angled.step with
        // --max-size 0.2 placed its nodes for 6 minutes before the bound refused 3.8e8 tetrahedra)
        const bool capped = h.base() < np;
        if (opt.max_elements > 0 && filling == 0 && round == 0 && (h.smallest() < h.base() || capped)) {
          char why[96];
          std::snprintf(why, sizeof why, "elements no larger than the maximum size %.3g", h.base());
          pipeline::check_element_bound(field_count(in, dc.d, h, dc.proxy.tess, opt.max_elements), opt, in.source,
                                        capped ? std::string(why) : element_bound_why(sizes), "the size field's samples over the cells");
        }
        std::function<bool(double)> place_progress;
        if (progress) place_progress = [&](double x) { return progress(placed_at(round + x)); };
        pipeline::BrepPlacement trial = pipeline::place_brep_nodes(in, dc.proxy, dc.d, h, opt.threads, place_progress);
        st.gen_nodes += since(t_nodes);
        ++st.placements;
        if (progress && !progress(placed_at(round + 1))) throw Cancelled();
        const double predicted = pipeline::predicted_tets(static_cast<double>(trial.inside_nodes()), static_cast<double>(trial.boundary_nodes()), scale);
        const double miss = std::abs(predicted - want);
        if (miss < placed_miss) placed_miss = miss, placed = std::move(trial), placed_np = np;
        if (opt.sizing.size > 0 || !search.step(np, predicted)) break;
        np = search.next();
      }
      np = placed_np;
      carried_np = np;
      if (opt.max_elements > 0) {  // refused before the filling, where the memory goes
        const double predicted = pipeline::predicted_tets(static_cast<double>(placed.inside_nodes()), static_cast<double>(placed.boundary_nodes()), scale);
        pipeline::check_element_bound(predicted, opt, in.source, element_bound_why(sizes));
      }
      const auto t_fill = Clock::now();
      std::function<bool(double)> fill_progress, jobs_progress;
      if (progress) {
        jobs_progress = [&](double x) { return progress(kBar.placed + (kBar.jobs - kBar.placed) * x); };
        fill_progress = [&](double x) { return progress(kBar.jobs + (kBar.filled - kBar.jobs) * x); };
      }
      std::vector<Vec3> X = placed.X;
      pipeline::BrepCellCounts cell_counts;
      util::ProgressPoll jobs_poll(jobs_progress);
      const std::vector<pipeline::CellJob> jobs =
          pipeline::brep_cell_jobs(in, dc.d, placed.grids, placed.X, placed.P, placed.cells, opt.delaunay_insertion,
                                   &cell_counts, [&jobs_poll](double x) {
                                     jobs_poll.at(x);
                                     return jobs_poll.cancelled();
                                   });
      pipeline::FilledCells cells = pipeline::fill_cell_jobs(X, jobs, opt.delaunay_insertion, opt.threads, fill_progress, &placed.P);
      st.gen_tets += since(t_fill);
      ++st.fillings;
      const double count = static_cast<double>(cells.tets.size());
      const double miss = std::abs(count - want);
      const double predicted_raw = pipeline::predicted_tets(static_cast<double>(placed.inside_nodes()), static_cast<double>(placed.boundary_nodes()));
      if (miss < best_miss) {
        best_miss = miss, filled = std::move(cells), st.spacing = np;
        best = std::move(placed);
        st.proxy_cells = cell_counts.in_proxy, st.joined_cells = cell_counts.joined;
        st.recovered_cells = cell_counts.recovered;
        best.X = std::move(X);
      }
      carried_scale = count / predicted_raw;
      if (opt.sizing.size > 0 || best_miss <= 0.1 * want) break;
      // above R at the floor: a second filling at a coarser base makes the same count again
      // (a 5 mm cylinder at a chord deviation of 3e-4 was filled twice, 45 s for 614k tetrahedra)
      if (search.at_floor() && count > want) break;
      scale = carried_scale;
      np *= std::cbrt(count / want);
      carried_np = np;
    }
    filled_cells = true;
    // the optimisation and the assembly inside the attempt: a fold the last resort left that its
    // refill cannot mend (optimize/inverted_refill.hpp) sends the route on to the next proxy
    out = optimise_and_assemble(in, opt, &best, filled, &st, progress);
    // no mesh leaves inside out, with a tetrahedron flat to round-off or with a face of three: a
    // stage's slip is an error naming the place (and the next proxy is tried), not a bad mesh;
    // checked once the complex is gone (the faces' table is 32 bytes a tetrahedron)
    pipeline::refuse_degenerate_tets(in, out);
      break;
    } catch (const MeshingError& e) {
      if (first_error.empty()) first_error = e.what();
      if (use_walls && walls_found && attempt >= 1 && !filled_cells && !keep_angle) use_walls = false, attempt = -1;
      else if (keep_angle || (attempt >= kProxyAttempts - 1 && angle_kept)) {
        if (mend_round || !flat_seen) throw MeshingError(first_error);
        mend_round = true, keep_angle = false, attempt = -1;
      }
      else if (attempt >= kProxyAttempts - 1) keep_angle = true, attempt = -1;
      const double total = st.total;
      const std::int64_t tried = st.proxy_attempts + 1, placements = st.placements;
      st = GenerateStats{};
      st.total = total, st.proxy_attempts = tried, st.placements = placements;
      best = {}, filled = {};
    }
  }
  if (progress && !progress(1.0)) throw Cancelled();
  if (opt.sizing.size <= 0 && static_cast<double>(out.num_tets()) > 1.2 * want) {
    // more than R asked: the thinnest walls, the smallest B-rep edges or the curvature bound set the floor (sizes
    // printed to 3 digits, at least the size field's own floor)
    st.count_floor = static_cast<std::int64_t>(out.num_tets());
    auto length = [](double x) {
      char text[32];
      std::snprintf(text, sizeof text, "%.3g", x);
      return std::string(text);
    };
    const double wall_size = size::kWallSizeFactor * sizes.thinnest_wall;
    auto finer = [](double a, double b) { return a > 0 && (b <= 0 || a < b); };  // a set, and below b (0: none)
    if (finer(wall_size, sizes.smallest_edge) && finer(wall_size, sizes.smallest_curvature_size))
      st.count_floor_reason = pipeline::walls_floor_reason(sizes.thinnest_wall);
    else if (finer(sizes.smallest_edge, sizes.smallest_curvature_size))
      st.count_floor_reason = "features: B-rep edges down to " + length(sizes.smallest_edge);
    else if (sizes.smallest_curvature_size > 0)
      st.count_floor_reason = "curvature: elements down to " + length(sizes.smallest_curvature_size) + " on curved faces";
    else  // neither bound asked for smaller elements: the count search itself came no nearer
      st.count_floor_reason = "calibration: the count search ended " +
                              std::to_string(std::lround(100 * (static_cast<double>(out.num_tets()) / want - 1))) + "% above R";
  }
  st.nodes = static_cast<std::int64_t>(out.nodes.size());
  st.tets = static_cast<std::int64_t>(out.num_tets());
  ++st.proxy_attempts;  // the one that meshed
  st.proxy_retry_reason = first_error;
  st.total = since(t_all);
  if (stats) *stats = st;
  return out;
}

}  // namespace pipeline
}  // namespace bisect
