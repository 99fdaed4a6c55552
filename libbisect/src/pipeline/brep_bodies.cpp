// Separate bodies of a B-rep: solids that share no face (an assembly's parts in one compound,
// touching or apart) are meshed group by group, each group of solids joined by shared faces as
// one conforming mesh (brep_generate.cpp), the count shared by volume, the meshes joined with
// no node in common, as the CAD has no face in common.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "bisect/errors.hpp"
#include "bisect/generate.hpp"
#include "domain/mesh_like_faces.hpp"
#include "pipeline/brep_bodies.hpp"

namespace bisect {

// (brep_input.hpp) also read by libbisect/occ's check for overlapping bodies
std::vector<std::vector<Index>> connected_solids(const BrepInput& in) {
  const Index n = static_cast<Index>(in.solids.size());
  std::vector<Index> parent(n);
  for (Index s = 0; s < n; ++s) parent[s] = s;
  auto root = [&](Index s) {
    while (parent[s] != s) s = parent[s] = parent[parent[s]];
    return s;
  };
  std::vector<Index> face_solid(in.faces.size(), -1);
  for (Index s = 0; s < n; ++s)
    for (Index f : in.solids[s].faces) {
      if (face_solid[f] < 0) face_solid[f] = s;
      else parent[root(s)] = root(face_solid[f]);
    }
  std::vector<std::vector<Index>> groups;
  std::vector<Index> group_of(n, -1);
  for (Index s = 0; s < n; ++s) {
    Index& g = group_of[root(s)];
    if (g < 0) g = static_cast<Index>(groups.size()), groups.emplace_back();
    groups[g].push_back(s);
  }
  return groups;
}

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// `in` restricted to the solids `group` (their FreeCAD numbers kept, every face, edge and vertex
// keeping its own), with the local sizes that name those solids renumbered.
BrepInput solids_part(const BrepInput& in, const std::vector<Index>& group, SizeOptions* sizing) {
  BrepInput sub = in;
  sub.solids.clear();
  std::vector<Index> local(in.solids.size(), -1);
  bool boxed = true;
  for (Index s : group) {
    local[s] = static_cast<Index>(sub.solids.size());
    BrepSolid solid = in.solids[s];
    solid.number = in.solids[s].number >= 0 ? in.solids[s].number : s;
    boxed = boxed && (solid.bbox_max - solid.bbox_min).norm() > 0;
    if (sub.solids.empty()) sub.bbox_min = solid.bbox_min, sub.bbox_max = solid.bbox_max;
    sub.bbox_min = sub.bbox_min.cwiseMin(solid.bbox_min), sub.bbox_max = sub.bbox_max.cwiseMax(solid.bbox_max);
    sub.solids.push_back(std::move(solid));
  }
  if (!boxed) sub.bbox_min = in.bbox_min, sub.bbox_max = in.bbox_max;
  for (SizeRegion& r : sizing->regions) {
    std::vector<Index> kept;
    for (Index s : r.solids)
      if (s >= 0 && s < static_cast<Index>(local.size()) && local[s] >= 0) kept.push_back(local[s]);
    r.solids = std::move(kept);
  }
  return sub;
}

// Appends `part` (its regions already FreeCAD's solid numbers) to `all`.
void append_mesh(TetMesh& all, const TetMesh& part) {
  const Index base = static_cast<Index>(all.nodes.size());
  all.order = part.order;
  all.nodes.insert(all.nodes.end(), part.nodes.begin(), part.nodes.end());
  for (Index v : part.tets) all.tets.push_back(v + base);
  all.region.insert(all.region.end(), part.region.begin(), part.region.end());
  for (Index v : part.tris) all.tris.push_back(v + base);
  all.tri_tag.insert(all.tri_tag.end(), part.tri_tag.begin(), part.tri_tag.end());
}

// generate_connected_solids, its failures naming the input first (a cell's failure names the cell and
// its solid only).
TetMesh generate_named(const BrepInput& in, const GenerateOptions& opt, GenerateStats* stats) {
  try {
    return pipeline::generate_connected_solids(in, opt, stats);
  } catch (const MeshingError& e) {
    const std::string what = e.what();
    if (in.source.empty() || what.rfind(in.source + ":", 0) == 0) throw;
    throw MeshingError(in.source + ": " + what);
  }
}

// The solids of `in`, each group of connected solids meshed on its own.
TetMesh generate_bodies(const BrepInput& in, const GenerateOptions& opt, GenerateStats* stats) {
  const std::vector<std::vector<Index>> groups = connected_solids(in);
  if (groups.size() <= 1) return generate_named(in, opt, stats);
  // Solids that share no face (a compound of parts that touch, or lie apart) are separate bodies:
  // each group is meshed on its own, with the count shared by volume, so that one body's
  // surface never has to be told from another's where they touch. Their meshes meet at most
  // at points and lines, not conformingly, as in the CAD.
  const auto t_all = Clock::now();
  double volume = 0;
  std::vector<double> group_volume(groups.size(), 0);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    for (Index s : groups[g]) group_volume[g] += in.solids[s].volume;
    volume += group_volume[g];
  }
  TetMesh all;
  GenerateStats total;
  double done = 0;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    GenerateOptions part_opt = opt;
    const double share = volume > 0 ? group_volume[g] / volume : 1.0 / static_cast<double>(groups.size());
    const BrepInput sub = solids_part(in, groups[g], &part_opt.sizing);
    if (opt.sizing.size <= 0)
      part_opt.sizing.elements = std::max<std::int64_t>(1, std::llround(share * static_cast<double>(opt.sizing.elements)));
    if (opt.progress) {
      const double from = done;
      part_opt.progress = [&opt, from, share](double x) { return opt.progress(from + share * x); };
    }
    GenerateStats st;
    TetMesh part = generate_named(sub, part_opt, &st);
    for (Index& r : part.region) r = sub.solids[r].number;
    append_mesh(all, part);
    done += share;
    total.convex_cells += st.convex_cells, total.helper_nodes += st.helper_nodes, total.helpers_removed += st.helpers_removed;
    total.skipped_nodes += st.skipped_nodes, total.flips += st.flips, total.sliver_moves += st.sliver_moves;
    total.surface_moves += st.surface_moves, total.surface_flips += st.surface_flips, total.facet_pieces += st.facet_pieces;
    total.mean_changes += st.mean_changes;
    total.fillings += st.fillings, total.graded_nodes += st.graded_nodes, total.straightened_edges += st.straightened_edges;
    total.proxy_cells += st.proxy_cells, total.joined_cells += st.joined_cells, total.recovered_cells += st.recovered_cells;
    total.steiner_nodes += st.steiner_nodes;
    total.refilled_cells += st.refilled_cells, total.refilled_folds += st.refilled_folds;
    total.surface_min_angle = g == 0 ? st.surface_min_angle : std::min(total.surface_min_angle, st.surface_min_angle);
    total.spacing = std::max(total.spacing, st.spacing);
    total.init_geom += st.init_geom, total.bisect += st.bisect, total.gen_nodes += st.gen_nodes;
    total.gen_tets += st.gen_tets, total.optimize += st.optimize;
    if (st.count_floor > 0 && total.count_floor_reason.empty()) total.count_floor_reason = st.count_floor_reason;
    total.proxy_attempts = std::max(total.proxy_attempts, st.proxy_attempts);  // the most any body needed
    total.placements += st.placements;
    if (total.proxy_retry_reason.empty()) total.proxy_retry_reason = st.proxy_retry_reason;
    total.face_corner_retry = total.face_corner_retry || st.face_corner_retry;
  }
  total.regions = static_cast<std::int64_t>(in.solids.size());
  total.nodes = static_cast<std::int64_t>(all.nodes.size());
  total.tets = static_cast<std::int64_t>(all.num_tets());
  if (opt.sizing.size <= 0 && static_cast<double>(total.tets) > 1.2 * static_cast<double>(opt.sizing.elements)) {
    total.count_floor = total.tets;
    if (total.count_floor_reason.empty()) total.count_floor_reason = "bodies: " + std::to_string(groups.size()) + " separate groups of solids";
  } else {
    total.count_floor_reason.clear();
  }
  total.total = since(t_all);
  if (stats) *stats = total;
  return all;
}

}  // namespace

TetMesh generate_brep_mesh(const BrepInput& in, const GenerateOptions& opt, GenerateStats* stats) {
  // a shape made from a mesh (domain/mesh_like_faces.hpp): said in the stats, and added to a
  // refusal, where it may be the cause
  const domain::MeshLikeFaces like = domain::mesh_like_faces(in);
  const std::string hint = domain::mesh_like_hint(like);
  try {
    TetMesh m = generate_bodies(in, opt, stats);
    if (stats) stats->coplanar_triangles = like.triangles, stats->coplanar_hint = hint;
    return m;
  } catch (const MeshingError& e) {
    if (hint.empty()) throw;
    throw MeshingError(std::string(e.what()) + " (" + hint + ")");
  }
}

}  // namespace bisect
