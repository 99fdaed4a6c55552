#include "pipeline/brep_piece_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "bisect/errors.hpp"
#include "bisect/quality.hpp"
#include "domain/face_split.hpp"
#include "pipeline/piece_against_proxy.hpp"
#include "surface/analytic_surfaces.hpp"
#include "surface/region_mesher.hpp"

namespace bisect::pipeline {
namespace {

// The parameters on the piece's face of node g reached through proxy face `proxy` (the chart of
// that side of a seam): the surface's closest point to it, from the parameters interpolated in
// the proxy triangle.
Vec2 node_uv(const BrepBoundary& bd, const ParametricSurface& surf, Index g, Index proxy) {
  return surf.closest_point(bd.nodes.x[g], bd.uv_on_proxy(proxy, bd.nodes.p[g]));
}

// The directed boundary edges of a set of oriented faces chained into loops. An edge used both
// ways is inside the piece, unless it lies on a B-rep edge: that is a seam (a full cylinder's),
// the piece's boundary on both of its sides, one side in each chart. Where a node has several
// edges going on (a seam's ends, a pole, a pinch), the loop keeps the piece on its left: it takes
// the edge next clockwise from the one it came in by, seen against the normal of the proxy facet
// it came through (3D: at a pole or a seam the parameters say nothing about the turn).
struct DirEdge {
  Index a, b, proxy;
  Vec3 normal;  // the oriented normal of the model face it came from
  Vec2 ua, ub;  // the ends' parameters in the proxy face's chart
};
std::vector<std::vector<DirEdge>> chain_loops(const BrepBoundary& bd, const ParametricSurface& surf,
                                              const std::vector<std::pair<Index, bool>>& faces) {
  const PolyhedralModel& m = bd.model;
  std::map<std::pair<Index, Index>, DirEdge> edges;
  for (const auto& [f, rev] : faces)
    for (const auto& loop : m.faces[f].loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        Index a = loop[i], b = loop[(i + 1) % loop.size()];
        if (rev) std::swap(a, b);
        auto back = edges.find({b, a});
        if (back != edges.end() && bd.edge_on(a, b).kind != PointOn::kEdge) edges.erase(back);
        else edges[{a, b}] = {a, b, m.faces[f].source, rev ? Vec3(-m.faces[f].normal) : m.faces[f].normal, Vec2::Zero(), Vec2::Zero()};
      }
  std::multimap<Index, DirEdge> from;
  for (auto& [k, e] : edges) {
    e.ua = node_uv(bd, surf, e.a, e.proxy);
    e.ub = node_uv(bd, surf, e.b, e.proxy);
    from.emplace(e.a, e);
  }
  const auto& X = bd.nodes.x;
  // clockwise angle from direction r to direction d round normal n, in [0, 2 pi)
  auto clockwise = [](const Vec3& r, const Vec3& d, const Vec3& n) {
    const Vec3 e1 = (r - r.dot(n) * n).normalized(), e2 = n.cross(e1);
    const Vec3 q = d - d.dot(n) * n;
    double a = -std::atan2(q.dot(e2), q.dot(e1));
    if (a <= 0) a += 2 * M_PI;
    return a;
  };
  std::vector<std::vector<DirEdge>> loops;
  while (!from.empty()) {
    auto it = from.begin();
    std::vector<DirEdge> loop{it->second};
    from.erase(it);
    for (;;) {
      const DirEdge& last = loop.back();
      const DirEdge& first = loop.front();
      auto range = from.equal_range(last.b);
      const bool home = last.b == first.a;
      const std::size_t options = static_cast<std::size_t>(std::distance(range.first, range.second)) + (home ? 1 : 0);
      if (options == 0) throw MeshingError("a face piece's boundary does not close at model node " + std::to_string(last.b + 1));
      auto best = range.first;
      bool close = home && range.first == range.second;
      if (options > 1) {
        const Vec3 n = last.normal.normalized(), r = X[last.a] - X[last.b];
        double least = 1e300;
        // Going back the way it came (along the same model edge, a seam's other side) is the
        // last choice: its direction is the one it came by, which the clockwise angle would put
        // at 0 or at 2 pi by the sign of a round-off (a frustum's side chained as two loops, each
        // crossing the seam at a node on it, and was meshed on the facets' planes)
        auto turn = [&](const DirEdge& e) { return e.b == last.a ? 2 * M_PI : clockwise(r, X[e.b] - X[e.a], n); };
        if (home) least = turn(first), close = true;
        for (auto c = range.first; c != range.second; ++c) {
          const double ang = turn(c->second);
          if (ang < least) least = ang, best = c, close = false;
        }
      }
      if (close) break;
      loop.push_back(best->second);
      from.erase(best);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

// The loops of model face `face` (each reversed when `rev`) in the plane of `frame`, at the
// proxy's positions, as a region to mesh: local node k is model node global[k] (appended).
surface::RegionBoundary loops_in_plane(const BrepBoundary& bd, const ModelFace& face, bool rev, const PlaneFrame& frame,
                                       const surface::PlaneSurface& plane, std::vector<Index>& global) {
  surface::RegionBoundary rb;
  std::map<Index, Index> local;
  for (const auto& loop0 : face.loops) {
    std::vector<Index> loop = loop0;
    if (rev) std::reverse(loop.begin(), loop.end());
    std::vector<Index> lloop;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Index a = loop[i], b = loop[(i + 1) % loop.size()];
      std::vector<Index> seq{a};
      std::vector<Index> inner = bd.edge_nodes.at({std::min(a, b), std::max(a, b)});
      if (a > b) std::reverse(inner.begin(), inner.end());
      seq.insert(seq.end(), inner.begin(), inner.end());
      for (Index g : seq) {
        auto [it, fresh] = local.emplace(g, static_cast<Index>(global.size()));
        if (fresh) {
          global.push_back(g);
          const Vec2 q = frame.to2d(bd.nodes.p[g]);
          rb.uv.push_back(q);
          rb.xyz.push_back(plane.point(q));
        }
        lloop.push_back(it->second);
      }
    }
    rb.loops.push_back(std::move(lloop));
  }
  return rb;
}

// The last resort for a piece whose boundary is no simple polygon in any chart (a sliver between
// two cut lines meeting at a small angle, drawn by coarse chords): each of its model faces, a
// planar piece of one proxy facet, meshed in its plane and mapped onto the surface through the
// facet's parameters. Every node still lies on the face; the facets' edges show in the grid.
Made mesh_piece_on_facets(const BrepBoundary& bd, const PieceJob& job, const size::SizeField& h, const std::function<bool()>& cancelled) {
  const ParametricSurface& surf = *bd.in.faces[job.face].surface;
  Made out;
  std::map<Index, Index> local;
  for (const auto& [f, rev] : job.faces) {
    const ModelFace& face = bd.model.faces[f];
    const Index proxy = face.source;
    const Vec3 normal = rev ? Vec3(-face.normal) : face.normal;
    const PlaneFrame frame(normal, bd.nodes.p[face.loops[0][0]]);
    const surface::PlaneSurface plane(frame.origin, frame.e1, frame.e2);
    std::vector<Index> global;
    const surface::RegionBoundary rb = loops_in_plane(bd, face, rev, frame, plane, global);
    surface::RegionMeshOptions ro;
    ro.size = [&h](const Vec3& x) { return h.at(x); };
    ro.cancelled = cancelled;
    const surface::RegionMesh rm = surface::mesh_region(plane, rb, ro);
    // local ids of this piece's mesh: boundary nodes shared across the piece's faces
    std::vector<Index> id(rm.uv.size());
    for (std::size_t v = 0; v < rm.uv.size(); ++v) {
      if (v < global.size()) {
        auto [it, fresh] = local.emplace(global[v], static_cast<Index>(out.global.size()));
        if (fresh) {
          out.global.push_back(global[v]);
          out.uv.push_back(node_uv(bd, surf, global[v], proxy));
        }
        id[v] = it->second;
        continue;
      }
      const Vec2 uv = bd.uv_on_proxy(proxy, rm.xyz[v]);
      PointOn on;
      on.kind = PointOn::kFace, on.id = job.face, on.proxy = proxy;
      id[v] = static_cast<Index>(out.global.size());
      out.global.push_back(-1);
      out.uv.push_back(uv);
      out.x.push_back(surf.point(uv));
      out.p.push_back(rm.xyz[v]);
      out.on.push_back(on);
    }
    for (const auto& t : rm.tris) out.tris.push_back({id[t[0]], id[t[1]], id[t[2]]});
  }
  out.on_facets = true;
  return out;
}

}  // namespace

Made mesh_piece(const BrepBoundary& bd, const PieceJob& job, const size::SizeField& h, const std::function<bool()>& cancelled) {
  const BrepInput& in = bd.in;
  const ParametricSurface& surf = *in.faces[job.face].surface;
  const std::string where = face_name(job.face);
  std::vector<Index> poles;  // vertices of this face's degenerate edges: one 3D point, a uv segment
  for (const auto& wire : in.faces[job.face].wires)
    for (const BrepEdgeUse& u : wire)
      if (in.edges[u.edge].degenerate) poles.push_back(in.edges[u.edge].v0);
  Made out;
  surface::RegionBoundary rb;
  std::map<Index, Index> local;  // global node -> local (nodes seen once; poles get fresh ones)
  auto add_node = [&](Index g, const Vec2& uv) {
    out.global.push_back(g);
    out.uv.push_back(uv);
    rb.uv.push_back(uv);
    rb.xyz.push_back(bd.nodes.x[g]);
    return static_cast<Index>(out.global.size() - 1);
  };
  std::vector<std::pair<Index, bool>> faces = job.faces;
  const auto loops = chain_loops(bd, surf, faces);
  std::vector<std::vector<Index>> node_cuts;  // per local boundary node: the cut faces it lies on
  for (const auto& loop : loops) {
    // the loop's nodes in order with the proxy face each came through, and the cut faces each
    // lies on (a model node: those of the edges on both sides of it)
    std::vector<std::pair<Index, Index>> seq;  // (global node, proxy face)
    std::vector<std::vector<Index>> seq_cuts;
    auto cuts_of = [&](const DirEdge& e) {
      auto it = job.cuts->find({std::min(e.a, e.b), std::max(e.a, e.b)});
      return it == job.cuts->end() ? std::vector<Index>{} : it->second;
    };
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const DirEdge& e = loop[k];
      const std::vector<Index> here = cuts_of(e);
      std::vector<Index> at_a = cuts_of(loop[(k + loop.size() - 1) % loop.size()]);
      at_a.insert(at_a.end(), here.begin(), here.end());
      seq.push_back({e.a, e.proxy});
      seq_cuts.push_back(at_a);
      auto it = bd.edge_nodes.find({std::min(e.a, e.b), std::max(e.a, e.b)});
      if (it == bd.edge_nodes.end()) throw MeshingError(where + ": a model edge was not discretised");
      std::vector<Index> inner = it->second;
      if (e.a > e.b) std::reverse(inner.begin(), inner.end());
      for (Index v : inner) seq.push_back({v, e.proxy}), seq_cuts.push_back(here);
    }
    std::vector<Vec2> uv(seq.size());
    std::vector<char> pole(seq.size(), 0);
    for (std::size_t i = 0; i < seq.size(); ++i) {
      const auto [g, proxy] = seq[i];
      const PointOn& on = bd.nodes.on[g];
      uv[i] = node_uv(bd, surf, g, proxy);
      if (on.kind == PointOn::kVertex && std::find(poles.begin(), poles.end(), on.id) != poles.end()) {
        pole[i] = 1;
        uv[i] = bd.uv_on_proxy(proxy, bd.nodes.p[g]);
      }
    }
    std::vector<Index> lloop;
    auto take = [&](Index l, std::size_t i) {
      lloop.push_back(l);
      node_cuts.resize(out.global.size());
      node_cuts[l].insert(node_cuts[l].end(), seq_cuts[i].begin(), seq_cuts[i].end());
    };
    for (std::size_t i = 0; i < seq.size(); ++i) {
      const Index g = seq[i].first;
      if (pole[i]) {
        // the pole as a segment of the parameter plane: from the previous node's u to the next
        // one's, at the pole's v, in steps of a 32nd of the u range: the triangles round the
        // pole each take the copy nearest them in u, so that none spans round it and folds
        const Vec2 prev = uv[(i + seq.size() - 1) % seq.size()], next = uv[(i + 1) % seq.size()];
        const double range = surf.period_u() > 0 ? surf.period_u() : surf.uv_max().x() - surf.uv_min().x();
        const int steps = std::clamp(static_cast<int>(std::ceil(std::abs(next.x() - prev.x()) / (range / 32))), 1, 64);
        for (int k = 0; k <= steps; ++k) {
          const double u = prev.x() + (next.x() - prev.x()) * k / steps;
          if (k > 0 && u == prev.x()) break;
          take(add_node(g, Vec2(u, uv[i].y())), i);
        }
        continue;
      }
      auto it = local.find(g);
      if (it != local.end() && (rb.uv[it->second] - uv[i]).norm() <= 1e-12 * (1 + uv[i].norm())) {
        take(it->second, i);
        continue;
      }
      const Index l = add_node(g, uv[i]);
      local[g] = l;
      take(l, i);
    }
    rb.loops.push_back(std::move(lloop));
  }
  // outer loops counter-clockwise in (u, v): when the 3D direction maps to clockwise, all loops
  // are reversed for the mesher and its triangles reversed back
  double total = 0;
  for (const auto& l : rb.loops) total += loop_area2(l, [&rb](Index i) { return rb.uv[i]; });
  const bool flipped = total < 0;
  if (flipped)
    for (auto& l : rb.loops) std::reverse(l.begin(), l.end());
  surface::RegionMeshOptions ro;
  ro.size = [&h](const Vec3& x) { return h.at(x); };
  ro.cancelled = cancelled;
  surface::RegionMesh rm;
  // a piece at a pole is meshed over a plane: its (u, v) draws straight segments bent round the
  // pole; any piece whose (u, v) polygon the mesher cannot use gets the same second chance
  const bool at_pole = rb.uv.size() > local.size();
  // Two triangles on the same three nodes fold the grid onto itself: a piece round a cone's apex
  // (corpus Cone_1) is a disc in space but, meshed in (u, v), a strip between two copies of the
  // seam, and a triangle from each copy to the same two nodes across the strip is the same
  // triangle in space. Such a grid is not used either.
  auto checked = [&](surface::RegionMesh r) {
    std::set<std::array<Index, 3>> seen;
    for (const auto& t : r.tris) {
      std::array<Index, 3> key;
      for (int k = 0; k < 3; ++k) key[k] = t[k] < static_cast<Index>(out.global.size()) ? out.global[t[k]] : -1 - t[k];
      std::sort(key.begin(), key.end());
      if (!seen.insert(key).second) throw MeshingError("two of its triangles join the same three nodes (the grid folds onto itself)");
    }
    return r;
  };
  try {
    rm = checked(at_pole ? surface::mesh_region_projected(surf, rb, ro) : surface::mesh_region(surf, rb, ro));
  } catch (const MeshingError& first) {
    try {
      rm = checked(at_pole ? surface::mesh_region(surf, rb, ro) : surface::mesh_region_projected(surf, rb, ro));
    } catch (const MeshingError& second) {
      // in (u, v) once more, its boundary first triangulated in the surface's metric (a fold in
      // (u, v) where the parameters are far from proportional to length: corpus Cone_1,
      // Kurbelwelle, x_t20_data and the scaled sphere sent pieces to their facets so), then the
      // facets' planes
      surface::RegionMeshOptions again = ro;
      again.boundary_in_surface_metric = true;
      try {
        rm = checked(surface::mesh_region(surf, rb, again));
      } catch (const MeshingError&) {
        try {
          return mesh_piece_on_facets(bd, job, h, cancelled);
        } catch (const MeshingError&) {
          throw MeshingError(where + ": " + (at_pole ? second : first).what());
        }
      }
    }
  }
  mend_cut_ears(surf, rm, node_cuts, rb.uv.size());
  // the inner nodes: on the face; their proxy point is the same parameters' point on the proxy
  // triangle holding them (planar faces: the point itself), for the morph's samples; when no
  // triangle holds them, the nearest point of the piece's proxy faces (piece_against_proxy.hpp)
  std::vector<Index> proxy_tris;
  for (const auto& [f, rev] : faces)
    if (bd.px.face_tri[bd.model.faces[f].source] >= 0) proxy_tris.push_back(bd.model.faces[f].source);
  auto place = [&](const Vec2& uv, const Vec3& x, PointOn& on) {
    on.kind = PointOn::kFace, on.id = job.face;
    Vec3 at = x;
    double best = 1e300;
    for (Index s : proxy_tris) {
      const auto& tri = bd.px.tess.faces[job.face].tris[bd.px.face_tri[s]];
      const auto& tuv = bd.px.tess.faces[job.face].uv[bd.px.face_tri[s]];
      // barycentric in the parameter plane; the least negative weight picks the triangle
      const Vec2 e1 = tuv[1] - tuv[0], e2 = tuv[2] - tuv[0], q = uv - tuv[0];
      const double det = e1.x() * e2.y() - e1.y() * e2.x();
      if (std::abs(det) < 1e-300) continue;
      const double l1 = (q.x() * e2.y() - q.y() * e2.x()) / det, l2 = (e1.x() * q.y() - e1.y() * q.x()) / det, l0 = 1 - l1 - l2;
      const double outside = -std::min({l0, l1, l2, 0.0});
      if (outside < best) {
        best = outside, on.proxy = s;
        at = l0 * bd.model.nodes[tri[0]] + l1 * bd.model.nodes[tri[1]] + l2 * bd.model.nodes[tri[2]];
      }
    }
    if (best > 1e-9 && !proxy_tris.empty()) at = nearest_on_faces(bd.model, faces, x, &on.proxy);
    if (on.proxy < 0) on.proxy = faces.front().first >= 0 ? bd.model.faces[faces.front().first].source : -1;
    return at;
  };
  const std::size_t nb = rb.uv.size();
  std::vector<Vec3> p(rm.uv.size());
  std::vector<PointOn> on(rm.uv.size());
  for (std::size_t v = 0; v < rm.uv.size(); ++v) p[v] = v < nb ? bd.nodes.p[out.global[v]] : place(rm.uv[v], rm.xyz[v], on[v]);
  auto off_cut = [&](Index f, const Vec3& q) {
    const ModelFace& cut = bd.model.faces[f];
    return std::abs(cut.normal.dot(q - bd.model.nodes[cut.loops[0][0]]));
  };
  auto proxy_at = [&](const Vec2& uv, const Vec3& x) {
    PointOn unused;
    return place(uv, x, unused);
  };
  mend_cut_chords(surf, rm, node_cuts, nb, p, proxy_at, off_cut);
  for (std::size_t v = on.size(); v < rm.uv.size(); ++v) place(rm.uv[v], rm.xyz[v], on.emplace_back());
  for (std::size_t v = nb; v < rm.uv.size(); ++v) {
    out.global.push_back(-1);
    out.uv.push_back(rm.uv[v]);
    out.x.push_back(rm.xyz[v]);
    out.p.push_back(p[v]);
    out.on.push_back(on[v]);
  }
  // the triangles turn so that their normals point out of cell_out: judged in 3D against the
  // piece's proxy facets (oriented the same way), not by the sign of an area in (u, v), which a
  // tiny piece at a pole or across a seam can get wrong. On a curved face each facet is compared
  // with the surface's du x dv where it lies, and each triangle with du x dv where it lies: the
  // facets' normals summed cancel on a piece that runs all the way round (a cylinder's whole
  // side: its sum is nought, and a cylinder of radius 0.8 came out with its side inside out)
  double along = 0;  // the facets' outward normals against du x dv, weighted by area
  for (const auto& [f, rev] : faces) {
    const ModelFace& face = bd.model.faces[f];
    const Index k = bd.px.face_tri[face.source];
    if (k < 0) continue;
    const auto& tuv = bd.px.tess.faces[job.face].uv[k];
    Vec3 du, dv;
    surf.derivatives((tuv[0] + tuv[1] + tuv[2]) / 3, &du, &dv);
    const Vec3 n = du.cross(dv);
    if (n.norm() > 0) along += (rev ? -1.0 : 1.0) * bd.model.face_area(f) * face.normal.dot(n / n.norm());
  }
  double agree = 0;
  if (along != 0) {
    for (const auto& t : rm.tris) {
      Vec3 du, dv;
      surf.derivatives((rm.uv[t[0]] + rm.uv[t[1]] + rm.uv[t[2]]) / 3, &du, &dv);
      agree += (rm.xyz[t[1]] - rm.xyz[t[0]]).cross(rm.xyz[t[2]] - rm.xyz[t[0]]).dot(du.cross(dv)) * along;
    }
  } else {  // a planar face's pieces are polygons: their normals are the face's
    Vec3 facing = Vec3::Zero();
    for (const auto& [f, rev] : faces) {
      const ModelFace& face = bd.model.faces[f];
      facing += (rev ? -1.0 : 1.0) * bd.model.face_area(f) * face.normal;
    }
    for (const auto& t : rm.tris) agree += (rm.xyz[t[1]] - rm.xyz[t[0]]).cross(rm.xyz[t[2]] - rm.xyz[t[0]]).dot(facing);
  }
  out.tris = rm.tris;
  if (agree < 0)
    for (auto& t : out.tris) std::swap(t[1], t[2]);
  return out;
}

// A cut face meshed in its plane with the proxy's positions: counter-clockwise around its normal.
Made mesh_cut_face(const BrepBoundary& bd, Index fi, const size::SizeField& h, const std::function<bool()>& cancelled) {
  const ModelFace& f = bd.model.faces[fi];
  const PlaneFrame frame(f.normal, bd.nodes.p[f.loops[0][0]]);
  const surface::PlaneSurface plane(frame.origin, frame.e1, frame.e2);
  Made out;
  const surface::RegionBoundary rb = loops_in_plane(bd, f, false, frame, plane, out.global);
  out.uv = rb.uv;
  surface::RegionMeshOptions ro;
  ro.size = [&h](const Vec3& x) { return h.at(x); };
  ro.cancelled = cancelled;
  surface::RegionMesh rm;
  try {
    rm = surface::mesh_region(plane, rb, ro);
  } catch (const MeshingError& e) {
    throw MeshingError("cut face " + std::to_string(fi + 1) + " of the decomposition: " + e.what());
  }
  for (std::size_t v = rb.uv.size(); v < rm.uv.size(); ++v) {
    out.global.push_back(-1);
    out.uv.push_back(rm.uv[v]);
    out.x.push_back(rm.xyz[v]);  // moved by the morph later
    out.p.push_back(rm.xyz[v]);
    out.on.push_back(PointOn{});
  }
  out.tris = rm.tris;
  return out;
}

}  // namespace bisect::pipeline
