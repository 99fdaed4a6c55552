#include "bisect/section.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "bisect/errors.hpp"
#include "domain/face_split.hpp"

namespace bisect {
namespace {

// The angle at which the section turns clockwise from the way back; the traced loop keeps the
// section on its left.
int next_piece(const Section& s, const std::vector<std::vector<int>>& outs, int piece) {
  const Piece& in = s.pieces[piece];
  const auto& cand = outs[in.to];
  if (cand.empty()) return -1;
  const Vec2 v = s.pts[in.to].q;
  const Vec2 back = s.pts[in.from].q - v;
  const double back_angle = std::atan2(back.y(), back.x());
  int best = -1;
  double best_turn = 0;
  for (int k : cand) {
    const Vec2 d = s.pts[s.pieces[k].to].q - v;
    double turn = back_angle - std::atan2(d.y(), d.x());
    while (turn <= 1e-14) turn += 2 * M_PI;
    if (best < 0 || turn < best_turn) best = k, best_turn = turn;
  }
  return best;
}

}  // namespace

bool face_splits_cleanly(const PolyhedralModel& m, Index f, const std::vector<std::array<Index, 2>>& chords,
                         const std::function<Index(Index, Index)>& new_point, const std::function<Vec3(Index)>& pos) {
  const ModelFace& face = m.faces[f];
  std::vector<std::vector<Index>> loops;
  for (const auto& loop : face.loops) {
    loops.emplace_back();
    for (std::size_t i = 0; i < loop.size(); ++i) {
      loops.back().push_back(loop[i]);
      if (const Index p = new_point(loop[i], loop[(i + 1) % loop.size()])) loops.back().push_back(p);
    }
  }
  const PlaneFrame ff(face.normal, m.nodes[face.loops[0][0]]);
  try {
    for (const auto& piece : split_polygon_by_chords(loops, chords, [&](Index v) { return ff.to2d(pos(v)); }))
      for (const auto& loop : piece) {
        std::vector<Index> sorted = loop;
        std::sort(sorted.begin(), sorted.end());
        if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;
      }
  } catch (const MeshingError&) {
    return false;
  }
  return true;
}

namespace {

// Each node's shortest edge among the faces' loops (an edge shared by two faces measured twice).
template <class Table>
void shortest_edges(const PolyhedralModel& m, const std::vector<Index>& faces, Table& info) {
  for (Index f : faces)
    for (const auto& loop : m.faces[f].loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Index a = loop[i], b = loop[(i + 1) % loop.size()];
        const double len = (m.nodes[a] - m.nodes[b]).norm();
        info[a].min_len = std::min(info[a].min_len, len);
        info[b].min_len = std::min(info[b].min_len, len);
      }
}

}  // namespace

RegionSnapshot region_snapshot(const PolyhedralModel& m, Index r) {
  RegionSnapshot s;
  s.edges = region_edges(m, r);
  s.faces = m.live_faces(r);
  s.slot.assign(m.nodes.size(), -1);
  NodeTable info(m.nodes.size());  // the first-use order and shortest edges, as a section's own
  shortest_edges(m, s.faces, info);
  for (const auto& e : info) {
    s.slot[e.first] = static_cast<int>(s.nodes.size());
    s.nodes.push_back(e);
  }
  s.face_start.push_back(0);
  for (Index f : s.faces) {
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (const auto& loop : m.faces[f].loops)
      for (Index v : loop) {
        s.face_entry.push_back(s.slot[v]);
        lo = lo.cwiseMin(m.nodes[v]), hi = hi.cwiseMax(m.nodes[v]);
      }
    s.face_start.push_back(static_cast<int>(s.face_entry.size()));
    const Vec3 c = 0.5 * (lo + hi);
    double radius = 0;
    for (const auto& loop : m.faces[f].loops)
      for (Index v : loop) radius = std::max(radius, (m.nodes[v] - c).norm());
    s.face_centre.push_back(c);
    s.face_radius.push_back(radius);
  }
  s.edge_keys.reserve(s.edges.size());
  std::vector<int> count(s.nodes.size() + 1, 0);
  bool every_node = true;
  for (const auto& kv : s.edges) {
    const Index a = key_lo(kv.first), b = key_hi(kv.first);
    s.edge_keys.push_back(kv.first);
    s.edge_length_sum += (m.nodes[a] - m.nodes[b]).norm();
    const bool known = static_cast<std::size_t>(b) < s.slot.size() && a >= 0 && s.slot[a] >= 0 && s.slot[b] >= 0;
    every_node = every_node && known;
    if (known) ++count[s.slot[a] + 1], ++count[s.slot[b] + 1];
  }
  if (every_node) {
    for (std::size_t k = 1; k < count.size(); ++k) count[k] += count[k - 1];
    s.edge_start = count;
    s.edge_at.resize(static_cast<std::size_t>(count.back()));
    for (std::size_t e = 0; e < s.edge_keys.size(); ++e)
      for (const Index v : {key_lo(s.edge_keys[e]), key_hi(s.edge_keys[e])}) s.edge_at[count[s.slot[v]]++] = static_cast<int>(e);
  }
  return s;
}

SectionResult build_section(const PolyhedralModel& m, Index r, const CutPlane& pl, bool whole_plane,
                            const DecomposeOptions& opt, const RegionSnapshot* snap) {
  SectionResult res(m, pl, snap);
  auto fail = [&](const char* why) {
    res.reject = why;
    return std::move(res);
  };
  const double min_angle = opt.min_angle_deg * M_PI / 180.0;
  const double min_corner = opt.min_face_corner_deg * M_PI / 180.0;
  // The smallest angle that a chord leaving P in direction d makes with the edges of face f at P
  // (the edge P lies on, or the two edges at the vertex P is). Not on a facet of a curved surface
  // (curved_faces): the true face runs on across its edges, and the grid only sees cut lines there.
  auto chord_corner = [&](Index f, const SectionPoint& P, const Vec3& d) {
    const Index s = m.faces[f].source;
    if (s != kCutFace && static_cast<std::size_t>(s) < opt.curved_faces.size() && opt.curved_faces[s]) return M_PI;
    auto angle = [&](const Vec3& e) { return std::acos(std::clamp(d.dot(e) / (d.norm() * e.norm()), -1.0, 1.0)); };
    if (P.vertex < 0) {
      const double a = angle(m.nodes[P.eb] - m.nodes[P.ea]);
      return std::min(a, M_PI - a);
    }
    double best = M_PI;
    for (const auto& loop : m.faces[f].loops)
      for (std::size_t i = 0; i < loop.size(); ++i)
        if (loop[i] == P.vertex)
          for (const Index w : {loop[(i + 1) % loop.size()], loop[(i + loop.size() - 1) % loop.size()]})
            best = std::min(best, angle(m.nodes[w] - P.p));
    return best;
  };
  const double tol_on = 1e-10 * m.size;  // keeps cut faces planar to well within 1e-9
  std::vector<Index> own_faces;
  if (!snap) own_faces = m.live_faces(r);
  const std::vector<Index>& F = snap ? snap->faces : own_faces;
  auto& info = res.info;
  auto& near = res.near;
  Section& sec = res.sec;
  auto& loops = res.loops;
  auto& loop2d = res.loop2d;
  auto& loop_of = res.loop_of;
  auto& poly_of = res.poly_of;
  auto& polys = res.polys;
  // 1. Nodes: distance, side, shortest incident edge (the snapshot's, else measured here); nodes
  // too near the plane.
  if (!snap) shortest_edges(m, F, info);
  int entry = 0;
  for (auto& [v, I] : info) {
    I.d = pl.n.dot(m.nodes[v]) - pl.c;
    I.side = std::abs(I.d) <= tol_on ? 0 : (I.d > 0 ? 1 : -1);
    if (I.side != 0 && std::abs(I.d) < opt.near_vertex_rel * I.min_len) near.push_back(v);
    if (I.side == 0) res.on_plane.push_back(entry);
    ++entry;
  }
  res.measured = entry;
  if (whole_plane && !near.empty()) return fail("near_vertex");
  // a face whose sphere the plane misses by more than this has every node strictly on one side
  const double sphere_margin = tol_on + 1e-9 * m.size, n_norm = pl.n.norm();

  // 2. Chords: where the plane crosses a face, the inside intervals of the face's line.
  for (std::size_t fi = 0; fi < F.size(); ++fi) {
    const Index f = F[fi];
    const ModelFace& face = m.faces[f];
    bool pos = false, neg = false;
    if (snap) {
      if (std::abs(pl.n.dot(snap->face_centre[fi]) - pl.c) > snap->face_radius[fi] * n_norm + sphere_margin) continue;
      for (int k = snap->face_start[fi]; k < snap->face_start[fi + 1]; ++k) {
        const int side = info.entry(snap->face_entry[k]).side;
        pos |= side > 0, neg |= side < 0;
      }
    } else {
      for (const auto& loop : face.loops)
        for (Index v : loop) pos |= info[v].side > 0, neg |= info[v].side < 0;
    }
    if (!pos || !neg) continue;
    const Vec3 line = pl.n.cross(face.normal);
    const char* face_flaw = std::asin(std::min(1.0, line.norm())) < min_angle ? "acute_angle" : nullptr;
    const Vec3 ldir = line.normalized();
    std::vector<int> bp;
    std::unordered_set<std::uint64_t> on_edges;
    for (const auto& loop : face.loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Index a = loop[i], b = loop[(i + 1) % loop.size()];
        const NodeInfo &A = info[a], &B = info[b];
        if (A.side == 0) bp.push_back(sec.vertex_point(a));
        if (A.side * B.side < 0) bp.push_back(sec.edge_point(a, b, A.d, B.d));
        if (A.side == 0 && B.side == 0) on_edges.insert(edge_key(a, b));
      }
    std::sort(bp.begin(), bp.end(), [&](int x, int y) { return sec.pts[x].p.dot(ldir) < sec.pts[y].p.dot(ldir); });
    bp.erase(std::unique(bp.begin(), bp.end()), bp.end());
    const PlaneFrame ff(face.normal, m.nodes[face.loops[0][0]]);
    std::vector<std::vector<Vec2>> l2;
    for (const auto& loop : face.loops) {
      l2.emplace_back();
      for (Index v : loop) l2.back().push_back(ff.to2d(m.nodes[v]));
    }
    const int side = m.side_of(f, r);
    // New edges are measured against the face's own shortest edge: a chord across a sliver of a
    // tessellation is as short as the sliver, which is no new defect.
    double face_min = 1e300;
    for (const auto& loop : face.loops)
      for (std::size_t i = 0; i < loop.size(); ++i)
        face_min = std::min(face_min, (m.nodes[loop[i]] - m.nodes[loop[(i + 1) % loop.size()]]).norm());
    for (std::size_t i = 0; i + 1 < bp.size(); ++i) {
      const SectionPoint &P = sec.pts[bp[i]], &Q = sec.pts[bp[i + 1]];
      if (P.vertex >= 0 && Q.vertex >= 0 && on_edges.count(edge_key(P.vertex, Q.vertex))) continue;
      if (!point_in_loops(ff.to2d(0.5 * (P.p + Q.p)), l2)) continue;
      const char* flaw = face_flaw ? face_flaw : ((P.p - Q.p).norm() < opt.short_edge_rel * face_min ? "short_edge" : nullptr);
      if (!flaw && min_corner > 0 && (chord_corner(f, P, Q.p - P.p) < min_corner || chord_corner(f, Q, P.p - Q.p) < min_corner))
        flaw = "acute_face_corner";
      for (int s = 0; s < 2; ++s) {
        if (side != 2 && side != s) continue;
        const Vec3 inward = s == 0 ? face.normal : Vec3(-face.normal);
        const bool forward = pl.n.cross(Q.p - P.p).dot(inward) > 0;
        sec.pieces.push_back({forward ? bp[i] : bp[i + 1], forward ? bp[i + 1] : bp[i], f, flaw});
      }
    }
  }

  // 3. Existing edges on the plane where the plane runs into the region.
  RegionEdges own_edges;
  if (!snap) own_edges = region_edges(m, r);
  const RegionEdges& edges = snap ? snap->edges : own_edges;
  const auto along_edge = [&](std::uint64_t key, const std::vector<FaceUse>& uses) {
    const Index a = key_lo(key), b = key_hi(key);
    const EdgeFrame ef(m.nodes[a], m.nodes[b]);
    const Vec3 t = pl.n.cross(ef.d);
    if (t.norm() < 0.5) return;  // numerically the edge is not in the plane
    const std::vector<Wedge> wedges = interior_wedges(m, r, a, b, uses);
    int interior = 0;
    std::vector<std::pair<Vec3, const char*>> dirs;
    for (const Vec3& u : {Vec3(t.normalized()), Vec3(-t.normalized())}) {
      const double alpha = ef.angle_of(u);
      for (const Wedge& w : wedges) {
        double rel = alpha - w.start;
        while (rel < 0) rel += 2 * M_PI;
        while (rel >= 2 * M_PI) rel -= 2 * M_PI;
        const double to_end = w.angle - rel;
        if (rel <= 1e-7 || to_end <= 1e-7) continue;  // along a face: not inside
        const char* flaw = std::min(rel, to_end) < min_angle ? "acute_angle" : nullptr;
        dirs.push_back({u, flaw});
        ++interior;
        break;
      }
    }
    for (const auto& [u, flaw] : dirs) {
      const bool forward = pl.n.cross(m.nodes[b] - m.nodes[a]).dot(u) > 0;
      const int pa = sec.vertex_point(a), pb = sec.vertex_point(b);
      sec.pieces.push_back({forward ? pa : pb, forward ? pb : pa, -1, interior == 2 ? "edge_inside_cut" : flaw});
    }
  };
  if (snap && !snap->edge_start.empty()) {
    // the edges with both nodes on the plane, from the nodes there, in the table's order
    std::vector<int> in_plane;
    for (const int k : res.on_plane) {
      if (static_cast<std::size_t>(k) + 1 >= snap->edge_start.size()) continue;  // not a node of the region
      const Index v = info.node(k);
      for (int i = snap->edge_start[k]; i < snap->edge_start[k + 1]; ++i) {
        const std::uint64_t key = snap->edge_keys[snap->edge_at[i]];
        if (key_lo(key) == v && info[key_hi(key)].side == 0) in_plane.push_back(snap->edge_at[i]);
      }
    }
    std::sort(in_plane.begin(), in_plane.end());
    for (const int e : in_plane) {
      const std::uint64_t key = snap->edge_keys[e];
      along_edge(key, edges.at(key));
    }
  } else {
    for (const auto& [key, uses] : edges) {
      if (info[key_lo(key)].side != 0 || info[key_hi(key)].side != 0) continue;
      along_edge(key, uses);
    }
  }
  if (sec.pieces.empty()) return fail("not_interior");

  // 4. Loops, then polygons: outer loops (counter-clockwise, A3 sum +2 pi) with their holes.
  std::vector<std::vector<int>> outs(sec.pts.size());
  for (std::size_t k = 0; k < sec.pieces.size(); ++k) outs[sec.pieces[k].from].push_back(static_cast<int>(k));
  loop_of.assign(sec.pieces.size(), -1);
  for (std::size_t start = 0; start < sec.pieces.size(); ++start) {
    if (loop_of[start] >= 0) continue;
    const int id = static_cast<int>(loops.size());
    loops.emplace_back();
    int k = static_cast<int>(start);
    while (loop_of[k] < 0) {
      loop_of[k] = id;
      loops.back().push_back(k);
      k = next_piece(sec, outs, k);
      if (k < 0) return fail("open_section");
    }
    if (k != static_cast<int>(start)) return fail("open_section");
    // A loop through the same point twice would make a face that is not a simple polygon.
    std::vector<int> at;
    for (int piece : loops.back()) at.push_back(sec.pieces[piece].from);
    std::sort(at.begin(), at.end());
    if (std::adjacent_find(at.begin(), at.end()) != at.end()) return fail("pinched_section");
  }
  loop2d.resize(loops.size());
  std::vector<char> is_outer(loops.size());
  for (std::size_t l = 0; l < loops.size(); ++l) {
    for (int k : loops[l]) loop2d[l].push_back(sec.pts[sec.pieces[k].from].q);
    if (loop2d[l].size() < 3) return fail("degenerate_section");
    is_outer[l] = turning_angle_sum(loop2d[l]) > 0;
  }
  auto area = [&](std::size_t l) {
    double a = 0;
    const auto& p = loop2d[l];
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec2 &u = p[i], &v = p[(i + 1) % p.size()];
      a += u.x() * v.y() - u.y() * v.x();
    }
    return 0.5 * a;
  };
  poly_of.assign(loops.size(), -1);
  for (std::size_t l = 0; l < loops.size(); ++l)
    if (is_outer[l]) poly_of[l] = static_cast<int>(polys.size()), polys.push_back({static_cast<int>(l)});
  for (std::size_t l = 0; l < loops.size(); ++l) {
    if (is_outer[l]) continue;
    const Vec2 a = loop2d[l][0], b = loop2d[l][1], d = b - a;
    const Vec2 probe = 0.5 * (a + b) + 1e-7 * Vec2(-d.y(), d.x());
    int best = -1;
    for (std::size_t p = 0; p < polys.size(); ++p) {
      const int o = polys[p][0];
      if (!point_in_loops(probe, {loop2d[o]})) continue;
      if (best < 0 || area(o) < area(polys[best][0])) best = static_cast<int>(p);
    }
    if (best < 0) return fail("open_section");
    poly_of[l] = best;
    polys[best].push_back(static_cast<int>(l));
  }

  return res;
}

}  // namespace bisect
