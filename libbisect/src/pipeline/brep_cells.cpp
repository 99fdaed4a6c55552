#include "pipeline/brep_cells.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <string>

#include "bisect/errors.hpp"
#include "tet/boundary_crossing.hpp"
#include "tet/cell_fill.hpp"

namespace bisect::pipeline {
namespace {

// A cell that neither its true nor its proxy geometry fills joins at most this many neighbours.
constexpr int kMaxJoins = 4;

struct Side {
  Index cell;
  bool outward;
};

// Drops the triangles that `boundary` holds both ways round: together they bound no volume (a cut
// face of one triangle whose three corners a face piece's grid also joins: the pocket of
// piece_against_proxy.hpp where the piece could not be mended). The cell beside the cut face
// keeps the triangle, as the mesh's boundary.
void drop_two_sided(std::vector<std::array<Index, 3>>& boundary) {
  std::map<std::array<Index, 3>, std::size_t> at;
  for (std::size_t i = 0; i < boundary.size(); ++i) at.emplace(tet::smallest_first(boundary[i]), i);
  std::vector<char> drop(boundary.size(), 0);
  bool any = false;
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    const auto& t = boundary[i];
    auto it = at.find(tet::smallest_first({t[0], t[2], t[1]}));
    if (it == at.end() || drop[i] || drop[it->second]) continue;
    drop[i] = drop[it->second] = 1, any = true;
  }
  if (!any) return;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < boundary.size(); ++i)
    if (!drop[i]) boundary[kept++] = boundary[i];
  boundary.resize(kept);
}

// Why no fill takes cell c, when its boundary crosses itself: which grids pass through each other,
// and where (the B-rep face of each triangle, or a cut face); empty when it does not.
std::string crossing_reason(const CellJob& job, const BrepGrids& g, Index c, const std::vector<Vec3>& X) {
  const std::optional<tet::BoundaryCrossing> x = tet::boundary_crossing(X, job.boundary);
  if (!x) return {};
  std::map<std::array<Index, 3>, Index> face_of;  // the cell's face pieces' triangles, nodes sorted
  for (const FacePiece& piece : g.pieces)
    if (piece.cell_out == c || piece.cell_in == c)
      for (auto t : piece.tris) {
        std::sort(t.begin(), t.end());
        face_of[t] = piece.face;
      }
  auto owner = [&](std::array<Index, 3> t) {
    std::sort(t.begin(), t.end());
    const auto it = face_of.find(t);
    return it == face_of.end() ? std::string("a cut face, a plane the solid was cut along,") : face_name(it->second);
  };
  return ": its boundary crosses itself once its grids lie on the true surfaces (an edge on " + owner(job.boundary[x->edge_triangle]) +
         " passes through a triangle on " + owner(job.boundary[x->crossed]) + " at " + point_name(x->at) +
         "), so no tetrahedra can fill it: the cell is thinner there than the curved face's bulge over the facets it was cut from";
}

}  // namespace

std::vector<CellJob> brep_cell_jobs(const BrepInput& in, const Decomposition& d, const BrepGrids& g, const std::vector<Vec3>& X,
                                    const std::vector<Vec3>& P, const std::vector<BrepCell>& cells, bool delaunay,
                                    BrepCellCounts* counts, const std::function<bool(double)>& cancelled) {
  const std::size_t n = d.cells.size();
  const PolyhedralModel& m = d.model;
  // per cell: its face pieces' triangles (outward) and its cut faces with their two sides
  std::vector<std::vector<std::array<Index, 3>>> piece_tris(n);
  std::vector<std::set<Index>> brep_faces(n);  // per cell: the B-rep faces it lies on, for messages
  for (const FacePiece& piece : g.pieces) {
    brep_faces[piece.cell_out].insert(piece.face);
    if (piece.cell_in >= 0) brep_faces[piece.cell_in].insert(piece.face);
    for (const auto& t : piece.tris) {
      piece_tris[piece.cell_out].push_back(t);
      if (piece.cell_in >= 0) piece_tris[piece.cell_in].push_back({t[0], t[2], t[1]});
    }
  }
  std::map<Index, std::vector<Side>> cut_sides;
  std::vector<std::vector<std::pair<Index, bool>>> cuts(n);
  for (std::size_t c = 0; c < n; ++c)
    for (std::size_t k = 0; k < d.cells[c].faces.size(); ++k) {
      const Index f = d.cells[c].faces[k];
      if (m.faces[f].source >= 0) continue;
      cuts[c].push_back({f, d.cells[c].outward[k] != 0});
      cut_sides[f].push_back({static_cast<Index>(c), d.cells[c].outward[k] != 0});
    }
  std::vector<Index> group(n);
  std::iota(group.begin(), group.end(), 0);
  std::vector<std::vector<Index>> members(n);
  for (std::size_t c = 0; c < n; ++c) members[c] = {static_cast<Index>(c)};
  // The job of a group of cells: the cut faces between two members are left out (their nodes
  // off the group's boundary go inside).
  auto job_of = [&](Index root) {
    const std::vector<Index>& mem = members[root];
    CellJob job;
    std::set<Index> inner_cuts;
    double volume = 0;
    Vec3 centre = Vec3::Zero();
    for (Index c : mem) {
      job.boundary.insert(job.boundary.end(), piece_tris[c].begin(), piece_tris[c].end());
      job.interior.insert(job.interior.end(), cells[c].interior.begin(), cells[c].interior.end());
      for (const auto& [f, out] : cuts[c]) {
        const auto& sides = cut_sides[f];
        if (sides.size() == 2 && group[sides[0].cell] == root && group[sides[1].cell] == root) {
          inner_cuts.insert(f);
          continue;
        }
        for (const auto& t : g.cut_tris[f]) job.boundary.push_back(out ? t : std::array<Index, 3>{t[0], t[2], t[1]});
      }
      centre += cells[c].volume * cells[c].centre, volume += cells[c].volume;
    }
    if (!inner_cuts.empty()) {
      std::set<Index> on_boundary;
      for (const auto& t : job.boundary) on_boundary.insert(t.begin(), t.end());
      std::set<Index> inside;
      for (Index f : inner_cuts)
        for (const auto& t : g.cut_tris[f])
          for (Index v : t)
            if (!on_boundary.count(v)) inside.insert(v);
      job.interior.insert(job.interior.end(), inside.begin(), inside.end());
    }
    drop_two_sided(job.boundary);
    job.centre = volume > 0 ? Vec3(centre / volume) : cells[root].centre;
    job.centre_p = cells[root].centre_p;
    job.region = d.cells[root].source_region;
    // where a user can look: the cell's centre and the B-rep faces it lies on (the cell's number
    // is the decomposition's, which no user sees)
    job.name = "convex cell " + std::to_string(root + 1) + " of " + solid_name(in, d.cells[root].source_region) + " at " +
               point_name(job.centre);
    std::set<Index> faces;
    for (Index c : mem) faces.insert(brep_faces[c].begin(), brep_faces[c].end());
    job.name += beside_faces(faces);
    if (mem.size() > 1) job.name += " (joined with " + std::to_string(mem.size() - 1) + " neighbour" + (mem.size() > 2 ? "s)" : ")");
    return job;
  };
  auto star = [&](const CellJob& job) {
    Index node;
    Vec3 point;
    return tet::star_centre(X, job.boundary, job.interior, job.centre, &node, &point);
  };
  *counts = {};
  std::vector<char> last_resort(n, 0);  // cells filled in the proxy keeping fixed inverted tetrahedra
  std::vector<char> recover(n, 0);      // cells filled by boundary recovery (2: with its second phase)
  for (std::size_t c = 0; c < n; ++c) {
    // the trial fillings below add up: Stop within them
    if (cancelled && cancelled(static_cast<double>(c) / static_cast<double>(n))) throw Cancelled();
    if (group[c] != static_cast<Index>(c)) continue;
    const std::vector<Index> group_before = group;
    const std::vector<std::vector<Index>> members_before = members;
    const std::int64_t joined_before = counts->joined;
    for (int joins = 0;; ++joins) {
      const Index root = group[c];
      CellJob job = job_of(root);
      if (star(job)) break;
      if (members[root].size() == 1) {
        // convex in the proxy: filled there and untangled, when the untangling succeeds
        job.in_proxy = true;
        if (fill_job_works(job, X, &P, delaunay)) break;
      }
      // the neighbour across the group's largest cut face to the outside
      Index best = -1;
      std::size_t most = 0;
      for (Index mc : members[root])
        for (const auto& [f, out] : cuts[mc])
          for (const Side& s : cut_sides[f])
            if (group[s.cell] != root && (best < 0 || g.cut_tris[f].size() > most)) most = g.cut_tris[f].size(), best = s.cell;
      if (joins >= kMaxJoins || best < 0) {
        // the joined cells by Delaunay boundary recovery: larger than the cell alone, their
        // boundary less often folds past the recovery's reach (corpus/x_ring.brep: a cell whose
        // neighbours' joined boundary recovered where its own did not)
        if (members[root].size() > 1) {
          CellJob joined = job;
          joined.recover = true;
          if (fill_job_works(joined, X, &P, delaunay)) {
            recover[c] = 1;
            break;
          }
        }
        // back to the cell alone for the last two ways
        const std::size_t joined_with = members[root].size() - 1;
        group = group_before, members = members_before, counts->joined = joined_before;
        // the cell alone, by Delaunay boundary recovery: no point need see it whole (its job made
        // once for the last three ways)
        const CellJob cell_alone = job_of(static_cast<Index>(c));
        CellJob recovered = cell_alone;
        recovered.recover = true;
        if (fill_job_works(recovered, X, &P, delaunay)) {
          recover[c] = 1;
          break;
        }
        // the last resort: the cell alone, filled in the proxy, what stays inverted left for the
        // global optimisation
        CellJob alone = cell_alone;
        alone.in_proxy = alone.keep_inverted = true;
        if (fill_job_works(alone, X, &P, delaunay)) {
          last_resort[c] = 1;
          break;
        }
        // after the last resort: boundary recovery with its second phase, flips that take the
        // tetrahedra out of a missing edge's way and points added inside (face_recovery.hpp);
        // after it, so that every cell the other fills take is filled as before
        CellJob more = cell_alone;
        more.recover = more.steiner = true;
        if (fill_job_works(more, X, &P, delaunay)) {
          recover[c] = 2;
          break;
        }
        // named alone: the group's name would give the centre and faces of the cells it was
        // joined with, tens of millimetres away (corpus/wrenchnut.brep: 22 mm)
        if (const std::string why = crossing_reason(more, g, static_cast<Index>(c), X); !why.empty()) throw MeshingError(alone.name + why);
        throw MeshingError(alone.name + ": no point sees its whole boundary" +
                             (joined_with > 0 ? ", even joined with " + std::to_string(joined_with) + " of its neighbours," : std::string()) +
                             " and it cannot be filled in the proxy's geometry either (the cell is narrower than the curved face's bulge "
                             "next to it)");
      }
      const Index other = group[best];
      for (Index k : members[other]) group[k] = root;
      members[root].insert(members[root].end(), members[other].begin(), members[other].end());
      members[other].clear();
      ++counts->joined;
    }
  }
  std::vector<CellJob> jobs;
  for (std::size_t c = 0; c < n; ++c) {
    if (group[c] != static_cast<Index>(c)) continue;
    jobs.push_back(job_of(static_cast<Index>(c)));
    if (recover[c]) {
      jobs.back().recover = true, jobs.back().steiner = recover[c] == 2;
      ++counts->recovered;
    } else if (members[c].size() == 1 && !star(jobs.back())) {
      jobs.back().in_proxy = true, jobs.back().keep_inverted = last_resort[c] != 0;
      ++counts->in_proxy;
    }
  }
  return jobs;
}

}  // namespace bisect::pipeline
