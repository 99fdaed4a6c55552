#include "bisect/edge_following.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "bisect/errors.hpp"
#include "geom/loop_triangulation.hpp"
#include "bisect/region_split.hpp"
#include "bisect/section.hpp"
#include "domain/face_split.hpp"

namespace bisect {

CutOutcome edge_following_cut(PolyhedralModel& m, Index r, const CutPlane& pl, Index ea, Index eb, bool contour,
                              const DecomposeOptions& opt, const RegionSnapshot* given) {
  CutOutcome out;
  auto reject = [&](const char* why) {
    out.reason = why;
    return out;
  };
  const double min_angle = opt.min_angle_deg * M_PI / 180.0;
  const double max_tilt = 45.0 * M_PI / 180.0;
  RegionSnapshot own;
  if (!given) own = region_snapshot(m, r);
  const RegionSnapshot& snap = given ? *given : own;
  const RegionEdges& edges = snap.edges;
  SectionResult S = build_section(m, r, pl, false, opt, &snap);
  if (S.reject) return reject(S.reject);
  const Section& sec = S.sec;

  std::vector<int> chosen;
  if (contour) {
    for (std::size_t p = 0; p < S.polys.size(); ++p) chosen.push_back(static_cast<int>(p));
  } else {
    for (std::size_t k = 0; k < sec.pieces.size() && chosen.empty(); ++k) {
      const Piece& p = sec.pieces[k];
      const Index va = sec.pts[p.from].vertex, vb = sec.pts[p.to].vertex;
      if (p.face < 0 && ((va == ea && vb == eb) || (va == eb && vb == ea))) chosen.push_back(S.poly_of[S.loop_of[k]]);
    }
    if (chosen.empty()) return reject("not_interior");
    if (S.polys[chosen[0]].size() > 1) return reject("section_has_holes");  // contour splitting's job
  }

  // 1. Walk: each section point becomes a node of the region, or a provisional mid-node -(k+2).
  std::vector<Vec3> mid_pos;              // provisional mid-nodes
  std::vector<std::array<Index, 2>> mid_edge;
  auto pos = [&](Index v) { return v >= 0 ? m.nodes[v] : mid_pos[-v - 2]; };
  auto dist = [&](Index v) { return pl.n.dot(pos(v)) - pl.c; };
  std::vector<std::vector<Index>> walked;  // per loop of every chosen polygon, outer first
  std::vector<std::size_t> poly_start;
  std::unordered_map<Index, std::vector<std::array<Index, 2>>> chords;  // face -> provisional chords
  for (int p : chosen) {
    poly_start.push_back(walked.size());
    for (int l : S.polys[p]) {
      std::vector<Index> w;
      std::vector<Index> via;  // the face the step to this node crossed (-1 along an edge)
      const auto& lp = S.loops[l];
      for (std::size_t i = 0; i < lp.size(); ++i) {
        const SectionPoint& sp = sec.pts[sec.pieces[lp[i]].from];
        // the step that arrives here crossed this face (-1: it ran along an edge)
        const Index face = sec.pieces[lp[(i + lp.size() - 1) % lp.size()]].face;
        Index v = sp.vertex;
        if (v < 0) {
          const double da = std::abs(S.info[sp.ea].d), db = std::abs(S.info[sp.eb].d);
          v = da <= db ? sp.ea : sp.eb;
          if (!w.empty()) {  // a mid-node when the nearer end tilts the walk too much
            const Vec3 prev = pos(w.back());
            const auto tilt = [&](const Vec3& q) {
              const double len = (q - prev).norm();
              return len > 0 ? std::asin(std::min(1.0, std::abs(pl.n.dot(q - prev)) / len)) : 0.0;
            };
            const Vec3 mid = 0.5 * (m.nodes[sp.ea] + m.nodes[sp.eb]);
            if (tilt(m.nodes[v]) > max_tilt && tilt(mid) < tilt(m.nodes[v])) {
              mid_pos.push_back(mid);
              mid_edge.push_back({sp.ea, sp.eb});
              v = -static_cast<Index>(mid_pos.size() + 1);
            }
          }
        }
        if (!w.empty() && w.back() == v) continue;
        w.push_back(v);
        via.push_back(face);
      }
      while (w.size() > 1 && w.front() == w.back()) w.pop_back(), via.pop_back();
      if (w.size() < 3) return reject("degenerate_section");
      std::vector<Index> sorted = w;
      std::sort(sorted.begin(), sorted.end());
      if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return reject("pinched_section");
      // every step runs along an edge of the region or across the face the section crossed
      for (std::size_t i = 0; i < w.size(); ++i) {
        const Index u = w[i], v = w[(i + 1) % w.size()];
        const Index f = via[(i + 1) % w.size()];
        if (u >= 0 && v >= 0 && edges.count(edge_key(u, v))) continue;
        if (f < 0) return reject("no_edge_path");
        auto& list = chords[f];
        std::array<Index, 2> c{std::min(u, v), std::max(u, v)};
        if (std::find(list.begin(), list.end(), c) == list.end()) list.push_back(c);
      }
      walked.push_back(std::move(w));
    }
  }

  // 2. Bandwidth test (7.3.3): no other node inside the projected loop between P_l and P_u.
  const double psi = opt.band_rel * snap.edge_length_sum / static_cast<double>(std::max<std::size_t>(edges.size(), 1));
  std::unordered_set<Index> on_loop, joined;
  double dmin = 1e300, dmax = -1e300;
  for (const auto& w : walked)
    for (Index v : w) {
      on_loop.insert(v);
      dmin = std::min(dmin, dist(v)), dmax = std::max(dmax, dist(v));
    }
  if (!snap.edge_start.empty()) {  // the loop's nodes' neighbours, from the edges at each node
    for (const Index v : on_loop) {
      if (v < 0 || static_cast<std::size_t>(v) >= snap.slot.size() || snap.slot[v] < 0) continue;
      const int k = snap.slot[v];
      for (int i = snap.edge_start[k]; i < snap.edge_start[k + 1]; ++i) {
        const std::uint64_t key = snap.edge_keys[snap.edge_at[i]];
        joined.insert(key_lo(key) == v ? key_hi(key) : key_lo(key));
      }
    }
  } else {
    for (const auto& [key, uses] : edges) {
      if (on_loop.count(key_lo(key))) joined.insert(key_hi(key));
      if (on_loop.count(key_hi(key))) joined.insert(key_lo(key));
    }
  }
  for (const auto& me : mid_edge) joined.insert(me[0]), joined.insert(me[1]);
  const PlaneFrame& fr = sec.frame();
  std::vector<std::vector<Vec2>> proj;
  for (const auto& w : walked) {
    proj.emplace_back();
    for (Index v : w) proj.back().push_back(fr.to2d(pos(v)));
  }
  for (const auto& [v, I] : S.info) {
    if (I.d < dmin - psi || I.d > dmax + psi) continue;  // first: most nodes are far from the band
    if (on_loop.count(v) || joined.count(v)) continue;
    if (point_in_loops(fr.to2d(m.nodes[v]), proj)) return reject("bandwidth");
  }

  // 3. Triangulate each polygon's projected loops, check the angles with the boundary.
  std::vector<Vec2> pts;
  std::vector<Index> id_of;
  std::vector<std::array<Index, 3>> tris;
  for (std::size_t p = 0; p < poly_start.size(); ++p) {
    const std::size_t end = p + 1 < poly_start.size() ? poly_start[p + 1] : walked.size();
    std::vector<std::vector<int>> loops;
    for (std::size_t l = poly_start[p]; l < end; ++l) {
      loops.emplace_back();
      for (Index v : walked[l]) {
        loops.back().push_back(static_cast<int>(pts.size()));
        pts.push_back(fr.to2d(pos(v)));
        id_of.push_back(v);
      }
    }
    const auto t = triangulate_loops(pts, loops);
    if (t.empty()) return reject("projection_not_simple");
    for (const auto& tri : t) tris.push_back({id_of[tri[0]], id_of[tri[1]], id_of[tri[2]]});
  }
  for (const auto& t : tris) {
    const Vec3 a = pos(t[0]), b = pos(t[1]), c = pos(t[2]);
    const Vec3 nt = (b - a).cross(c - a);
    if (nt.norm() <= 1e-14 * m.size * m.size) return reject("degenerate_section");
    for (int i = 0; i < 3; ++i) {  // 3D corner angles of the interface triangles
      const Vec3 p = pos(t[i]), q = pos(t[(i + 1) % 3]), s = pos(t[(i + 2) % 3]);
      const double ang = std::acos(std::clamp((q - p).normalized().dot((s - p).normalized()), -1.0, 1.0));
      if (ang < min_angle) return reject("acute_angle");
    }
    for (int i = 0; i < 3; ++i) {  // where a triangle edge runs along the region's boundary
      const Index u = t[i], v = t[(i + 1) % 3];
      if (u < 0 || v < 0) continue;
      auto it = edges.find(edge_key(u, v));
      if (it == edges.end()) continue;
      const Index lo = std::min(u, v), hi = std::max(u, v);
      const EdgeFrame ef(m.nodes[lo], m.nodes[hi]);
      const Vec3 inside = pos(t[(i + 2) % 3]) - m.nodes[lo];
      const Vec3 w = inside - inside.dot(ef.d) * ef.d;
      const double alpha = ef.angle_of(w);
      bool ok = false;
      for (const Wedge& wd : interior_wedges(m, r, lo, hi, it->second)) {
        double rel = alpha - wd.start;
        while (rel < 0) rel += 2 * M_PI;
        while (rel >= 2 * M_PI) rel -= 2 * M_PI;
        if (rel > min_angle && wd.angle - rel > min_angle) ok = true;
      }
      if (!ok) return reject("acute_angle");
    }
  }

  // 4. Dry run of the face splits, then the changes.
  auto new_point = [&](Index a, Index b) -> Index {
    for (std::size_t k = 0; k < mid_edge.size(); ++k)
      if (edge_key(mid_edge[k][0], mid_edge[k][1]) == edge_key(a, b)) return -static_cast<Index>(k + 2);
    return 0;
  };
  for (const auto& [f, list] : chords)
    if (!face_splits_cleanly(m, f, list, new_point, pos)) return reject("pinched_face");
  std::vector<Index> real(mid_pos.size());
  for (std::size_t k = 0; k < mid_pos.size(); ++k) real[k] = m.insert_vertex_in_edge(mid_edge[k][0], mid_edge[k][1], mid_pos[k]);
  auto to_real = [&](Index v) { return v >= 0 ? v : real[-v - 2]; };
  for (auto& [f, list] : chords) {
    for (auto& c : list) c = {to_real(c[0]), to_real(c[1])};
    m.split_face(f, list);
  }
  for (const auto& t : tris) {
    ModelFace tf;
    tf.loops = {{to_real(t[0]), to_real(t[1]), to_real(t[2])}};
    const Vec3 a = m.nodes[tf.loops[0][0]], b = m.nodes[tf.loops[0][1]], c = m.nodes[tf.loops[0][2]];
    tf.normal = (b - a).cross(c - a).normalized();
    tf.offset = tf.normal.dot(a);
    tf.front = tf.back = r;
    tf.source = kCutFace;
    m.regions[r].faces.push_back(m.add_face(std::move(tf)));
  }
  out.cut_faces = tris.size();
  out.regions = split_region_by_connectivity(m, r);
  out.ok = true;
  return out;
}

}  // namespace bisect
