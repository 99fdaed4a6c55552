#include "bisect/plane_cut.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include "bisect/edge_wedges.hpp"
#include "bisect/section.hpp"
#include "bisect/region_split.hpp"
#include "bisect/errors.hpp"
#include "domain/face_split.hpp"

namespace bisect {

CutOutcome cut_region(PolyhedralModel& m, Index r, const CutPlane& pl, Index ea, Index eb, bool whole_plane,
                      const DecomposeOptions& opt, const RegionSnapshot* snap) {
  CutOutcome out;
  auto reject = [&](const char* why) {
    out.reason = why;
    return out;
  };
  const double min_angle = opt.min_angle_deg * M_PI / 180.0;
  SectionResult S = build_section(m, r, pl, whole_plane, opt, snap);
  if (S.reject) return reject(S.reject);
  auto& info = S.info;
  auto& near = S.near;
  Section& sec = S.sec;
  auto& loops = S.loops;
  auto& loop2d = S.loop2d;
  auto& loop_of = S.loop_of;
  auto& poly_of = S.poly_of;
  auto& polys = S.polys;

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
    // a vertex in the polygon's interior: the cut would touch it (the nodes on the plane, then
    // any entry made after their sides were set, whose side is 0 untouched)
    std::vector<int> on = S.on_plane;
    for (int k = S.measured; k < info.size(); ++k) on.push_back(k);
    for (const int k : on) {
      const Index v = info.node(k);
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
  // (point_used covers the points of the chosen polygons; the vertex checks above may have
  // added points after it, which no polygon uses)
  for (std::size_t i = 0; i < point_used.size(); ++i)
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
  auto new_point = [&](Index a, Index b) -> Index {
    auto it = crossing.find(edge_key(a, b));
    return it == crossing.end() ? 0 : prov(it->second);
  };
  auto pos = [&](Index v) { return v >= 0 ? m.nodes[v] : sec.pts[-v - 2].p; };
  for (const auto& [f, list] : chords)
    if (!face_splits_cleanly(m, f, list, new_point, pos)) return reject("pinched_face");

  // 8. Insert: vertices into edges, chords into faces, polygons into the region.
  std::vector<Index> vert(sec.pts.size(), -1);
  for (std::size_t i = 0; i < point_used.size(); ++i) {
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
