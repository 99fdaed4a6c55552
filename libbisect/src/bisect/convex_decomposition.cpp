// Cavity removal (thesis 6.5) and convex decomposition (6.7).
//
// A region with inner shells (cavities, sub-domains) is first split by the planes of its inner
// shells' faces (polyhedral splitting, 7.3.2), which joins the inner surface to the outer one.
// Then reflex edges are taken in descending angle order, edges on double-occurring faces last;
// each is tried with the candidate planes of its inner wedge (6.4.1), the cut face method first
// and whole-plane splitting second. An edge no plane resolves is deferred: the regions cut from
// its region try it after their other edges.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include "bisect/balance_split.hpp"
#include "bisect/edge_following.hpp"
#include "bisect/section.hpp"
#include "bisect/edge_wedges.hpp"
#include "bisect/errors.hpp"
#include "bisect/plane_cut.hpp"
#include "bisect/slender_split.hpp"
#include "bisect/plane_selection.hpp"
#include "geom/recentre.hpp"

namespace bisect {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::vector<ReflexEdge> reflex_edges(const PolyhedralModel& m, Index r, const RegionEdges& edges, double tol) {
  std::vector<ReflexEdge> out;
  for (const auto& [key, uses] : edges)
    for (const Wedge& w : interior_wedges(m, r, key_lo(key), key_hi(key), uses))
      if (w.angle > M_PI + tol)
        out.push_back({key_lo(key), key_hi(key), w, m.side_of(w.face0, r) == 2 || m.side_of(w.face1, r) == 2});
  std::sort(out.begin(), out.end(), [](const ReflexEdge& x, const ReflexEdge& y) {
    if (x.on_double_face != y.on_double_face) return !x.on_double_face;
    if (x.wedge.angle != y.wedge.angle) return x.wedge.angle > y.wedge.angle;
    return std::make_pair(x.a, x.b) < std::make_pair(y.a, y.b);
  });
  return out;
}

// Connected surfaces bounding the region, by faces sharing edges; returns each face's shell.
std::vector<int> shells(const PolyhedralModel& m, Index r, const std::vector<Index>& faces, int* count) {
  std::unordered_map<Index, int> slot;
  for (std::size_t k = 0; k < faces.size(); ++k) slot[faces[k]] = static_cast<int>(k);
  std::vector<int> parent(faces.size());
  for (std::size_t k = 0; k < faces.size(); ++k) parent[k] = static_cast<int>(k);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& [key, uses] : region_edges(m, r))
    for (std::size_t i = 1; i < uses.size(); ++i) parent[find(slot[uses[i].face])] = find(slot[uses[0].face]);
  std::unordered_map<int, int> id;
  std::vector<int> shell(faces.size());
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const int root = find(static_cast<int>(k));
    auto it = id.find(root);
    if (it == id.end()) it = id.emplace(root, static_cast<int>(id.size())).first;
    shell[k] = it->second;
  }
  *count = static_cast<int>(id.size());
  return shell;
}

std::string node_name(const PolyhedralModel& m, Index v) {
  std::ostringstream s;
  s.precision(6);
  s << "node " << v + 1 << " (" << m.nodes[v].x() << ", " << m.nodes[v].y() << ", " << m.nodes[v].z() << ")";
  return s.str();
}

// The order in which a region's reflex edges are tried: planar cuts before walked ones (whose
// triangulated interfaces can leave new reflex edges behind); first the planar cuts of the first
// edges with the wider vertex margin (level -1), then each method under the thesis's limits, then
// under relaxed ones; only the last stage gives up on the limits almost entirely. (Walked cuts
// under the wider margin left non-convex cells on 3 of 1,000 random CSG solids: not tried.)
struct Stage {
  int level;
  int methods[2];
};
constexpr Stage kStages[] = {{-1, {0, 2}}, {0, {0, 2}}, {0, {1, 3}}, {1, {0, 2}}, {1, {1, 3}}, {2, {0, 2}}};

// How many of a region's edges (in the order above) are tried with the wider margin. On fine
// facets it fails for most edges, and each failed plane costs a section of the region: with
// every edge tried, the 49,820-face double sphere of the decomposition bench took about 5 times as long
// as with the thesis's margin alone, with 16 it takes 1.5 times as long (1.1 times at 10k-20k
// faces), and on flange.stl and Angled.stl at 10^4 the meshes are as good as with every edge
// (fewer edges, 8 or 4, gave smaller dihedral angles).
constexpr int kWideMarginEdges = 16;

// The four methods: the cut face and edge following resolve a reflex edge (6.4.1, 6.7); plane
// splitting and contour splitting handle sections with holes (a sub-region in the way, 6.5).
const char* const kMethodNames[4] = {"cut_face", "edge_following", "splitting", "contour_splitting"};

CutOutcome try_method(PolyhedralModel& m, Index r, const CutPlane& pl, Index a, Index b, int method,
                      const DecomposeOptions& opt, const RegionSnapshot* snap = nullptr) {
  switch (method) {
    case 0: return cut_region(m, r, pl, a, b, false, opt, snap);
    case 1: return edge_following_cut(m, r, pl, a, b, false, opt, snap);
    case 2: return cut_region(m, r, pl, a, b, true, opt, snap);
    default: return edge_following_cut(m, r, pl, a, b, true, opt, snap);
  }
}

// The limits of a stage: level -1 widens the vertex margin (never narrows it), 0 is as given,
// 1 and 2 relax every limit.
DecomposeOptions relaxed(const DecomposeOptions& opt, int level) {
  DecomposeOptions o = opt;
  if (level < 0) o.near_vertex_rel = std::max(o.near_vertex_rel, o.preferred_near_vertex_rel);
  if (level >= 1) o.near_vertex_rel /= 4, o.short_edge_rel /= 4, o.min_angle_deg /= 2, o.min_face_corner_deg /= 2;
  if (level >= 2) o.near_vertex_rel = 1e-6, o.short_edge_rel = 1e-6, o.min_angle_deg = 0.2, o.min_face_corner_deg = 0;
  return o;
}

// Whether level -1 differs from level 0 (it does not on the narrow retry): an equal stage would
// only repeat the same planes.
bool stage_applies(const DecomposeOptions& opt, int level) {
  return level >= 0 || opt.widens_margin();
}

// A convex cell may keep a face with a hole that a coplanar face of the same cell fills (a slab
// over a cavity's top). The thesis removes such holes by cut edges (7.3.2 step 6); here the cell
// is split by a plane across the face through the hole, which keeps both halves convex and leaves
// only simple polygons, so that the .poly file (which tells a hole only by its lying inside a
// coplanar face) reads back the same.
void remove_face_holes(PolyhedralModel& m, const DecomposeOptions& opt, DecomposeStats& st) {
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    if (!m.faces[f].alive || m.faces[f].loops.size() < 2) continue;
    const ModelFace face = m.faces[f];
    const Index r = face.back >= 0 ? face.back : face.front;
    Vec3 centre = Vec3::Zero();
    for (Index v : face.loops[1]) centre += m.nodes[v];
    centre /= static_cast<double>(face.loops[1].size());
    const PlaneFrame fr(face.normal);
    bool done = false;
    for (int level = -1; level < 3 && !done; ++level) {
      if (!stage_applies(opt, level)) continue;
      for (int k = 0; k < 12 && !done; ++k) {  // directions across the face, 15 degrees apart
        const double a = M_PI * k / 12;
        const Vec3 n = (std::cos(a) * fr.e1 + std::sin(a) * fr.e2).normalized();
        const CutOutcome c = cut_region(m, r, {n, n.dot(centre)}, -1, -1, true, relaxed(opt, level));
        if (c.ok) {
          ++st.bisections["hole_removal"];
          done = true;
        }
      }
    }
    if (!done)
      throw MeshingError(m.source + ": no plane across a cell face with a hole (near " + std::to_string(centre.x()) + ", " +
                         std::to_string(centre.y()) + ", " + std::to_string(centre.z()) + ") divides it into simple polygons");
    f = static_cast<std::size_t>(-1);  // faces were split and added: look again from the start
  }
}

}  // namespace

Decomposition decompose(const PolyInput& in, const DecomposeOptions& opt) {
  const Vec3 shift = geom::recentring_shift(in.nodes);  // a part far from the origin: near it
  if (shift != Vec3::Zero()) {
    PolyInput near = in;
    for (Vec3& p : near.nodes) p -= shift;
    Decomposition d = decompose(near, opt);
    for (Vec3& p : d.model.nodes) p += shift;
    for (ModelFace& f : d.model.faces) f.offset += f.normal.dot(shift);
    return d;
  }
  const auto t0 = Clock::now();
  PolyhedralModel m = prepare_model(in);
  const double prep = since(t0);
  Decomposition d = decompose(std::move(m), opt);
  d.stats.prepare_seconds = prep;
  return d;
}

namespace {

Decomposition decompose_once(PolyhedralModel model, const DecomposeOptions& opt) {
  const auto t0 = Clock::now();
  Decomposition d;
  d.model = std::move(model);
  PolyhedralModel& m = d.model;
  DecomposeStats& st = d.stats;
  const double tol = opt.reflex_tol_deg * M_PI / 180.0;

  std::deque<Index> work;
  for (std::size_t r = 0; r < m.regions.size(); ++r) work.push_back(static_cast<Index>(r));
  std::unordered_map<Index, std::set<std::uint64_t>> deferred;  // edges that failed in the region
  std::size_t finished = 0;
  auto accept = [&](const CutOutcome& c, Index r, const char* method) {
    ++st.bisections[method];
    const std::set<std::uint64_t> failed = deferred[r];
    for (Index nr : c.regions) {
      deferred[nr] = failed;
      work.push_back(nr);
    }
  };

  while (!work.empty()) {
    const Index r = work.front();
    work.pop_front();
    if (opt.progress && !opt.progress(static_cast<double>(finished) / static_cast<double>(finished + work.size() + 1)))
      throw Cancelled();
    m.drop_dead_faces(r);

    // Cavity removal: planes of inner-shell faces, largest faces first.
    int nshell = 0;
    const std::vector<Index> faces = m.live_faces(r);
    const std::vector<int> shell = shells(m, r, faces, &nshell);
    if (nshell > 1) {
      std::vector<double> lo(nshell, 1e300);
      for (std::size_t k = 0; k < faces.size(); ++k)
        for (Index v : m.faces[faces[k]].loops[0]) lo[shell[k]] = std::min(lo[shell[k]], m.nodes[v].x());
      const int outer = static_cast<int>(std::min_element(lo.begin(), lo.end()) - lo.begin());
      std::vector<Index> inner;
      for (std::size_t k = 0; k < faces.size(); ++k)
        if (shell[k] != outer) inner.push_back(faces[k]);
      std::sort(inner.begin(), inner.end(), [&](Index a, Index b) { return m.face_area(a) > m.face_area(b); });
      bool done = false;
      std::vector<CutPlane> tried;
      for (Index f : inner) {
        const CutPlane pl{m.faces[f].normal, m.faces[f].offset};
        bool seen = false;
        for (const CutPlane& t : tried) seen |= std::abs(t.n.dot(pl.n)) > 1 - 1e-12 && std::abs(t.c - pl.c * t.n.dot(pl.n)) < 1e-9 * m.size;
        if (seen) continue;
        tried.push_back(pl);
        for (int method : {2, 3}) {
          for (int level : {-1, 0}) {  // the planar split with the wider vertex margin first
            if (level < 0 && (method != 2 || !stage_applies(opt, level))) continue;
            const CutOutcome c = try_method(m, r, pl, -1, -1, method, relaxed(opt, level));
            if (c.ok) {
              accept(c, r, kMethodNames[method]);
              done = true;
              break;
            }
            if (level == 0) ++st.rejected[c.reason];
          }
          if (done) break;
        }
        if (done) break;
      }
      if (done) continue;
    }

    const RegionSnapshot snap = region_snapshot(m, r);  // unchanged until a cut succeeds
    const RegionEdges& edges = snap.edges;
    const std::vector<ReflexEdge> reflex = reflex_edges(m, r, edges, tol);
    if (reflex.empty()) {
      ++finished;
      continue;
    }
    std::vector<Index> nodes;  // the region's nodes, for the planes through a vertex
    for (const auto& kv : edges) nodes.push_back(key_lo(kv.first)), nodes.push_back(key_hi(kv.first));
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    std::vector<ReflexEdge> order;
    for (const ReflexEdge& e : reflex)
      if (!deferred[r].count(edge_key(e.a, e.b))) order.push_back(e);
    for (const ReflexEdge& e : reflex)
      if (deferred[r].count(edge_key(e.a, e.b))) order.push_back(e);
    bool done = false;
    std::map<std::string, std::size_t> why;  // this region's rejections, for the error message
    // Every reflex edge with the thesis's rejection limits first; only when none of the region's
    // edges can be resolved so, the limits are relaxed step by step (a short edge or a small angle
    // in one cell is better than no mesh), and each relaxed cut is counted.
    for (const Stage& stage : kStages) {
      if (done) break;
      const int level = stage.level;
      if (!stage_applies(opt, level)) continue;
      const DecomposeOptions lim = relaxed(opt, level);
      int tried = 0;
      for (const ReflexEdge& e : order) {
        if (level < 0 && ++tried > kWideMarginEdges) break;
        const std::vector<CutPlane> planes = candidate_planes(m, e, opt.max_candidates, nodes, opt.curved_faces);
        for (int method : {stage.methods[0], stage.methods[1]}) {
          if (done) break;
          for (const CutPlane& pl : planes) {
            const CutOutcome c = try_method(m, r, pl, e.a, e.b, method, lim, &snap);
            if (c.ok) {
              accept(c, r, kMethodNames[method]);
              if (level > 0) ++st.bisections["relaxed_limits"];
              done = true;
              break;
            }
            if (level == 0) ++st.rejected[c.reason];
            if (level >= 0) ++why[c.reason];
          }
        }
        if (done) break;
        if (level == 0 && deferred[r].insert(edge_key(e.a, e.b)).second) ++st.deferred;
      }
    }
    if (!done) {
      const ReflexEdge& e = order.front();
      std::ostringstream msg;
      msg.precision(4);
      msg << m.source << ": region " << m.regions[r].source + 1 << ": no bisection plane resolves the reflex edge from "
          << node_name(m, e.a) << " to " << node_name(m, e.b) << " (angle " << e.wedge.angle * 180 / M_PI
          << " degrees) nor any of the region's other " << order.size() - 1 << " reflex edges; planes rejected:";
      for (const auto& [reason, n] : why) msg << ' ' << reason << ' ' << n;
      throw MeshingError(msg.str());
    }
  }

  remove_face_holes(m, opt, st);
  split_slender_cells(m, opt, st);
  split_large_cells(m, opt, st);
  for (std::size_t r = 0; r < m.regions.size(); ++r) {
    m.drop_dead_faces(static_cast<Index>(r));
    ConvexCell c;
    c.source_region = m.regions[r].source;
    for (Index f : m.regions[r].faces) {
      if (m.side_of(f, static_cast<Index>(r)) == 2)
        throw MeshingError(m.source + ": a cut face remained inside a cell of region " + std::to_string(c.source_region + 1));
      c.faces.push_back(f);
      c.outward.push_back(m.faces[f].back == static_cast<Index>(r) ? 1 : 0);
    }
    d.cells.push_back(std::move(c));
  }
  st.convex_cells = d.cells.size();
  st.bisect_seconds = since(t0);
  return d;
}

// The wider vertex margin changes which cuts are made, and a different sequence of cuts can leave
// a region that no plane resolves where the thesis's margin alone would not (2 of 1,000 random
// CSG solids, against 1). Such an input is decomposed again from the start with the thesis's
// margin only, so that the wider margin never costs a mesh.
Decomposition decompose_margins(PolyhedralModel model, const DecomposeOptions& opt) {
  if (!opt.widens_margin()) return decompose_once(std::move(model), opt);
  const auto t0 = Clock::now();
  try {
    return decompose_once(model, opt);
  } catch (const MeshingError&) {
    Decomposition d = decompose_once(std::move(model), opt.thesis_margin_only());
    d.stats.narrow_margin_retry = true;
    d.stats.bisect_seconds = since(t0);
    return d;
  }
}

}  // namespace

// The face corner limit, like the wider margin, changes the sequence of cuts, and a sequence can
// end in a region no plane resolves (corpus Kurbelwelle, Zylkopf and x_ring did at 2*10^4): the
// input is decomposed again without it, so that the limit never costs a mesh either.
Decomposition decompose(PolyhedralModel model, const DecomposeOptions& opt) {
  if (!(opt.min_face_corner_deg > 0)) return decompose_margins(std::move(model), opt);
  const auto t0 = Clock::now();
  try {
    return decompose_margins(model, opt);
  } catch (const MeshingError&) {
    DecomposeOptions o = opt;
    o.min_face_corner_deg = 0;
    Decomposition d = decompose_margins(std::move(model), o);
    d.stats.face_corner_retry = true;
    d.stats.bisect_seconds = since(t0);
    return d;
  }
}

}  // namespace bisect
