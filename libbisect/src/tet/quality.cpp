// Tetrahedral quality measures (quality.hpp, ARCHITECTURE.md §3, thesis 2.4 and 8.3.1).
#include "bisect/quality.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>

#include "bisect/errors.hpp"
#include "geom/predicates.hpp"
#include "util/ordered_parallel.hpp"

namespace bisect {

namespace {

// β of thesis 2.4.2: 72·3·√3 = 374.1229744..., so the regular tetrahedron grades 1 to ~1e-7.
constexpr double kGoodnessBeta = 374.123;
constexpr double kPi = 3.14159265358979323846;
constexpr double kDegrees = 180.0 / kPi;

bool finite(const Vec3& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

}  // namespace

double triangle_min_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  // the smallest angle faces the shortest side (law of sines): one arctangent, not three (the
  // surface mesher grades every triangle it makes or smooths by this: three were 8% of a whole
  // run of lug at 10^5 on one thread)
  auto at = [](const Vec3& p, const Vec3& q, const Vec3& r) { return std::atan2((q - p).cross(r - p).norm(), (q - p).dot(r - p)); };
  const double bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm(), ab = (b - a).squaredNorm();
  if (bc <= ca && bc <= ab) return at(a, b, c);
  return ca <= ab ? at(b, c, a) : at(c, a, b);
}

double triangle_min_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c) { return triangle_min_angle(a, b, c) * kDegrees; }

double surface_min_angle_deg(const TetMesh& mesh) {
  double worst = 180;
  for (std::size_t t = 0; t < mesh.num_tris(); ++t) {
    const Index* v = &mesh.tris[mesh.nodes_per_tri() * t];
    worst = std::min(worst, triangle_min_angle_deg(mesh.nodes[v[0]], mesh.nodes[v[1]], mesh.nodes[v[2]]));
  }
  return worst;
}

double min_solid_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return 2 * std::atan(min_solid_angle_tan_half(a, b, c, d));
}

double signed_min_solid_angle_tan_half(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // Van Oosterom–Strackee at each corner i with edge vectors x, y, z of lengths X, Y, Z:
  // tan(Ω/2) = 6V / (XYZ + (x·y) Z + (x·z) Y + (y·z) X). One determinant and six lengths serve
  // the four corners and one division the minimum (this is the min-max criterion's key, the
  // generator's hottest function). The smallest corner angle of a tetrahedron is below π (the
  // four add up to at most 2π), so its denominator is positive and the ratio is monotone in Ω:
  // the largest positive denominator gives the smallest angle.
  const Vec3 ab = b - a, ac = c - a, ad = d - a, bc = c - b, bd = d - b, cd = d - c;
  const double lab = ab.norm(), lac = ac.norm(), lad = ad.norm(), lbc = bc.norm(), lbd = bd.norm(), lcd = cd.norm();
  // six times the signed volume: the denominators below are the same for a mirrored tetrahedron
  const double six_v = ab.dot(ac.cross(ad));
  // corner a: ab, ac, ad; b: -ab, bc, bd; c: -ac, -bc, cd; d: -ad, -bd, -cd
  const double da = lab * lac * lad + ab.dot(ac) * lad + ab.dot(ad) * lac + ac.dot(ad) * lab;
  const double db = lab * lbc * lbd - ab.dot(bc) * lbd - ab.dot(bd) * lbc + bc.dot(bd) * lab;
  const double dc = lac * lbc * lcd + ac.dot(bc) * lcd - ac.dot(cd) * lbc - bc.dot(cd) * lac;
  const double dd = lad * lbd * lcd + ad.dot(bd) * lcd + ad.dot(cd) * lbd + bd.dot(cd) * lad;
  const double most = std::max(std::max(da, db), std::max(dc, dd));
  return most > 0 ? six_v / most : 0;
}

double min_solid_angle_tan_half(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return std::abs(signed_min_solid_angle_tan_half(a, b, c, d));
}

TetQuality tet_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  TetQuality q;
  if (!finite(a) || !finite(b) || !finite(c) || !finite(d)) return q;
  // Exact: a tetrahedron the validator calls zero-volume grades 0 here too, whatever rounding
  // would make of its floating-point volume.
  const int sign = geom::orient3d(a, b, c, d);
  if (sign == 0) return q;
  q.volume = std::copysign(std::abs((b - a).dot((c - a).cross(d - a))) / 6.0, double(sign));

  // The shape measures are scale invariant: work relative to corner a in units of the longest
  // edge, so that neither V² ~ L⁶ nor S³ ~ L⁶ can overflow or underflow for any finite input.
  const std::array<Vec3, 4> raw{a, b, c, d};
  double longest = 0;
  for (const auto& e : kTetEdge) longest = std::max(longest, (raw[e[1]] - raw[e[0]]).norm());
  if (!(longest > 0) || !std::isfinite(longest)) return TetQuality{};
  std::array<Vec3, 4> p;
  for (int i = 0; i < 4; ++i) p[i] = (raw[i] - a) / longest;

  const Vec3 u = p[1], v = p[2], w = p[3];
  const double det = u.dot(v.cross(w));  // 6 V in units of the longest edge

  // Outward face normals for the positive orientation (inward for the mirror image: every
  // formula below uses them in pairs or through |n|, so reflection changes nothing).
  std::array<Vec3, 4> unit_normal;
  double area2 = 0;  // twice the surface area
  for (int f = 0; f < 4; ++f) {
    const auto& fv = kTetFace[f];
    const Vec3 n = (p[fv[1]] - p[fv[0]]).cross(p[fv[2]] - p[fv[0]]);
    const double len = n.norm();
    area2 += len;
    unit_normal[f] = len > 0 ? Vec3(n / len) : Vec3::Zero();
  }

  // Dihedral angle at edge ij: the faces through it are those opposite the other two corners
  // k and l; the interior angle is π minus the angle between their outward normals. atan2 of
  // |cross| and dot keeps full accuracy near 0° and 180°, where acos of a dot product loses it.
  double dmin = 180, dmax = 0;
  for (int e = 0; e < 6; ++e) {
    int other[2], m = 0;
    for (int k = 0; k < 4; ++k)
      if (k != kTetEdge[e][0] && k != kTetEdge[e][1]) other[m++] = k;
    const Vec3& nk = unit_normal[other[0]];
    const Vec3& nl = unit_normal[other[1]];
    const double angle = std::atan2(nk.cross(nl).norm(), -nk.dot(nl)) * kDegrees;
    dmin = std::min(dmin, angle);
    dmax = std::max(dmax, angle);
  }
  q.dihedral_min = dmin;
  q.dihedral_max = dmax;

  // Solid angle at each corner by Van Oosterom–Strackee on unit edge vectors:
  // tan(Ω/2) = |â·(b̂×ĉ)| / (1 + â·b̂ + â·ĉ + b̂·ĉ). atan2 puts Ω in [0, 2π) also when the
  // denominator is zero or negative (Ω ≥ π, a corner flattened into its opposite face).
  q.solid_angle_min = min_solid_angle(p[0], p[1], p[2], p[3]);

  // γ = β V² / S³ with V = det/6 and S = area2/2.
  const double area = area2 / 2;
  if (area > 0) q.gamma = kGoodnessBeta * (det * det / 36) / (area * area * area);

  q.alpha = alpha_from_edges(u, v, w, area);
  return q;
}

double alpha_from_edges(const Vec3& u, const Vec3& v, const Vec3& w, double area) {
  const double det = u.dot(v.cross(w));
  const Vec3 n = u.squaredNorm() * v.cross(w) + v.squaredNorm() * w.cross(u) + w.squaredNorm() * u.cross(v);
  const double nlen = n.norm();
  return area > 0 && nlen > 0 ? det * det / (area * nlen) : 0;
}

std::vector<TetQuality> element_quality(const TetMesh& mesh, const std::function<bool()>& cancelled, int threads) {
  const std::size_t nt = mesh.num_tets();
  const std::size_t nn = mesh.nodes.size();
  std::vector<TetQuality> out(nt);
  // in chunks of 4096 on the threads (about half a second at 10^6 on one), asked between chunks
  // whether to stop
  constexpr std::size_t kChunk = 4096;
  util::ordered_parallel(
      (nt + kChunk - 1) / kChunk, util::thread_count(threads),
      [&](std::size_t c) {
        for (std::size_t t = c * kChunk; t < std::min(nt, (c + 1) * kChunk); ++t) {
          Index v[4];
          bool ok = true;
          for (int i = 0; i < 4; ++i) {
            v[i] = mesh.tet_node(t, i);
            ok = ok && v[i] >= 0 && std::size_t(v[i]) < nn;
          }
          // A tetrahedron naming a missing node grades as degenerate; the validator names it.
          if (ok) out[t] = tet_quality(mesh.nodes[v[0]], mesh.nodes[v[1]], mesh.nodes[v[2]], mesh.nodes[v[3]]);
        }
      },
      [&](std::size_t) {
        if (cancelled && cancelled()) throw Cancelled();
      });
  return out;
}

namespace {

MeasureStats measure_stats(const std::vector<TetQuality>& q, double TetQuality::*field, double lo, double hi,
                           std::size_t bins) {
  MeasureStats s;
  s.lo = lo;
  s.hi = hi;
  s.histogram.assign(bins, 0);
  if (q.empty()) return s;
  s.min = q[0].*field;
  s.max = q[0].*field;
  double sum = 0;
  for (const auto& t : q) {
    const double x = t.*field;
    s.min = std::min(s.min, x);
    s.max = std::max(s.max, x);
    sum += x;
    // Multiply before dividing so that bin edges that are whole multiples land exactly
    // (10° of [0, 90] in 18 bins is 180/90 = 2, not 1.999...).
    const double pos = (x - lo) * double(bins) / (hi - lo);
    std::size_t bin = 0;
    if (pos >= double(bins)) bin = bins - 1;
    else if (pos > 0) bin = std::size_t(pos);  // NaN and values below lo fall into bin 0
    ++s.histogram[bin];
  }
  s.mean = sum / double(q.size());
  return s;
}

}  // namespace

QualitySummary summarize_quality(const std::vector<TetQuality>& q) {
  QualitySummary s;
  s.tets = q.size();
  s.dihedral_min = measure_stats(q, &TetQuality::dihedral_min, 0, 90, 18);
  s.dihedral_max = measure_stats(q, &TetQuality::dihedral_max, 0, 180, 18);
  s.solid_angle_min = measure_stats(q, &TetQuality::solid_angle_min, 0, 0.6, 12);
  s.gamma = measure_stats(q, &TetQuality::gamma, 0, 1, 10);
  s.alpha = measure_stats(q, &TetQuality::alpha, 0, 1.0 / 3.0, 10);
  std::size_t below = 0;
  for (const auto& t : q)
    if (t.dihedral_min < 10) ++below;
  s.pct_dihedral_below_10 = q.empty() ? 0 : 100.0 * double(below) / double(q.size());
  return s;
}

namespace {

// Locale independent (inside FreeCAD the C locale may use a decimal comma) and the shortest
// text that reads back to the same double. JSON has no NaN or infinity: those become null.
void append_number(std::string& out, double x) {
  if (!std::isfinite(x)) {
    out += "null";
    return;
  }
  char buf[32];
  auto res = std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, res.ptr);
}

void append_count(std::string& out, std::size_t n) {
  char buf[24];
  auto res = std::to_chars(buf, buf + sizeof buf, n);
  out.append(buf, res.ptr);
}

void append_key(std::string& out, const char* key) {
  out += '"';
  out += key;
  out += "\":";
}

void append_stats(std::string& out, const MeasureStats& m) {
  out += '{';
  append_key(out, "min");
  append_number(out, m.min);
  out += ',';
  append_key(out, "mean");
  append_number(out, m.mean);
  out += ',';
  append_key(out, "max");
  append_number(out, m.max);
  out += ',';
  append_key(out, "lo");
  append_number(out, m.lo);
  out += ',';
  append_key(out, "hi");
  append_number(out, m.hi);
  out += ',';
  append_key(out, "histogram");
  out += '[';
  for (std::size_t i = 0; i < m.histogram.size(); ++i) {
    if (i) out += ',';
    append_count(out, m.histogram[i]);
  }
  out += "]}";
}

}  // namespace

std::string quality_json(const QualitySummary& s) {
  std::string out = "{";
  append_key(out, "tets");
  append_count(out, s.tets);
  const std::pair<const char*, double> headline[] = {
      {"dihedral_min", s.dihedral_min.min},      {"dihedral_max", s.dihedral_max.max},
      {"solid_angle_min", s.solid_angle_min.min}, {"solid_angle_mean", s.solid_angle_min.mean},
      {"gamma_mean", s.gamma.mean},               {"gamma_min", s.gamma.min},
      {"alpha_mean", s.alpha.mean},               {"pct_dihedral_below_10", s.pct_dihedral_below_10},
  };
  for (const auto& [key, value] : headline) {
    out += ',';
    append_key(out, key);
    append_number(out, value);
  }
  out += ',';
  append_key(out, "measures");
  const std::pair<const char*, const MeasureStats*> measures[] = {
      {"dihedral_min", &s.dihedral_min}, {"dihedral_max", &s.dihedral_max},
      {"solid_angle_min", &s.solid_angle_min}, {"gamma", &s.gamma}, {"alpha", &s.alpha},
  };
  out += '{';
  for (std::size_t i = 0; i < std::size(measures); ++i) {
    if (i) out += ',';
    append_key(out, measures[i].first);
    append_stats(out, *measures[i].second);
  }
  out += "}}";
  return out;
}

}  // namespace bisect
