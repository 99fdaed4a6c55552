#include "pipeline/piece_against_proxy.hpp"

#include <algorithm>
#include <array>
#include <initializer_list>
#include <map>

#include "bisect/quality.hpp"

namespace bisect::pipeline {
namespace {

using Tri = std::array<Index, 3>;

// A piece grid's triangles by directed edge, and the cut faces its boundary nodes lie on: what
// both mends look up.
class PieceEdges {
 public:
  PieceEdges(surface::RegionMesh& rm, const std::vector<std::vector<Index>>& node_cuts, std::size_t boundary)
      : rm_(rm), node_cuts_(node_cuts), boundary_(boundary) {
    for (std::size_t ti = 0; ti < rm.tris.size(); ++ti) own(ti);
  }
  void own(std::size_t ti) {
    const Tri& t = rm_.tris[ti];
    for (int k = 0; k < 3; ++k) owner_[{t[k], t[(k + 1) % 3]}] = ti;
  }
  void disown(std::size_t ti) {
    const Tri& t = rm_.tris[ti];
    for (int k = 0; k < 3; ++k) owner_.erase({t[k], t[(k + 1) % 3]});
  }
  // the triangle holding directed edge (a, b), or -1
  long owner(Index a, Index b) const {
    auto it = owner_.find({a, b});
    return it == owner_.end() ? -1 : static_cast<long>(it->second);
  }
  // the cut faces all of `nodes` lie on (empty unless all are boundary nodes)
  std::vector<Index> shared_cuts(std::initializer_list<Index> nodes) const {
    std::vector<Index> out;
    if (!all_boundary(nodes)) return out;
    for (Index f : node_cuts_[static_cast<std::size_t>(*nodes.begin())])
      if (std::all_of(nodes.begin(), nodes.end(), [&](Index v) { return on_cut(v, f); })) out.push_back(f);
    return out;
  }
  // whether all of `nodes` lie on one cut face: asked of every triangle and edge, so without
  // building the list (a copy per call cost a fine cylinder's grids 0.3 s)
  bool share_a_cut(std::initializer_list<Index> nodes) const {
    if (!all_boundary(nodes)) return false;
    for (Index f : node_cuts_[static_cast<std::size_t>(*nodes.begin())])
      if (std::all_of(nodes.begin(), nodes.end(), [&](Index v) { return on_cut(v, f); })) return true;
    return false;
  }
  bool on_one_cut(const Tri& t) const { return share_a_cut({t[0], t[1], t[2]}); }
  // the far node of the triangle holding directed edge (a, b)
  Index far(std::size_t ti, Index a, Index b) const {
    for (Index w : rm_.tris[ti])
      if (w != a && w != b) return w;
    return -1;
  }

 private:
  bool all_boundary(std::initializer_list<Index> nodes) const {
    return std::all_of(nodes.begin(), nodes.end(), [&](Index v) {
      const auto i = static_cast<std::size_t>(v);
      return i < boundary_ && i < node_cuts_.size() && !node_cuts_[i].empty();
    });
  }
  bool on_cut(Index v, Index f) const {
    const std::vector<Index>& c = node_cuts_[static_cast<std::size_t>(v)];
    return std::find(c.begin(), c.end(), f) != c.end();
  }

  surface::RegionMesh& rm_;
  const std::vector<std::vector<Index>>& node_cuts_;
  std::size_t boundary_;
  std::map<std::pair<Index, Index>, std::size_t> owner_;
};

Vec3 normal_of(const std::vector<Vec3>& x, const Tri& t) { return Vec3((x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]])); }

double quality_of(const std::vector<Vec3>& x, const Tri& t) { return triangle_min_angle(x[t[0]], x[t[1]], x[t[2]]); }

// whether any of the first `boundary` nodes lies on a cut face (most pieces: none, nothing to mend)
bool touches_a_cut(const std::vector<std::vector<Index>>& node_cuts, std::size_t boundary) {
  for (std::size_t v = 0; v < std::min(boundary, node_cuts.size()); ++v)
    if (!node_cuts[v].empty()) return true;
  return false;
}

}  // namespace

int mend_cut_ears(const ParametricSurface& surf, surface::RegionMesh& rm, const std::vector<std::vector<Index>>& node_cuts,
                  std::size_t boundary) {
  if (!touches_a_cut(node_cuts, boundary)) return 0;
  PieceEdges edges(rm, node_cuts, boundary);
  auto normal = [&](const Tri& t) { return normal_of(rm.xyz, t); };
  int mended = 0;
  for (std::size_t ti = 0; ti < rm.tris.size(); ++ti) {
    const Tri t = rm.tris[ti];
    if (!edges.on_one_cut(t)) continue;
    const Vec3 n0 = normal(t);
    // the best flip: across edge (a, b) to the neighbour's far node d
    double best = -1;
    std::size_t flip_with = 0;
    Tri flip1{}, flip2{};
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      const long ui = edges.owner(b, a);
      if (ui < 0) continue;
      const Index d = edges.far(static_cast<std::size_t>(ui), a, b);
      const Tri t1{c, a, d}, t2{c, d, b};
      const Vec3 along = n0 + normal(rm.tris[ui]);
      if (!(normal(t1).dot(along) > 0 && normal(t2).dot(along) > 0) || edges.on_one_cut(t1) || edges.on_one_cut(t2)) continue;
      const double q = std::min(quality_of(rm.xyz, t1), quality_of(rm.xyz, t2));
      if (q > best) best = q, flip_with = static_cast<std::size_t>(ui), flip1 = t1, flip2 = t2;
    }
    if (best >= 0) {
      edges.disown(ti), edges.disown(flip_with);
      rm.tris[ti] = flip1, rm.tris[flip_with] = flip2;
      edges.own(ti), edges.own(flip_with);
      ++mended;
      continue;
    }
    // else the split at the triangle's centre in (u, v): on the piece's side of the cut (the
    // surface point nearest the triangle's centre may lie on the cut curve itself: a cylinder
    // cut across)
    const Vec2 uv = (rm.uv[t[0]] + rm.uv[t[1]] + rm.uv[t[2]]) / 3;
    const Index m = static_cast<Index>(rm.uv.size());
    const Vec3 centre = surf.point(uv);
    const std::array<Tri, 3> split{Tri{t[0], t[1], m}, Tri{t[1], t[2], m}, Tri{t[2], t[0], m}};
    rm.uv.push_back(uv);
    rm.xyz.push_back(centre);
    bool turns = true;
    for (const Tri& s : split) turns = turns && normal(s).dot(n0) > 0;
    if (!turns) {  // neither works: the cell fill reports the cell
      rm.uv.pop_back();
      rm.xyz.pop_back();
      continue;
    }
    edges.disown(ti);
    rm.tris[ti] = split[0];
    rm.tris.push_back(split[1]);
    rm.tris.push_back(split[2]);
    edges.own(ti), edges.own(rm.tris.size() - 2), edges.own(rm.tris.size() - 1);
    ++mended;
  }
  return mended;
}

int mend_cut_chords(const ParametricSurface& surf, surface::RegionMesh& rm, const std::vector<std::vector<Index>>& node_cuts,
                    std::size_t boundary, std::vector<Vec3>& p, const std::function<Vec3(const Vec2& uv, const Vec3& x)>& proxy_at,
                    const std::function<double(Index f, const Vec3& q)>& off_cut) {
  if (!touches_a_cut(node_cuts, boundary)) return 0;
  PieceEdges edges(rm, node_cuts, boundary);
  // new triangles replacing t and u must turn as they did, on the surface and on the proxy
  auto turn_as = [&](const Tri& t, const Tri& u, const std::vector<Tri>& repl) {
    const Vec3 along_x = normal_of(rm.xyz, t) + normal_of(rm.xyz, u), along_p = normal_of(p, t) + normal_of(p, u);
    for (const Tri& r : repl)
      if (!(normal_of(rm.xyz, r).dot(along_x) > 0 && normal_of(p, r).dot(along_p) > 0)) return false;
    return true;
  };
  auto worst = [&](const std::vector<Tri>& repl) {
    double q = 1e300;
    for (const Tri& r : repl) q = std::min(q, quality_of(rm.xyz, r));
    return q;
  };
  int mended = 0;
  for (std::size_t ti = 0; ti < rm.tris.size(); ++ti) {
    for (int k = 0; k < 3; ++k) {
      const Tri t = rm.tris[ti];
      const Index a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      if (!edges.share_a_cut({a, b})) continue;
      const long ui = edges.owner(b, a);
      if (ui < 0) continue;  // an edge of the piece's boundary
      const std::vector<Index> cuts = edges.shared_cuts({a, b});
      const Tri u = rm.tris[ui];
      const Index d = edges.far(static_cast<std::size_t>(ui), a, b);
      // the flip to (c, d), unless that is a chord too
      const std::vector<Tri> flip{Tri{c, a, d}, Tri{c, d, b}};
      const double flip_q = !edges.share_a_cut({c, d}) && turn_as(t, u, flip) ? worst(flip) : -1;
      // or a node between the two triangles, off the cut planes, joined to all four corners:
      // tried at the quadrilateral's centre in (u, v) and at each triangle's
      const Index m = static_cast<Index>(rm.uv.size());
      const std::vector<Tri> split{Tri{a, d, m}, Tri{d, b, m}, Tri{b, c, m}, Tri{c, a, m}};
      const double clear = 0.05 * (p[a] - p[b]).norm();
      double split_q = -1;
      Vec2 best_uv;
      Vec3 best_x, best_p;
      const std::array<Vec2, 3> tries{Vec2((rm.uv[a] + rm.uv[b] + rm.uv[c] + rm.uv[d]) / 4), Vec2((rm.uv[a] + rm.uv[b] + rm.uv[c]) / 3),
                                      Vec2((rm.uv[a] + rm.uv[b] + rm.uv[d]) / 3)};
      for (const Vec2& uv : tries) {
        const Vec3 x = surf.point(uv), q = proxy_at(uv, x);
        bool off = true;
        for (Index f : cuts) off = off && off_cut(f, q) > clear;
        if (!off) continue;
        rm.uv.push_back(uv), rm.xyz.push_back(x), p.push_back(q);
        if (turn_as(t, u, split) && worst(split) > split_q) split_q = worst(split), best_uv = uv, best_x = x, best_p = q;
        rm.uv.pop_back(), rm.xyz.pop_back(), p.pop_back();
      }
      // the better of the two, unless it leaves a triangle with under half the smallest angle
      // the two had: a needle on the surface costs more than the chord (the cell fill may still
      // take the cell joined with a neighbour)
      if (std::max(flip_q, split_q) < 0.5 * worst({t, u})) continue;
      edges.disown(ti), edges.disown(static_cast<std::size_t>(ui));
      if (flip_q >= split_q) {
        rm.tris[ti] = flip[0], rm.tris[ui] = flip[1];
        edges.own(ti), edges.own(static_cast<std::size_t>(ui));
        ++mended;
        continue;
      }
      rm.uv.push_back(best_uv), rm.xyz.push_back(best_x), p.push_back(best_p);
      rm.tris[ti] = split[0], rm.tris[ui] = split[1];
      rm.tris.push_back(split[2]), rm.tris.push_back(split[3]);
      edges.own(ti), edges.own(static_cast<std::size_t>(ui)), edges.own(rm.tris.size() - 2), edges.own(rm.tris.size() - 1);
      ++mended;
    }
  }
  return mended;
}

Vec3 nearest_on_faces(const PolyhedralModel& m, const std::vector<std::pair<Index, bool>>& faces, const Vec3& x, Index* source) {
  Vec3 best = x;
  double least = 1e300;
  for (const auto& face : faces) {
    const ModelFace& f = m.faces[face.first];
    const std::vector<Index>& loop = f.loops[0];
    // x in the face's plane, kept when it lies inside the outer loop (a cell's face is convex)
    const Vec3 q = x - f.normal.dot(x - m.nodes[loop[0]]) * f.normal;
    bool inside = true;
    for (std::size_t i = 0; i < loop.size() && inside; ++i) {
      const Vec3& a = m.nodes[loop[i]];
      const Vec3& b = m.nodes[loop[(i + 1) % loop.size()]];
      inside = f.normal.dot((b - a).cross(q - a)) >= 0;
    }
    Vec3 c = q;
    if (!inside) {
      double edge = 1e300;
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Vec3& a = m.nodes[loop[i]];
        const Vec3 ab = m.nodes[loop[(i + 1) % loop.size()]] - a;
        const double s = std::clamp(ab.dot(x - a) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
        const Vec3 p = a + s * ab;
        if ((p - x).squaredNorm() < edge) edge = (p - x).squaredNorm(), c = p;
      }
    }
    if ((c - x).squaredNorm() < least) least = (c - x).squaredNorm(), best = c, *source = f.source;
  }
  return best;
}

}  // namespace bisect::pipeline
