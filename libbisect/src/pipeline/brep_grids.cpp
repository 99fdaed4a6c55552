#include "pipeline/brep_grids.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <string>

#include "bisect/errors.hpp"
#include "bisect/quality.hpp"
#include "pipeline/brep_piece_mesh.hpp"
#include "util/ordered_parallel.hpp"
#include "util/progress_poll.hpp"

namespace bisect::pipeline {
namespace {

struct CellSide {
  Index cell;
  bool outward;
};

int find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

BrepGrids mesh_brep_faces(BrepBoundary& bd, const Decomposition& d, const size::SizeField& h, int threads,
                          const std::function<bool(double)>& progress) {
  // Stop within a face: the meshers poll `cancelled`; on the calling thread it asks progress (at
  // most every 50 ms), elsewhere it reads the flag that answer sets; while the calling thread
  // waits for a face meshed elsewhere, ordered_parallel's idle asks progress.
  util::ParallelPoll poll(progress);
  const std::function<bool()> cancelled = poll.hook();
  const std::function<void()> idle = [&poll] { poll.idle(); };
  bd.discretise_edges(h, cancelled, threads);
  const PolyhedralModel& m = d.model;
  std::vector<std::vector<CellSide>> cells_of(m.faces.size());
  for (std::size_t c = 0; c < d.cells.size(); ++c)
    for (std::size_t k = 0; k < d.cells[c].faces.size(); ++k)
      cells_of[d.cells[c].faces[k]].push_back({static_cast<Index>(c), d.cells[c].outward[k] != 0});
  // face pieces: live model faces on B-rep faces, grouped by (B-rep face, cells) and joined
  // across model edges inside the B-rep face
  std::vector<int> parent(m.faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto key_of = [&](Index f) {
    std::array<Index, 3> k{m.faces[f].source >= 0 ? bd.px.face_brep[m.faces[f].source] : -1, -1, -1};
    for (const CellSide& s : cells_of[f]) (k[1] < 0 ? k[1] : k[2]) = s.cell;
    if (k[2] >= 0 && k[2] < k[1]) std::swap(k[1], k[2]);
    return k;
  };
  std::map<std::pair<Index, Index>, std::vector<Index>> faces_at_edge;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    if (!m.faces[f].alive || m.faces[f].source < 0) continue;
    for (const auto& loop : m.faces[f].loops)
      for (std::size_t i = 0; i < loop.size(); ++i)
        faces_at_edge[{std::min(loop[i], loop[(i + 1) % loop.size()]), std::max(loop[i], loop[(i + 1) % loop.size()])}].push_back(static_cast<Index>(f));
  }
  for (const auto& [e, fs] : faces_at_edge) {
    if (fs.size() < 2 || bd.edge_on(e.first, e.second).kind != PointOn::kFace) continue;
    for (std::size_t i = 1; i < fs.size(); ++i)
      if (key_of(fs[i]) == key_of(fs[0])) parent[find(parent, fs[i])] = find(parent, fs[0]);
  }
  std::map<int, std::size_t> job_of;
  std::vector<PieceJob> jobs;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    if (!m.faces[f].alive || m.faces[f].source < 0) continue;
    if (cells_of[f].empty()) continue;  // a face of a cavity's side only: no cell holds it
    const int root = find(parent, static_cast<int>(f));
    auto [it, fresh] = job_of.emplace(root, jobs.size());
    if (fresh) {
      const auto k = key_of(static_cast<Index>(f));
      PieceJob j;
      j.face = k[0], j.cell_out = k[1], j.cell_in = k[2];
      jobs.push_back(j);
    }
    PieceJob& j = jobs[it->second];
    bool out = true;
    for (const CellSide& s : cells_of[f])
      if (s.cell == j.cell_out) out = s.outward;
    j.faces.push_back({static_cast<Index>(f), !out});
  }
  std::vector<Index> cut_faces;
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    if (m.faces[f].alive && m.faces[f].source < 0) cut_faces.push_back(static_cast<Index>(f));
  CutFacesAt cuts_at;
  for (Index f : cut_faces)
    for (const auto& loop : m.faces[f].loops)
      for (std::size_t i = 0; i < loop.size(); ++i)
        cuts_at[{std::min(loop[i], loop[(i + 1) % loop.size()]), std::max(loop[i], loop[(i + 1) % loop.size()])}].push_back(f);
  for (PieceJob& j : jobs) j.cuts = &cuts_at;
  // the model edges each job's boundary uses
  auto job_edges = [&](std::size_t k) {
    std::vector<std::pair<Index, Index>> out;
    auto add = [&](Index f) {
      for (const auto& loop : m.faces[f].loops)
        for (std::size_t i = 0; i < loop.size(); ++i) out.push_back({std::min(loop[i], loop[(i + 1) % loop.size()]), std::max(loop[i], loop[(i + 1) % loop.size()])});
    };
    if (k < jobs.size())
      for (const auto& [f, rev] : jobs[k].faces) add(f);
    else
      add(cut_faces[k - jobs.size()]);
    return out;
  };
  const std::size_t n = jobs.size() + cut_faces.size();
  for (int round = 0;; ++round) {
    if (round > 0) bd.discretise_edges(h, cancelled, threads);
    BrepGrids g;
    g.nodes = bd.nodes;
    g.pieces.resize(jobs.size());
    g.cut_tris.assign(m.faces.size(), {});
    std::vector<Made> made(n);
    std::vector<std::size_t> failed;
    util::ordered_parallel(
        n, util::thread_count(threads),
        [&](std::size_t k) {
          try {
            made[k] = k < jobs.size() ? mesh_piece(bd, jobs[k], h, cancelled) : mesh_cut_face(bd, cut_faces[k - jobs.size()], h, cancelled);
          } catch (const MeshingError& e) {
            made[k].error = e.what();
          }
        },
        [&](std::size_t k) {
          poll.at(static_cast<double>(k + 1) / static_cast<double>(n));
          if (cancelled()) throw Cancelled();
          Made& mk = made[k];
          if (!mk.error.empty()) {
            failed.push_back(k);
            return;
          }
          std::size_t fresh = 0;
          for (Index& v : mk.global)
            if (v < 0) {
              g.nodes.x.push_back(mk.x[fresh]);
              g.nodes.p.push_back(mk.p[fresh]);
              g.nodes.on.push_back(mk.on[fresh]);
              ++fresh;
              v = static_cast<Index>(g.nodes.x.size() - 1);
            }
          std::vector<std::array<Index, 3>> tris;
          for (const auto& t : mk.tris) tris.push_back({mk.global[t[0]], mk.global[t[1]], mk.global[t[2]]});
          if (k < jobs.size()) {
            FacePiece& piece = g.pieces[k];
            piece.face = jobs[k].face, piece.cell_out = jobs[k].cell_out, piece.cell_in = jobs[k].cell_in;
            if (mk.on_facets) ++g.facet_pieces;
            for (std::size_t i = 0; i < tris.size(); ++i) {
              piece.tris.push_back(tris[i]);
              piece.tri_uv.push_back({mk.uv[mk.tris[i][0]], mk.uv[mk.tris[i][1]], mk.uv[mk.tris[i][2]]});
              const auto& t = tris[i];
              g.min_angle_deg = std::min(g.min_angle_deg, triangle_min_angle_deg(g.nodes.x[t[0]], g.nodes.x[t[1]], g.nodes.x[t[2]]));
            }
          } else {
            g.cut_tris[cut_faces[k - jobs.size()]] = std::move(tris);
          }
          if (!failed.empty()) return;
          mk = {};
        },
        {}, idle);
    if (failed.empty()) return g;
    if (round >= 2) throw MeshingError(made[failed.front()].error);
    // a finer boundary where the meshing failed, then every grid again (they share the edges)
    for (std::size_t k : failed)
      for (const auto& e : job_edges(k)) {
        int& f = bd.finer[e];
        f = std::max(f, 1) * 2;
      }
  }
}

}  // namespace bisect::pipeline
