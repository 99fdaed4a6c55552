#include "pipeline/piece_against_proxy.hpp"

#include <algorithm>
#include <array>
#include <map>

#include "bisect/quality.hpp"

namespace bisect::pipeline {
namespace {

using Tri = std::array<Index, 3>;

}  // namespace

int mend_cut_ears(const ParametricSurface& surf, surface::RegionMesh& rm, const std::vector<std::vector<Index>>& node_cuts,
                  std::size_t boundary) {
  auto cuts = [&](Index v) -> const std::vector<Index>* {
    const auto i = static_cast<std::size_t>(v);
    return i < boundary && i < node_cuts.size() ? &node_cuts[i] : nullptr;
  };
  auto on_one_cut = [&](const Tri& t) {
    const std::vector<Index>*a = cuts(t[0]), *b = cuts(t[1]), *c = cuts(t[2]);
    if (!a || !b || !c) return false;
    for (Index f : *a)
      if (std::find(b->begin(), b->end(), f) != b->end() && std::find(c->begin(), c->end(), f) != c->end()) return true;
    return false;
  };
  auto normal = [&](const Tri& t) { return Vec3((rm.xyz[t[1]] - rm.xyz[t[0]]).cross(rm.xyz[t[2]] - rm.xyz[t[0]])); };
  auto quality = [&](const Tri& t) { return triangle_min_angle(rm.xyz[t[0]], rm.xyz[t[1]], rm.xyz[t[2]]); };
  // directed edge -> its triangle
  std::map<std::pair<Index, Index>, std::size_t> owner;
  auto own = [&](std::size_t ti) {
    const Tri& t = rm.tris[ti];
    for (int k = 0; k < 3; ++k) owner[{t[k], t[(k + 1) % 3]}] = ti;
  };
  auto disown = [&](std::size_t ti) {
    const Tri& t = rm.tris[ti];
    for (int k = 0; k < 3; ++k) owner.erase({t[k], t[(k + 1) % 3]});
  };
  for (std::size_t ti = 0; ti < rm.tris.size(); ++ti) own(ti);
  int mended = 0;
  for (std::size_t ti = 0; ti < rm.tris.size(); ++ti) {
    const Tri t = rm.tris[ti];
    if (!on_one_cut(t)) continue;
    const Vec3 n0 = normal(t);
    // the best flip: across edge (a, b) to the neighbour's far node d
    double best = -1;
    std::size_t flip_with = 0;
    Tri flip1{}, flip2{};
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      auto it = owner.find({b, a});
      if (it == owner.end()) continue;
      const Tri& u = rm.tris[it->second];
      Index d = -1;
      for (Index w : u)
        if (w != a && w != b) d = w;
      const Tri t1{c, a, d}, t2{c, d, b};
      const Vec3 along = n0 + normal(u);
      if (!(normal(t1).dot(along) > 0 && normal(t2).dot(along) > 0) || on_one_cut(t1) || on_one_cut(t2)) continue;
      const double q = std::min(quality(t1), quality(t2));
      if (q > best) best = q, flip_with = it->second, flip1 = t1, flip2 = t2;
    }
    if (best >= 0) {
      disown(ti), disown(flip_with);
      rm.tris[ti] = flip1, rm.tris[flip_with] = flip2;
      own(ti), own(flip_with);
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
    disown(ti);
    rm.tris[ti] = split[0];
    rm.tris.push_back(split[1]);
    rm.tris.push_back(split[2]);
    own(ti), own(rm.tris.size() - 2), own(rm.tris.size() - 1);
    ++mended;
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
