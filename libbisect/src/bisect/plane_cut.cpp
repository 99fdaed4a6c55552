#include "bisect/plane_cut.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include "bisect/edge_wedges.hpp"
#include "bisect/region_split.hpp"
#include "bisect/errors.hpp"
#include "domain/face_split.hpp"

namespace bisect {
namespace {

struct NodeInfo {
  double d = 0;        // signed distance to the plane
  int side = 0;        // -1, 0 (on), +1
  double min_len = 1e300;  // shortest edge at the node
};

struct SectionPoint {
  Index vertex = -1;   // a node on the plane, or
  Index ea = -1, eb = -1;  // the edge the plane crosses (ea < eb)
  Vec3 p;
  Vec2 q;              // in the plane's frame
};

struct Piece {
  int from, to;
  Index face;          // the face it crosses (a chord), or -1 along an existing edge
  const char* flaw;    // why this piece is unacceptable, or nullptr
};

class Section {
 public:
  Section(const PolyhedralModel& m, const CutPlane& pl) : m_(m), frame_(pl.n, pl.n * pl.c) {}
  std::vector<SectionPoint> pts;
  std::vector<Piece> pieces;

  int vertex_point(Index v) { return point(edge_key(v, v), [&] { return SectionPoint{v, -1, -1, m_.nodes[v], {}}; }); }
  int edge_point(Index a, Index b, double da, double db) {
    if (a > b) std::swap(a, b), std::swap(da, db);
    return point(edge_key(a, b), [&] {
      const double t = da / (da - db);
      return SectionPoint{-1, a, b, m_.nodes[a] + t * (m_.nodes[b] - m_.nodes[a]), {}};
    });
  }
  const PlaneFrame& frame() const { return frame_; }

 private:
  template <class Make>
  int point(std::uint64_t key, Make make) {
    auto it = index_.find(key);
    if (it != index_.end()) return it->second;
    SectionPoint sp = make();
    sp.q = frame_.to2d(sp.p);
    pts.push_back(sp);
    return index_[key] = static_cast<int>(pts.size() - 1);
  }
  const PolyhedralModel& m_;
  PlaneFrame frame_;
  std::unordered_map<std::uint64_t, int> index_;
};

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

CutOutcome cut_region(PolyhedralModel& m, Index r, const CutPlane& pl, Index ea, Index eb, bool whole_plane,
                      const DecomposeOptions& opt) {
  CutOutcome out;
  auto reject = [&](const char* why) {
    out.reason = why;
    return out;
  };
  const double min_angle = opt.min_angle_deg * M_PI / 180.0;
  const double tol_on = 1e-9 * m.size;
  const std::vector<Index> F = m.live_faces(r);

  // 1. Nodes: distance, side, shortest incident edge; nodes too near the plane.
  std::unordered_map<Index, NodeInfo> info;
  for (Index f : F)
    for (const auto& loop : m.faces[f].loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Index a = loop[i], b = loop[(i + 1) % loop.size()];
        const double len = (m.nodes[a] - m.nodes[b]).norm();
        info[a].min_len = std::min(info[a].min_len, len);
        info[b].min_len = std::min(info[b].min_len, len);
      }
  std::vector<Index> near;
  for (auto& [v, I] : info) {
    I.d = pl.n.dot(m.nodes[v]) - pl.c;
    I.side = std::abs(I.d) <= tol_on ? 0 : (I.d > 0 ? 1 : -1);
    if (I.side != 0 && std::abs(I.d) < opt.near_vertex_rel * I.min_len) near.push_back(v);
  }
  if (whole_plane && !near.empty()) return reject("near_vertex");

  Section sec(m, pl);
  // 2. Chords: where the plane crosses a face, the inside intervals of the face's line.
  for (Index f : F) {
    const ModelFace& face = m.faces[f];
    bool pos = false, neg = false;
    for (const auto& loop : face.loops)
      for (Index v : loop) pos |= info[v].side > 0, neg |= info[v].side < 0;
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
      for (int s = 0; s < 2; ++s) {
        if (side != 2 && side != s) continue;
        const Vec3 inward = s == 0 ? face.normal : Vec3(-face.normal);
        const bool forward = pl.n.cross(Q.p - P.p).dot(inward) > 0;
        sec.pieces.push_back({forward ? bp[i] : bp[i + 1], forward ? bp[i + 1] : bp[i], f, flaw});
      }
    }
  }

  // 3. Existing edges on the plane where the plane runs into the region.
  const RegionEdges edges = region_edges(m, r);
  for (const auto& [key, uses] : edges) {
    const Index a = key_lo(key), b = key_hi(key);
    if (info[a].side != 0 || info[b].side != 0) continue;
    const EdgeFrame ef(m.nodes[a], m.nodes[b]);
    const Vec3 t = pl.n.cross(ef.d);
    if (t.norm() < 0.5) continue;  // numerically the edge is not in the plane
    const std::vector<Wedge> wedges = interior_wedges(m, r, a, b, uses);
    int interior = 0;
    std::vector<std::pair<Vec3, const char*>> dirs;
    for (const Vec3 u : {Vec3(t.normalized()), Vec3(-t.normalized())}) {
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
  }
  if (sec.pieces.empty()) return reject("not_interior");

  // 4. Loops, then polygons: outer loops (counter-clockwise, A3 sum +2 pi) with their holes.
  std::vector<std::vector<int>> outs(sec.pts.size());
  for (std::size_t k = 0; k < sec.pieces.size(); ++k) outs[sec.pieces[k].from].push_back(static_cast<int>(k));
  std::vector<int> loop_of(sec.pieces.size(), -1);
  std::vector<std::vector<int>> loops;  // piece ids
  for (std::size_t start = 0; start < sec.pieces.size(); ++start) {
    if (loop_of[start] >= 0) continue;
    const int id = static_cast<int>(loops.size());
    loops.emplace_back();
    int k = static_cast<int>(start);
    while (loop_of[k] < 0) {
      loop_of[k] = id;
      loops.back().push_back(k);
      k = next_piece(sec, outs, k);
      if (k < 0) return reject("open_section");
    }
    if (k != static_cast<int>(start)) return reject("open_section");
    // A loop through the same point twice would make a face that is not a simple polygon.
    std::vector<int> at;
    for (int piece : loops.back()) at.push_back(sec.pieces[piece].from);
    std::sort(at.begin(), at.end());
    if (std::adjacent_find(at.begin(), at.end()) != at.end()) return reject("pinched_section");
  }
  std::vector<std::vector<Vec2>> loop2d(loops.size());
  std::vector<char> is_outer(loops.size());
  for (std::size_t l = 0; l < loops.size(); ++l) {
    for (int k : loops[l]) loop2d[l].push_back(sec.pts[sec.pieces[k].from].q);
    if (loop2d[l].size() < 3) return reject("degenerate_section");
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
  std::vector<int> poly_of(loops.size(), -1);
  std::vector<std::vector<int>> polys;  // loop ids, outer first
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
    if (best < 0) return reject("open_section");
    poly_of[l] = best;
    polys[best].push_back(static_cast<int>(l));
  }

  // 5. Which polygons to insert.
  std::vector<int> chosen;
  if (whole_plane) {
    chosen.resize(polys.size());
    std::iota(chosen.begin(), chosen.end(), 0);
  } else {
    for (std::size_t k = 0; k < sec.pieces.size() && chosen.empty(); ++k) {
      const Piece& p = sec.pieces[k];
      const Index va = sec.pts[p.from].vertex, vb = sec.pts[p.to].vertex;
      if (p.face < 0 && ((va == ea && vb == eb) || (va == eb && vb == ea))) chosen.push_back(poly_of[loop_of[k]]);
    }
    if (chosen.empty()) return reject("not_interior");
  }

  // 6. Checks on the chosen polygons, before anything changes.
  std::vector<char> point_used(sec.pts.size(), 0);
  for (int p : chosen)
    for (int l : polys[p]) {
      const auto& lp = loops[l];
      const std::size_t n = lp.size();
      for (std::size_t i = 0; i < n; ++i) {
        const Piece& pc = sec.pieces[lp[i]];
        if (pc.flaw) return reject(pc.flaw);
        point_used[pc.from] = 1;
        const Vec2 d0 = sec.pts[pc.to].q - sec.pts[pc.from].q;
        const Vec2 d1 = sec.pts[sec.pieces[lp[(i + 1) % n]].to].q - sec.pts[pc.to].q;
        const double turn = std::atan2(d0.x() * d1.y() - d0.y() * d1.x(), d0.dot(d1));
        if (M_PI - turn < min_angle) return reject("acute_angle");  // a sharp corner of the cut
      }
    }
  for (int p : chosen) {
    std::vector<std::vector<Vec2>> pl2;
    Vec2 lo = Vec2::Constant(1e300), hi = Vec2::Constant(-1e300);
    for (int l : polys[p]) {
      pl2.push_back(loop2d[l]);
      for (const Vec2& q : loop2d[l]) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
    }
    for (Index v : near) {  // a vertex almost on the cut polygon would leave a short edge
      const Vec2 q = sec.frame().to2d(m.nodes[v]);
      const double margin = opt.near_vertex_rel * info[v].min_len;
      if (q.x() > lo.x() - margin && q.x() < hi.x() + margin && q.y() > lo.y() - margin && q.y() < hi.y() + margin)
        return reject("near_vertex");
    }
    for (const auto& [v, I] : info) {  // a vertex in the polygon's interior: the cut would touch it
      if (I.side != 0) continue;
      const int pv = sec.vertex_point(v);
      if (pv < static_cast<int>(point_used.size()) && point_used[pv]) continue;
      if (point_in_loops(sec.frame().to2d(m.nodes[v]), pl2)) return reject("touches_vertex");
    }
  }

  // 7. Dry run of the face splits on provisional vertex ids (new points are -(id + 2)): a face
  // that would not split into simple polygons (a chord bridging a hole on one side only, say)
  // rejects the plane while the model is still untouched.
  auto prov = [&](int pt) { return sec.pts[pt].vertex >= 0 ? sec.pts[pt].vertex : -(pt + 2); };
  std::unordered_map<std::uint64_t, int> crossing;
  for (std::size_t i = 0; i < sec.pts.size(); ++i)
    if (point_used[i] && sec.pts[i].vertex < 0) crossing[edge_key(sec.pts[i].ea, sec.pts[i].eb)] = static_cast<int>(i);
  std::unordered_map<Index, std::vector<std::array<Index, 2>>> chords;  // provisional ids
  for (int p : chosen)
    for (int l : polys[p])
      for (int k : loops[l]) {
        const Piece& pc = sec.pieces[k];
        if (pc.face < 0) continue;
        std::array<Index, 2> c{prov(pc.from), prov(pc.to)};
        if (c[0] > c[1]) std::swap(c[0], c[1]);
        auto& list = chords[pc.face];
        if (std::find(list.begin(), list.end(), c) == list.end()) list.push_back(c);
      }
  for (const auto& [f, list] : chords) {
    const ModelFace& face = m.faces[f];
    std::vector<std::vector<Index>> loops_with_points;
    for (const auto& loop : face.loops) {
      loops_with_points.emplace_back();
      for (std::size_t i = 0; i < loop.size(); ++i) {
        loops_with_points.back().push_back(loop[i]);
        auto it = crossing.find(edge_key(loop[i], loop[(i + 1) % loop.size()]));
        if (it != crossing.end()) loops_with_points.back().push_back(prov(it->second));
      }
    }
    const PlaneFrame ff(face.normal, m.nodes[face.loops[0][0]]);
    auto pos = [&](Index v) { return ff.to2d(v >= 0 ? m.nodes[v] : sec.pts[-v - 2].p); };
    try {
      for (const auto& piece : split_polygon_by_chords(loops_with_points, list, pos))
        for (const auto& loop : piece) {
          std::vector<Index> sorted = loop;
          std::sort(sorted.begin(), sorted.end());
          if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return reject("pinched_face");
        }
    } catch (const MeshingError&) {
      return reject("pinched_face");
    }
  }

  // 8. Insert: vertices into edges, chords into faces, polygons into the region.
  std::vector<Index> vert(sec.pts.size(), -1);
  for (std::size_t i = 0; i < sec.pts.size(); ++i) {
    if (!point_used[i]) continue;
    const SectionPoint& sp = sec.pts[i];
    vert[i] = sp.vertex >= 0 ? sp.vertex : m.insert_vertex_in_edge(sp.ea, sp.eb, sp.p);
  }
  auto real = [&](Index v) { return v >= 0 ? v : vert[-v - 2]; };
  for (auto& [f, list] : chords) {
    for (auto& c : list) c = {real(c[0]), real(c[1])};
    m.split_face(f, list);
  }
  for (int p : chosen) {
    ModelFace cf;
    for (int l : polys[p]) {
      cf.loops.emplace_back();
      for (int k : loops[l]) cf.loops.back().push_back(vert[sec.pieces[k].from]);
    }
    cf.normal = pl.n;
    cf.offset = pl.c;
    cf.front = cf.back = r;
    cf.source = kCutFace;
    m.regions[r].faces.push_back(m.add_face(std::move(cf)));
  }
  out.cut_faces = chosen.size();
  out.regions = split_region_by_connectivity(m, r);
  out.ok = true;
  return out;
}

}  // namespace bisect
