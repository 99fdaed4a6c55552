#include "mesh2d/face_grids.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>

#include "bisect/errors.hpp"
#include "mesh2d/fill_region.hpp"
#include "mesh2d/planar_failure.hpp"
#include "mesh2d/spacing.hpp"
#include "util/ordered_parallel.hpp"

namespace bisect::mesh2d {
namespace {

std::pair<Index, Index> edge_key(Index a, Index b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); }

// Which edges of the live faces are creases of the input: two of their faces lie on different
// input faces. The others were made by the cuts (on a cut face, or across an input face).
std::map<std::pair<Index, Index>, bool> input_creases(const PolyhedralModel& model) {
  std::map<std::pair<Index, Index>, Index> source;  // the first input face seen on the edge
  std::map<std::pair<Index, Index>, bool> crease;
  for (const ModelFace& f : model.faces) {
    if (!f.alive) continue;
    for (const auto& loop : f.loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const auto e = edge_key(loop[i], loop[(i + 1) % loop.size()]);
        bool& c = crease[e];
        if (f.source < 0 || c) continue;
        const auto [it, fresh] = source.emplace(e, f.source);
        c = !fresh && it->second != f.source;
      }
  }
  return crease;
}

// Every edge of the live faces discretised once: node spacings no larger than h (or the
// smallest spacing of the edge's faces, face_h), than the node's shortest edge, nor than the
// spacing the input asks of the node; inner nodes graded between them. An edge the cuts made
// asks for cut_edge_spacing instead of its length (spacing.hpp).
void discretise_edges(const PolyhedralModel& model, double h, const std::vector<double>& face_h, FaceGrids& g) {
  g.nodes = model.nodes;
  g.face_of.assign(g.nodes.size(), -1);
  g.spacing.assign(model.nodes.size(), h);
  for (std::size_t v = 0; v < model.node_spacing.size() && v < g.spacing.size(); ++v)
    if (model.node_spacing[v] > 0) g.spacing[v] = std::min(h, model.node_spacing[v]);
  g.edge_nodes.clear();
  const auto crease = input_creases(model);
  std::map<std::pair<Index, Index>, double> edge_h;  // per edge: the smallest of its faces' spacings
  for (std::size_t fi = 0; fi < model.faces.size(); ++fi) {
    const ModelFace& f = model.faces[fi];
    if (!f.alive) continue;
    for (const auto& loop : f.loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Index a = loop[i], b = loop[(i + 1) % loop.size()];
        double len = (model.nodes[a] - model.nodes[b]).norm();
        if (!crease.at(edge_key(a, b))) len = cut_edge_spacing(len, face_h[fi]);
        g.spacing[a] = std::min({g.spacing[a], len, face_h[fi]});
        g.spacing[b] = std::min({g.spacing[b], len, face_h[fi]});
        g.edge_nodes.emplace(edge_key(a, b), std::vector<Index>{});
        const auto [it, fresh] = edge_h.emplace(edge_key(a, b), face_h[fi]);
        if (!fresh) it->second = std::min(it->second, face_h[fi]);
      }
  }
  auto hint = [&](Index v) { return std::size_t(v) < model.node_spacing.size() ? model.node_spacing[v] : 0.0; };
  for (auto& [e, inner] : g.edge_nodes) {
    const Vec3 p = model.nodes[e.first], q = model.nodes[e.second];
    const double sa = g.spacing[e.first], sb = g.spacing[e.second];
    const double len = (q - p).norm();
    const double he = edge_h.at(e);
    // an edge whose both ends ask for a spacing keeps it all along (a curved face's ruling
    // strip stays as fine as its chords); other edges grow towards their faces' h in their middle
    const double cap = hint(e.first) > 0 && hint(e.second) > 0 ? std::min(he, std::max({hint(e.first), hint(e.second), sa, sb})) : he;
    for (double f : graded_edge_fractions(len, sa, sb, cap)) {
      g.nodes.push_back(p + (q - p) * f);
      g.spacing.push_back(edge_spacing_at(f * len, len, sa, sb, cap));
      g.face_of.push_back(-1);
      inner.push_back(static_cast<Index>(g.nodes.size() - 1));
    }
  }
}

double angle_at(const Vec3& a, const Vec3& b, const Vec3& c) {  // at a, degrees
  const Vec3 u = b - a, v = c - a;
  return std::atan2(u.cross(v).norm(), u.dot(v)) * 180 / M_PI;
}

// One face's grid before it joins g: the node of g behind each local node (the loops' nodes;
// -1 for the interior nodes the fill made), the interior nodes in 3D, the triangles in local ids.
struct FaceGrid {
  std::vector<Index> global;
  std::vector<Vec3> inner;
  std::vector<std::array<Index, 3>> tris;
};

// One face: its loops in the plane frame with the shared edge nodes, filled and optimised.
// Reads the model and edge nodes (`nodes`, a copy: g.nodes grows as faces are committed) and
// g's edge nodes, writes nothing shared: faces run in parallel.
FaceGrid mesh_face(const PolyhedralModel& model, Index fi, double h, bool optimize, bool nodes_only, const std::vector<Vec3>& nodes,
                   const FaceGrids& g) {
  const ModelFace& f = model.faces[fi];
  const PlaneFrame frame(f.normal, model.nodes[f.loops[0][0]]);
  TriMesh2 m;
  FaceGrid out;
  std::unordered_map<Index, Index> local;
  auto add = [&](Index v) {
    auto [it, fresh] = local.emplace(v, static_cast<Index>(out.global.size()));
    if (fresh) {
      out.global.push_back(v);
      m.nodes.push_back(frame.to2d(nodes[v]));
    }
    return it->second;
  };
  std::vector<std::vector<Index>> loops;
  for (const auto& loop : f.loops) {
    loops.emplace_back();
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Index a = loop[i], b = loop[(i + 1) % loop.size()];
      loops.back().push_back(add(a));
      std::vector<Index> inner = g.edge_nodes.at(edge_key(a, b));
      if (a > b) std::reverse(inner.begin(), inner.end());
      for (Index v : inner) loops.back().push_back(add(v));
    }
  }
  const std::size_t boundary = m.nodes.size();
  try {
    fill_region(m, loops, h, std::sqrt(3.0) / 4 * h * h, 0, nullptr, !nodes_only);
  } catch (const PlanarFailure& e) {
    const Vec3 at = frame.origin + e.where.x() * frame.e1 + e.where.y() * frame.e2;
    std::ostringstream where;
    where.precision(9);
    where << ", near (" << at.x() << ", " << at.y() << ", " << at.z() << ")";
    throw MeshingError("face grid of model face " + std::to_string(fi + 1) + (f.source >= 0 ? " (input face " + std::to_string(f.source + 1) + ")" : " (a cut face)") + ": " + e.what() + where.str());
  } catch (const MeshingError& e) {
    throw MeshingError("face grid of model face " + std::to_string(fi + 1) + (f.source >= 0 ? " (input face " + std::to_string(f.source + 1) + ")" : " (a cut face)") + ": " + e.what());
  }
  m.fixed.assign(m.nodes.size(), 0);
  std::fill(m.fixed.begin(), m.fixed.begin() + static_cast<std::ptrdiff_t>(boundary), 1);
  if (optimize && !nodes_only) optimize_planar(m);
  for (std::size_t v = boundary; v < m.nodes.size(); ++v) {
    out.inner.push_back(frame.origin + m.nodes[v].x() * frame.e1 + m.nodes[v].y() * frame.e2);
    out.global.push_back(-1);
  }
  out.tris = std::move(m.tris);
  return out;
}

// The face's interior nodes numbered after those of g, its triangles added.
void commit_face(Index fi, double h, FaceGrid& fg, FaceGrids& g) {
  std::size_t k = 0;
  for (Index& v : fg.global)
    if (v < 0) {
      g.nodes.push_back(fg.inner[k++]);
      g.spacing.push_back(h);
      g.face_of.push_back(fi);
      v = static_cast<Index>(g.nodes.size() - 1);
    }
  auto& out = g.face_tris[fi];
  for (const auto& t : fg.tris) out.push_back({fg.global[t[0]], fg.global[t[1]], fg.global[t[2]]});
}

FaceGrids mesh_once(const PolyhedralModel& model, double h, const FaceGridOptions& opt) {
  FaceGrids g;
  g.h = h;
  std::vector<double> face_h(model.faces.size(), h);  // each face's own spacing
  for (std::size_t fi = 0; fi < face_h.size() && fi < opt.face_size.size(); ++fi)
    if (opt.face_size[fi] > 0) face_h[fi] = std::min(h, opt.face_size[fi]);
  discretise_edges(model, h, face_h, g);
  g.face_tris.assign(model.faces.size(), {});
  std::vector<Index> live;
  for (std::size_t fi = 0; fi < model.faces.size(); ++fi)
    if (model.faces[fi].alive) live.push_back(static_cast<Index>(fi));
  std::vector<FaceGrid> made(live.size());
  const std::vector<Vec3> edge_and_model_nodes = g.nodes;
  util::ordered_parallel(
      live.size(), util::thread_count(opt.threads),
      [&](std::size_t k) { made[k] = mesh_face(model, live[k], face_h[live[k]], opt.optimize, opt.nodes_only, edge_and_model_nodes, g); },
      [&](std::size_t k) {
        commit_face(live[k], face_h[live[k]], made[k], g);
        made[k] = {};
        g.triangles += static_cast<std::int64_t>(g.face_tris[live[k]].size());
        if (opt.progress && !opt.progress(static_cast<double>(k + 1) / static_cast<double>(live.size()))) throw Cancelled();
      });
  g.min_angle_deg = 180, g.max_angle_deg = 0;
  for (const auto& tris : g.face_tris)
    for (const auto& t : tris)
      for (int k = 0; k < 3; ++k) {
        const double a = angle_at(g.nodes[t[k]], g.nodes[t[(k + 1) % 3]], g.nodes[t[(k + 2) % 3]]);
        g.min_angle_deg = std::min(g.min_angle_deg, a), g.max_angle_deg = std::max(g.max_angle_deg, a);
      }
  return g;
}

}  // namespace

FaceGrids mesh_faces(const PolyhedralModel& model, const FaceGridOptions& opt) {
  if (opt.size > 0) return mesh_once(model, opt.size, opt);
  if (opt.elements <= 0) throw InputError(model.source + ": face grids need a number of triangles or a spacing");
  double area = 0;
  for (std::size_t fi = 0; fi < model.faces.size(); ++fi)
    if (model.faces[fi].alive) area += model.face_area(static_cast<Index>(fi));
  double h = element_spacing(area, opt.elements);
  FaceGrids g = mesh_once(model, h, opt);
  // the count goes with 1 / h^2, but short edges add triangles of their own: a few corrections,
  // keeping the closest count (as the planar mesher does)
  for (int round = 0; round < 3; ++round) {
    const double ratio = static_cast<double>(g.triangles) / static_cast<double>(opt.elements);
    if (std::abs(ratio - 1) <= 0.05) break;
    h *= std::sqrt(ratio);
    FaceGrids again = mesh_once(model, h, opt);
    if (std::abs(again.triangles - opt.elements) < std::abs(g.triangles - opt.elements)) g = std::move(again);
  }
  return g;
}

}  // namespace bisect::mesh2d
