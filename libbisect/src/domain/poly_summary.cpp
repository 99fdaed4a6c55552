// What `bisect-mesh info` reports about a polyhedral input: per region its closed shells, how they
// nest, which region it lies in, and its net volume.
//
// Faces come in either direction (thesis 6.13), so each shell is first oriented consistently
// (faces sharing an edge traverse it in opposite directions) and then signed so that it encloses
// a positive volume (divergence theorem over fan triangles). Nesting is decided with the
// generalized winding number (sum of signed solid angles) at a point strictly inside each shell:
// shells of valid input do not cross, so a shell lies inside a larger one exactly when its
// interior point does. Comparing volumes first means a point that lies inside both (a pocket's
// interior is also inside the box) is only asked about the larger shell.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>

#include "bisect/errors.hpp"
#include "bisect/poly_input.hpp"

namespace bisect {
namespace {

using Tri = std::array<Index, 3>;
constexpr double kPi = 3.14159265358979323846;

struct Shell {
  Index region = -1;
  std::vector<Tri> tris;  // fan triangles, oriented outward
  double volume = 0;
  Vec3 lo, hi;
  Vec3 point = Vec3::Zero();  // strictly inside
};

// Signed solid angle of triangle abc seen from p (Van Oosterom and Strackee).
double solid_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p) {
  const Vec3 x = a - p, y = b - p, z = c - p;
  const double lx = x.norm(), ly = y.norm(), lz = z.norm();
  const double num = x.dot(y.cross(z));
  const double den = lx * ly * lz + x.dot(y) * lz + x.dot(z) * ly + y.dot(z) * lx;
  return 2 * std::atan2(num, den);
}

// 1 inside an outward-oriented closed shell, 0 outside, 1/2 on it.
double winding(const std::vector<Vec3>& nodes, const Shell& s, const Vec3& p) {
  if ((p.array() < s.lo.array()).any() || (p.array() > s.hi.array()).any()) return 0;
  double sum = 0;
  for (const Tri& t : s.tris) sum += solid_angle(nodes[t[0]], nodes[t[1]], nodes[t[2]], p);
  return sum / (4 * kPi);
}

// Distance along the ray o + t*d (t > tmin) to the first triangle of the shell it meets.
double first_hit(const std::vector<Vec3>& nodes, const Shell& s, const Vec3& o, const Vec3& d, double tmin) {
  double best = HUGE_VAL;
  for (const Tri& t : s.tris) {
    const Vec3 &a = nodes[t[0]], &b = nodes[t[1]], &c = nodes[t[2]];
    const Vec3 e1 = b - a, e2 = c - a;
    const Vec3 q = d.cross(e2);
    const double det = e1.dot(q);
    if (std::abs(det) < 1e-300) continue;  // parallel to the ray
    const Vec3 r = o - a;
    const double u = r.dot(q) / det;
    const Vec3 w = r.cross(e1);
    const double v = d.dot(w) / det;
    const double slack = 1e-12;  // count hits on shared edges: two near-equal answers are harmless
    if (u < -slack || v < -slack || u + v > 1 + slack) continue;
    const double dist = e2.dot(w) / det;
    if (dist > tmin) best = std::min(best, dist);
  }
  return best;
}

// A point strictly inside the shell, as far from its surface as a cheap construction allows: from
// the centre of a large triangle, half way along the inward normal to the next surface it meets.
// Checked with the winding number, because the centre of a fan triangle of a non-convex polygon
// need not lie on the polygon.
Vec3 interior_point(const std::vector<Vec3>& nodes, const Shell& s) {
  const double size = (s.hi - s.lo).norm();
  std::vector<std::size_t> order(s.tris.size());
  std::iota(order.begin(), order.end(), 0);
  auto twice_area = [&](std::size_t i) {
    const Tri& t = s.tris[i];
    return (nodes[t[1]] - nodes[t[0]]).cross(nodes[t[2]] - nodes[t[0]]).norm();
  };
  const std::size_t tries = std::min<std::size_t>(order.size(), 12);
  std::partial_sort(order.begin(), order.begin() + tries, order.end(),
                    [&](std::size_t a, std::size_t b) { return twice_area(a) > twice_area(b); });
  Vec3 fallback = Vec3::Zero();
  for (std::size_t k = 0; k < tries; ++k) {
    const Tri& t = s.tris[order[k]];
    const Vec3 n = (nodes[t[1]] - nodes[t[0]]).cross(nodes[t[2]] - nodes[t[0]]);
    if (!(n.norm() > 0)) continue;
    const Vec3 c = (nodes[t[0]] + nodes[t[1]] + nodes[t[2]]) / 3;
    const Vec3 inward = -n.normalized();
    if (k == 0) fallback = c + 1e-6 * size * inward;
    const double hit = first_hit(nodes, s, c, inward, 1e-9 * size);
    if (!std::isfinite(hit)) continue;
    const Vec3 p = c + 0.5 * hit * inward;
    if (std::abs(winding(nodes, s, p) - 1) < 0.25) return p;
  }
  return fallback;
}

struct EdgeUse {
  std::uint64_t key;
  Index face;  // position in the region's face list
  bool forward;  // the face runs from the smaller node to the larger one
};

// The closed shells of one region, each oriented outward.
std::vector<Shell> region_shells(const PolyInput& in, Index region) {
  const std::vector<Index>& faces = in.regions[region].faces;
  const Index nf = Index(faces.size());
  std::vector<EdgeUse> uses;
  for (Index i = 0; i < nf; ++i) {
    const auto& v = in.faces[faces[i]].nodes;
    for (std::size_t j = 0; j < v.size(); ++j) {
      const Index a = v[j], b = v[(j + 1) % v.size()];
      const std::uint64_t key = (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
      uses.push_back({key, i, a < b});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.key != y.key ? x.key < y.key : x.face < y.face;
  });
  // Orientation spreads only across edges shared by exactly two faces: at an edge of four faces
  // (two solids of one region touching along it) the pairing is ambiguous, and each solid is
  // reached through its own manifold edges anyway.
  std::vector<std::vector<std::pair<Index, bool>>> next(nf);  // neighbour, must flip relative
  std::vector<std::pair<std::size_t, std::size_t>> groups;     // [begin, end) in uses
  for (std::size_t b = 0, e; b < uses.size(); b = e) {
    for (e = b; e < uses.size() && uses[e].key == uses[b].key;) ++e;
    groups.push_back({b, e});
    if (e - b == 2 && uses[b].face != uses[b + 1].face) {
      const bool flip = uses[b].forward == uses[b + 1].forward;
      next[uses[b].face].push_back({uses[b + 1].face, flip});
      next[uses[b + 1].face].push_back({uses[b].face, flip});
    }
  }
  std::vector<Index> comp(nf, -1);
  std::vector<char> flipped(nf, 0);
  Index ncomp = 0;
  for (Index seed = 0; seed < nf; ++seed) {
    if (comp[seed] >= 0) continue;
    std::vector<Index> stack{seed};
    comp[seed] = ncomp;
    while (!stack.empty()) {
      const Index f = stack.back();
      stack.pop_back();
      for (auto [g, flip] : next[f]) {
        if (comp[g] >= 0) continue;  // a conflict here means a non-orientable (crossing) input
        comp[g] = ncomp;
        flipped[g] = char(flipped[f] ^ flip);
        stack.push_back(g);
      }
    }
    ++ncomp;
  }
  // A component is a closed shell when each of its edges is used an even number of times by it.
  std::vector<char> closed(ncomp, 1);
  std::vector<Index> in_group;
  for (auto [b, e] : groups) {
    in_group.clear();
    for (std::size_t k = b; k < e; ++k) in_group.push_back(comp[uses[k].face]);
    std::sort(in_group.begin(), in_group.end());
    for (std::size_t k = 0, j; k < in_group.size(); k = j) {
      for (j = k; j < in_group.size() && in_group[j] == in_group[k];) ++j;
      if ((j - k) % 2) closed[in_group[k]] = 0;
    }
  }
  std::vector<Shell> shells(ncomp);
  for (Index i = 0; i < nf; ++i) {
    if (!closed[comp[i]]) continue;
    std::vector<Index> v = in.faces[faces[i]].nodes;
    if (flipped[i]) std::reverse(v.begin(), v.end());
    for (std::size_t j = 1; j + 1 < v.size(); ++j) shells[comp[i]].tris.push_back({v[0], v[j], v[j + 1]});
  }
  std::vector<Shell> out;
  for (Index c = 0; c < ncomp; ++c) {
    Shell& s = shells[c];
    if (!closed[c] || s.tris.empty()) continue;
    s.region = region;
    const Vec3 origin = in.nodes[s.tris[0][0]];  // near the shell, for less cancellation
    double six_v = 0;
    s.lo = s.hi = origin;
    for (const Tri& t : s.tris) {
      const Vec3 a = in.nodes[t[0]] - origin, b = in.nodes[t[1]] - origin, c2 = in.nodes[t[2]] - origin;
      six_v += a.dot(b.cross(c2));
      for (Index n : t) s.lo = s.lo.cwiseMin(in.nodes[n]), s.hi = s.hi.cwiseMax(in.nodes[n]);
    }
    if (six_v < 0) {
      for (Tri& t : s.tris) std::swap(t[1], t[2]);
      six_v = -six_v;
    }
    s.volume = six_v / 6;
    out.push_back(std::move(s));
  }
  return out;
}

// The readers guarantee valid references; an input built in code (the Python module allows it)
// gets an error instead of an out-of-bounds read.
void check_references(const PolyInput& in) {
  const std::string name = in.source.empty() ? std::string("input") : in.source;
  for (std::size_t f = 0; f < in.faces.size(); ++f) {
    for (Index n : in.faces[f].nodes)
      if (n < 0 || std::size_t(n) >= in.nodes.size())
        throw InputError(name + ": face " + std::to_string(f + 1) + " refers to node " + std::to_string(n + 1) +
                         ", but there are " + std::to_string(in.nodes.size()) + " nodes");
    const Index h = in.faces[f].hole_of;
    if (h < -1 || (h >= 0 && std::size_t(h) >= in.faces.size()))
      throw InputError(name + ": face " + std::to_string(f + 1) + " is the hole of face " + std::to_string(h + 1) +
                       ", but there are " + std::to_string(in.faces.size()) + " faces");
  }
  for (std::size_t r = 0; r < in.regions.size(); ++r)
    for (Index f : in.regions[r].faces)
      if (f < 0 || std::size_t(f) >= in.faces.size())
        throw InputError(name + ": region " + std::to_string(r + 1) + " refers to face " + std::to_string(f + 1) +
                         ", but there are " + std::to_string(in.faces.size()) + " faces");
}

}  // namespace

PolySummary summarize(const PolyInput& in) {
  PolySummary sum;
  sum.faces = in.faces.size();
  sum.nodes = in.nodes.size();
  if (!in.nodes.empty()) {
    sum.bbox_min = sum.bbox_max = in.nodes[0];
    for (const Vec3& p : in.nodes) sum.bbox_min = sum.bbox_min.cwiseMin(p), sum.bbox_max = sum.bbox_max.cwiseMax(p);
  }
  check_references(in);
  const Index nr = Index(in.regions.size());
  sum.regions.resize(nr);
  std::vector<Shell> shells;
  std::vector<char> mine(in.faces.size(), 0);
  for (Index r = 0; r < nr; ++r) {
    const PolyRegion& region = in.regions[r];
    RegionSummary& rs = sum.regions[r];
    rs.faces = region.faces.size();
    rs.cavity = region.cavity;
    std::vector<Index> used;
    for (Index f : region.faces) {
      mine[f] = 1;
      used.insert(used.end(), in.faces[f].nodes.begin(), in.faces[f].nodes.end());
    }
    std::sort(used.begin(), used.end());
    rs.nodes = std::size_t(std::unique(used.begin(), used.end()) - used.begin());
    for (Index f : region.faces)
      if (in.faces[f].hole_of >= 0 && mine[in.faces[f].hole_of]) ++rs.holes;
    for (Index f : region.faces) mine[f] = 0;
    for (Shell& s : region_shells(in, r)) shells.push_back(std::move(s));
  }
  for (Shell& s : shells) {
    s.point = interior_point(in.nodes, s);
    ++sum.regions[s.region].shells;
  }

  // inside[s][t]: the interior point of shell s lies inside shell t.
  const std::size_t ns = shells.size();
  std::vector<std::vector<char>> inside(ns, std::vector<char>(ns, 0));
  for (std::size_t s = 0; s < ns; ++s)
    for (std::size_t t = 0; t < ns; ++t)
      if (s != t) inside[s][t] = std::abs(winding(in.nodes, shells[t], shells[s].point)) > 0.5;
  auto larger = [&](std::size_t t, std::size_t s) { return shells[t].volume > shells[s].volume * (1 + 1e-9); };

  // Within a region, a shell inside an odd number of the region's larger shells bounds a hollow.
  std::vector<double> net(nr, 0.0);
  std::vector<char> outer(ns, 0);
  for (std::size_t s = 0; s < ns; ++s) {
    int depth = 0;
    for (std::size_t t = 0; t < ns; ++t)
      if (t != s && shells[t].region == shells[s].region && larger(t, s) && inside[s][t]) ++depth;
    net[shells[s].region] += depth % 2 ? -shells[s].volume : shells[s].volume;
    outer[s] = depth == 0;
  }
  // Other regions: each outer shell belongs in the smallest larger shell of another region that
  // holds it; its volume leaves that region when it sits in that region's material (inside an
  // odd number of its shells: not in a hollow it already left out, nor the same surface listed
  // as its inner boundary).
  std::vector<double> largest(nr, -1.0);
  std::vector<double> taken(nr, 0.0);
  for (std::size_t s = 0; s < ns; ++s) {
    if (!outer[s]) continue;
    std::size_t holder = ns;
    for (std::size_t t = 0; t < ns; ++t)
      if (shells[t].region != shells[s].region && larger(t, s) && inside[s][t] &&
          (holder == ns || shells[t].volume < shells[holder].volume))
        holder = t;
    const Index r = shells[s].region;
    if (shells[s].volume > largest[r]) {  // a region lies where its largest outer shell lies
      largest[r] = shells[s].volume;
      sum.regions[r].inside = holder == ns ? -1 : shells[holder].region;
    }
    if (holder == ns) continue;
    const Index h = shells[holder].region;
    int count = 0;
    for (std::size_t t = 0; t < ns; ++t)
      if (shells[t].region == h && inside[s][t]) ++count;
    if (count % 2) taken[h] += shells[s].volume;
  }
  for (Index r = 0; r < nr; ++r) {
    sum.regions[r].volume = net[r] - taken[r];
    if (!sum.regions[r].cavity) sum.volume += sum.regions[r].volume;
  }
  return sum;
}

}  // namespace bisect
