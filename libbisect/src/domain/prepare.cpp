// Geometry preparation (thesis 6.12): from the faces and regions a reader produced to a
// PolyhedralModel whose faces know their normal and the region on each side.
//
// Per region, faces are grouped into shells (connected through edges) and oriented consistently
// inside each shell; a ray from a point inside one face along its normal then tells whether that
// normal points out of the region (an even number of crossings) or into it (odd). Rays that pass
// near an edge or meet a face at a grazing angle are not trusted: another face is tried.
//
// A region whose shells bound several separate bodies is split into one model region per body.
#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <sstream>
#include <unordered_map>

#include "bisect/errors.hpp"
#include "bisect/polyhedral_model.hpp"
#include "domain/face_split.hpp"
#include "domain/surface_intersections.hpp"

namespace bisect {
namespace {

std::uint64_t edge_key(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

Vec3 newell_normal(const std::vector<Vec3>& nodes, const std::vector<Index>& loop) {
  Vec3 n = Vec3::Zero();
  const Vec3 o = nodes[loop[0]];
  for (std::size_t i = 0; i < loop.size(); ++i)
    n += (nodes[loop[i]] - o).cross(nodes[loop[(i + 1) % loop.size()]] - o);
  return n;
}

// A point strictly inside a face: the middle of the widest inside interval of a scan line
// through the face's 2D bounding box (holes included).
bool interior_point(const PolyhedralModel& m, const ModelFace& f, double frac, Vec3* out) {
  const PlaneFrame fr(f.normal, m.nodes[f.loops[0][0]]);
  std::vector<std::vector<Vec2>> l2;
  double ymin = 1e300, ymax = -1e300;
  for (const auto& loop : f.loops) {
    l2.emplace_back();
    for (Index v : loop) {
      l2.back().push_back(fr.to2d(m.nodes[v]));
      ymin = std::min(ymin, l2.back().back().y()), ymax = std::max(ymax, l2.back().back().y());
    }
  }
  const double y = ymin + frac * (ymax - ymin);
  std::vector<double> xs;
  for (const auto& l : l2)
    for (std::size_t i = 0, j = l.size() - 1; i < l.size(); j = i++)
      if ((l[i].y() > y) != (l[j].y() > y))
        xs.push_back(l[i].x() + (y - l[i].y()) * (l[j].x() - l[i].x()) / (l[j].y() - l[i].y()));
  std::sort(xs.begin(), xs.end());
  double best = 0, x = 0;
  for (std::size_t i = 0; i + 1 < xs.size(); i += 2)
    if (xs[i + 1] - xs[i] > best) best = xs[i + 1] - xs[i], x = 0.5 * (xs[i] + xs[i + 1]);
  if (best <= 0) return false;
  *out = fr.origin + x * fr.e1 + y * fr.e2;
  return true;
}

// Distance from p to the nearest loop edge, in the face's 2D frame.
double boundary_distance(const std::vector<std::vector<Vec2>>& loops, const Vec2& p) {
  double best = 1e300;
  for (const auto& l : loops)
    for (std::size_t i = 0, j = l.size() - 1; i < l.size(); j = i++) {
      const Vec2 d = l[i] - l[j];
      const double t = std::clamp((p - l[j]).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
      best = std::min(best, (l[j] + t * d - p).norm());
    }
  return best;
}

// Crossings of the ray o + t d (t > 0) with the faces, or -1 when the ray is not trustworthy.
int ray_crossings(const PolyhedralModel& m, const std::vector<Index>& faces, Index skip, const Vec3& o, const Vec3& d) {
  const double graze = std::sin(2.0 * M_PI / 180.0), tol = 1e-7 * m.size;
  int count = 0;
  for (Index fi : faces) {
    if (fi == skip) continue;
    const ModelFace& f = m.faces[fi];
    const double dn = f.normal.dot(d);
    const double t_num = f.offset - f.normal.dot(o);
    if (std::abs(dn) < 1e-300) {
      if (std::abs(t_num) < tol) return -1;  // the ray runs in the face's plane
      continue;
    }
    const double t = t_num / dn;
    if (t < -tol) continue;
    const Vec3 hit = o + t * d;
    const PlaneFrame fr(f.normal, m.nodes[f.loops[0][0]]);
    std::vector<std::vector<Vec2>> l2;
    for (const auto& loop : f.loops) {
      l2.emplace_back();
      for (Index v : loop) l2.back().push_back(fr.to2d(m.nodes[v]));
    }
    const Vec2 h = fr.to2d(hit);
    const double bd = boundary_distance(l2, h);
    const bool in = point_in_loops(h, l2);
    if (!in && bd > tol) continue;
    if (t < tol || bd <= tol || std::abs(dn) < graze) return -1;
    ++count;
  }
  return count;
}

std::string face_name(const PolyInput& in, Index input_face) { return input_face_name(in, input_face); }


// Per region: its faces grouped into shells (faces joined through edges that exactly two of the
// region's faces use: two bodies touching along an edge stay apart), each shell's volume with
// the normals pointing out of the region (positive: it bounds a body; negative: an inner
// boundary, a cavity or a sub-domain).
struct RegionShells {
  std::vector<std::vector<Index>> faces;
  std::vector<double> volume;
};

RegionShells region_shells(const PolyhedralModel& m, Index r) {
  const std::vector<Index>& F = m.regions[r].faces;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> uses;
  for (std::size_t k = 0; k < F.size(); ++k)
    for (const auto& loop : m.faces[F[k]].loops)
      for (std::size_t i = 0; i < loop.size(); ++i) uses[edge_key(loop[i], loop[(i + 1) % loop.size()])].push_back(k);
  std::vector<std::size_t> parent(F.size());
  for (std::size_t k = 0; k < F.size(); ++k) parent[k] = k;
  auto find = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& [key, us] : uses)
    if (us.size() == 2) parent[find(us[0])] = find(us[1]);
  RegionShells out;
  std::unordered_map<std::size_t, std::size_t> id;
  for (std::size_t k = 0; k < F.size(); ++k) {
    const auto [it, fresh] = id.emplace(find(k), out.faces.size());
    if (fresh) out.faces.emplace_back(), out.volume.push_back(0);
    out.faces[it->second].push_back(F[k]);
  }
  for (std::size_t s = 0; s < out.faces.size(); ++s) {
    const Vec3 o = m.nodes[m.faces[out.faces[s][0]].loops[0][0]];  // a point of the shell: less cancellation
    for (Index f : out.faces[s]) {
      const ModelFace& face = m.faces[f];
      const int side = m.side_of(f, r);
      if (side != 0 && side != 1) continue;
      const double sgn = side == 1 ? 1.0 : -1.0;  // back side: the normal points out of r
      for (const auto& loop : face.loops) {
        Vec3 a = Vec3::Zero();
        for (std::size_t i = 0; i < loop.size(); ++i) a += (m.nodes[loop[i]] - o).cross(m.nodes[loop[(i + 1) % loop.size()]] - o);
        out.volume[s] += sgn * (m.nodes[loop[0]] - o).dot(face.normal) * 0.5 * a.dot(face.normal) / 3.0;
      }
    }
  }
  return out;
}

// Whether p lies inside the closed shell: rays along a few directions until one is trusted.
bool inside_shell(const PolyhedralModel& m, const std::vector<Index>& shell, const Vec3& p) {
  static const Vec3 kDirs[] = {Vec3(0.5773, 0.5774, 0.5775), Vec3(-0.31, 0.87, 0.38), Vec3(0.92, -0.17, -0.35),
                               Vec3(-0.44, -0.61, 0.66), Vec3(0.13, 0.29, -0.95), Vec3(-0.83, 0.41, -0.37)};
  for (const Vec3& d : kDirs) {
    const int c = ray_crossings(m, shell, -1, p, d.normalized());
    if (c >= 0) return c % 2 == 1;
  }
  throw MeshingError(m.source + ": no ray tells whether a shell lies inside another");
}

std::string point_name(const Vec3& p) {
  std::ostringstream s;
  s.precision(9);
  s << '(' << p.x() << ", " << p.y() << ", " << p.z() << ')';
  return s.str();
}

// A region whose boundary falls into several bodies (disjoint parts of one STL or OFF, or of one
// .poly region) becomes one model region per body: the decomposition joins a region's inner
// shells to its outer one by cuts, which cannot join two bodies, and a cell that is two convex
// pieces cannot be filled. Each inner shell goes with the smallest body around it. Bodies may
// share vertices or edges: each is meshed on its own side and they share those nodes.
std::size_t split_bodies(PolyhedralModel& m) {
  std::size_t added = 0;
  const std::size_t nr = m.regions.size();
  for (std::size_t r = 0; r < nr; ++r) {
    const RegionShells sh = region_shells(m, static_cast<Index>(r));
    std::vector<std::size_t> bodies, inner;
    for (std::size_t s = 0; s < sh.faces.size(); ++s) (sh.volume[s] > 0 ? bodies : inner).push_back(s);
    if (bodies.size() < 2) continue;
    std::vector<std::size_t> owner(sh.faces.size());
    for (std::size_t b : bodies) owner[b] = b;
    for (std::size_t s : inner) {
      Vec3 p;
      bool found = false;
      for (std::size_t k = 0; k < sh.faces[s].size() * 3 && !found; ++k) {
        static const double kScanAt[3] = {0.5, 0.31, 0.73};
        found = interior_point(m, m.faces[sh.faces[s][k % sh.faces[s].size()]], kScanAt[k / sh.faces[s].size()], &p);
      }
      if (!found) throw MeshingError(m.source + ": no point found on an inner shell of region " + std::to_string(m.regions[r].source + 1));
      double best = HUGE_VAL;
      for (std::size_t b : bodies)
        if (sh.volume[b] < best && inside_shell(m, sh.faces[b], p)) best = sh.volume[b], owner[s] = b;
      if (!(best < HUGE_VAL))
        throw InputError(m.source + ": region " + std::to_string(m.regions[r].source + 1) + ": the inner boundary through " +
                         point_name(p) + " lies inside none of the region's bodies");
    }
    for (std::size_t i = 1; i < bodies.size(); ++i) {
      const Index nr2 = static_cast<Index>(m.regions.size());
      ModelRegion reg;
      reg.source = m.regions[r].source;
      for (std::size_t s = 0; s < sh.faces.size(); ++s) {
        if (owner[s] != bodies[i]) continue;
        for (Index f : sh.faces[s]) {
          ModelFace& face = m.faces[f];
          if (face.front == static_cast<Index>(r)) face.front = nr2;
          if (face.back == static_cast<Index>(r)) face.back = nr2;
          reg.faces.push_back(f);
        }
      }
      m.regions.push_back(std::move(reg));
      ++added;
    }
    m.drop_dead_faces(static_cast<Index>(r));  // keeps only the faces still on r's side
  }
  return added;
}

}  // namespace

PolyhedralModel prepare_model(const PolyInput& in, PreparationReport* report) {
  reject_surface_intersections(in);  // first: orientation and containment assume no crossing
  PolyhedralModel m;
  m.source = in.source;
  for (const Vec3& p : in.nodes) m.add_node(p);
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const Vec3& p : in.nodes) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  m.size = in.nodes.empty() ? 1.0 : std::max((hi - lo).norm(), 1e-300);
  if (!in.node_spacing.empty() && in.node_spacing.size() != in.nodes.size())
    throw InputError(in.source + ": " + std::to_string(in.node_spacing.size()) + " node spacings for " +
                     std::to_string(in.nodes.size()) + " nodes");
  m.node_spacing = in.node_spacing;
  PreparationReport rep;

  // Faces: outer loop counter-clockwise around its Newell normal, holes clockwise.
  std::vector<Index> model_face(in.faces.size(), -1);
  std::vector<Index> input_face_of;  // model face -> input face
  for (std::size_t i = 0; i < in.faces.size(); ++i) {
    if (in.faces[i].hole_of >= 0) continue;
    ModelFace f;
    f.loops.push_back(in.faces[i].nodes);
    const Vec3 nn = newell_normal(m.nodes, f.loops[0]);
    if (nn.norm() <= 0) throw InputError(in.source + ": " + face_name(in, static_cast<Index>(i)) + " has zero area");
    f.normal = nn.normalized();
    f.offset = f.normal.dot(m.nodes[f.loops[0][0]]);
    f.source = static_cast<Index>(i);
    model_face[i] = static_cast<Index>(m.faces.size());
    input_face_of.push_back(static_cast<Index>(i));
    m.add_face(std::move(f));
  }
  for (std::size_t i = 0; i < in.faces.size(); ++i) {
    const Index p = in.faces[i].hole_of;
    if (p < 0) continue;
    ModelFace& f = m.faces[model_face[p]];
    std::vector<Index> hole = in.faces[i].nodes;
    if (newell_normal(m.nodes, hole).dot(f.normal) > 0) std::reverse(hole.begin(), hole.end());
    f.loops.push_back(hole);
    model_face[i] = model_face[p];
    ++rep.face_holes;
  }
  // the holes were added after add_face registered the nodes: rebuild registrations
  {
    PolyhedralModel fresh;
    fresh.source = m.source;
    fresh.size = m.size;
    fresh.node_spacing = m.node_spacing;
    for (const Vec3& p : m.nodes) fresh.add_node(p);
    for (ModelFace& f : m.faces) fresh.add_face(std::move(f));
    m = std::move(fresh);
  }
  rep.faces = m.faces.size();

  // Regions' face sets (unique model faces) and how many input regions use each face.
  const std::size_t nr = in.regions.size();
  std::vector<std::vector<Index>> rfaces(nr);
  std::vector<int> uses(m.faces.size(), 0);
  for (std::size_t r = 0; r < nr; ++r) {
    for (Index f : in.regions[r].faces) rfaces[r].push_back(model_face[f]);
    std::sort(rfaces[r].begin(), rfaces[r].end());
    rfaces[r].erase(std::unique(rfaces[r].begin(), rfaces[r].end()), rfaces[r].end());
    for (Index f : rfaces[r]) ++uses[f];
  }
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    if (uses[f] > 2)
      throw InputError(in.source + ": " + face_name(in, input_face_of[f]) + " belongs to " + std::to_string(uses[f]) +
                       " regions; a face separates at most two");

  // Orientation: sign[r][k] = +1 when the normal of rfaces[r][k] points out of region r.
  std::vector<std::vector<int>> sign(nr);
  for (std::size_t r = 0; r < nr; ++r) {
    const auto& F = rfaces[r];
    std::unordered_map<std::uint64_t, std::vector<std::pair<std::size_t, int>>> edges;  // (k, dir)
    for (std::size_t k = 0; k < F.size(); ++k)
      for (const auto& loop : m.faces[F[k]].loops)
        for (std::size_t i = 0; i < loop.size(); ++i) {
          const Index a = loop[i], b = loop[(i + 1) % loop.size()];
          edges[edge_key(a, b)].push_back({k, a < b ? 1 : -1});
        }
    for (const auto& [key, us] : edges)
      if (us.size() % 2) {
        const Index a = static_cast<Index>(key >> 32), b = static_cast<Index>(key & 0xffffffffu);
        throw InputError(in.source + ": region " + std::to_string(r + 1) + " is not closed: the edge from node " +
                         std::to_string(a + 1) + " to node " + std::to_string(b + 1) + " is used by " +
                         std::to_string(us.size()) + " of its faces");
      }
    std::vector<int> s(F.size(), 0);
    std::vector<int> comp(F.size(), -1);
    int ncomp = 0;
    for (std::size_t seed = 0; seed < F.size(); ++seed) {
      if (comp[seed] >= 0) continue;
      std::vector<std::size_t> members;
      std::queue<std::size_t> q;
      q.push(seed), comp[seed] = ncomp, s[seed] = 1;
      while (!q.empty()) {
        const std::size_t k = q.front();
        q.pop();
        members.push_back(k);
        for (const auto& loop : m.faces[F[k]].loops)
          for (std::size_t i = 0; i < loop.size(); ++i) {
            const Index a = loop[i], b = loop[(i + 1) % loop.size()];
            const auto& us = edges[edge_key(a, b)];
            if (us.size() != 2) continue;  // non-manifold edges (7.2.5) do not propagate
            const int mydir = a < b ? 1 : -1;
            const auto& other = us[0].first == k && us[0].second == mydir ? us[1] : us[0];
            const int want = -s[k] * mydir * other.second;  // outward loops run opposite ways
            if (comp[other.first] < 0) {
              comp[other.first] = ncomp, s[other.first] = want;
              q.push(other.first);
            } else if (s[other.first] != want) {
              throw InputError(in.source + ": region " + std::to_string(r + 1) + ": " +
                               face_name(in, input_face_of[F[k]]) + " and " + face_name(in, input_face_of[F[other.first]]) +
                               " cannot be oriented consistently at the edge from node " + std::to_string(a + 1) +
                               " to node " + std::to_string(b + 1));
            }
          }
      }
      // One trusted ray decides the whole shell.
      int flip = 0;
      for (std::size_t t = 0; t < members.size() * 3 && !flip; ++t) {
        const std::size_t k = members[t % members.size()];
        Vec3 p;
        static const double kScanAt[3] = {0.5, 0.31, 0.73};  // scan lines tried in turn
        if (!interior_point(m, m.faces[F[k]], kScanAt[t / members.size()], &p)) continue;
        const int c = ray_crossings(m, F, F[k], p, m.faces[F[k]].normal * s[k]);
        if (c >= 0) flip = c % 2 ? -1 : 1;
      }
      if (!flip)
        throw InputError(in.source + ": region " + std::to_string(r + 1) + ": no ray from " +
                         face_name(in, input_face_of[F[seed]]) + "'s shell gives a clear inside/outside answer");
      for (std::size_t k : members) s[k] *= flip;
      ++ncomp;
    }
    sign[r] = std::move(s);
  }

  // Meshable regions get model regions; faces learn their sides.
  rep.region_of_input.assign(nr, -1);
  for (std::size_t r = 0; r < nr; ++r) {
    if (in.regions[r].cavity) continue;
    rep.region_of_input[r] = static_cast<Index>(m.regions.size());
    ModelRegion reg;
    reg.source = static_cast<Index>(r);
    m.regions.push_back(reg);
  }
  auto claim = [&](Index f, Index region, bool normal_out, std::size_t input_region) {
    ModelFace& F = m.faces[f];
    Index& slot = normal_out ? F.back : F.front;
    if (slot >= 0 && slot != region)
      throw InputError(in.source + ": inconsistent interface: " + face_name(in, input_face_of[f]) + " has regions " +
                       std::to_string(m.regions[slot].source + 1) + " and " + std::to_string(input_region + 1) +
                       " on the same side");
    slot = region;
    auto& rf = m.regions[region].faces;
    if (std::find(rf.begin(), rf.end(), f) == rf.end()) rf.push_back(f);
  };
  for (std::size_t r = 0; r < nr; ++r) {
    const Index mr = rep.region_of_input[r];
    if (mr < 0) continue;
    for (std::size_t k = 0; k < rfaces[r].size(); ++k) claim(rfaces[r][k], mr, sign[r][k] > 0, r);
  }

  // Cavities and sub-domains: their outer surface also bounds the region that holds them.
  const PolySummary sum = summarize(in);
  for (std::size_t r = 0; r < nr; ++r) {
    const Index holder = sum.regions[r].inside;
    if (in.regions[r].cavity) {
      ++rep.cavities;
      if (holder < 0 || in.regions[holder].cavity)
        throw InputError(in.source + ": cavity region " + std::to_string(r + 1) + " lies inside no region");
    } else if (holder >= 0 && !in.regions[holder].cavity) {
      ++rep.sub_domains;
    }
    if (holder < 0 || in.regions[holder].cavity) continue;
    const Index mh = rep.region_of_input[holder];
    for (std::size_t k = 0; k < rfaces[r].size(); ++k) {
      const Index f = rfaces[r][k];
      const ModelFace& F = m.faces[f];
      if (F.front == mh || F.back == mh) continue;  // already shared with the holder
      // a region that lists the face lies there, between r and the holder: a cylinder through a
      // box as BooleanFragments, whose middle piece fills the box's hole and whose end pieces
      // hold its discs (the middle piece's point lies in the box's outer shell, and the box's
      // hole is a shell of its own)
      if ((sign[r][k] < 0 ? F.back : F.front) >= 0) continue;
      claim(f, mh, sign[r][k] < 0, holder);  // the holder lies outside r
    }
  }
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    if (m.faces[f].front >= 0 && m.faces[f].back >= 0) ++rep.interfaces;
  rep.separate_bodies = split_bodies(m);
  std::size_t inner_shells = 0;
  for (std::size_t r = 0; r < nr; ++r)
    if (!in.regions[r].cavity && sum.regions[r].shells > 1) inner_shells += sum.regions[r].shells - 1;
  rep.inner_shells_as_cavities = inner_shells - std::min(inner_shells, rep.separate_bodies);

  if (report) *report = rep;
  return m;
}

}  // namespace bisect
