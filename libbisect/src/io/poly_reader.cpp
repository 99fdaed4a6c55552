// Readers of the thesis formats: .poly (6.13) and .poly2 (4.6.1), and the dispatch of
// read_polyhedral on the file extension.
//
// Both formats are one record per line (a header, a node, a face, a region); a line that holds
// more or fewer numbers than its record needs is an error on that line, which catches a wrong
// count where it happens instead of letting it shift every later record. `--` starts a comment
// anywhere on a line. Nodes, faces and regions are numbered from 1 in the file and in messages.
#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <unordered_map>

#include "bisect/errors.hpp"
#include "bisect/io.hpp"
#include "io/file_paths.hpp"
#include "io/face_checks.hpp"
#include "io/polygon_checks.hpp"
#include "io/text_scan.hpp"

namespace bisect {
namespace {

using io::LineScanner;

constexpr std::int64_t kMaxCount = std::numeric_limits<Index>::max();
// Counts come from the file: reserve no more than this up front, so that a corrupt header
// claiming billions of nodes fails on its missing lines instead of exhausting memory.
constexpr std::int64_t kMaxReserve = std::int64_t(1) << 20;

std::ifstream open_text(const std::string& path) {
  io::check_readable_file(path);
  std::ifstream f(path);
  if (!f) throw InputError(path + ": cannot open the file (" + std::strerror(errno) + ")");
  return f;
}

std::int64_t count_field(const LineScanner& s, std::size_t i, const std::string& what, std::int64_t min) {
  const std::int64_t v = s.integer(i, what);
  if (v < min || v > kMaxCount)
    s.fail(what + " is " + std::to_string(v) + "; it must be at least " + std::to_string(min) +
           (v > kMaxCount ? " and fit a 32-bit index" : ""));
  return v;
}

// The 1-based node number at token i of the current line, checked against the node count.
Index node_ref(const LineScanner& s, std::size_t i, const std::string& owner, std::size_t nodes) {
  const std::int64_t v = s.integer(i, "a node number of " + owner);
  if (v < 1 || v > std::int64_t(nodes))
    s.fail(owner + " refers to node " + std::to_string(v) + ", but there are " + std::to_string(nodes) +
           " nodes (numbered from 1)");
  return Index(v - 1);
}

std::string header_hint(std::int64_t faces, std::int64_t nodes, std::int64_t regions) {
  return "; does the header (" + io::count_of(faces, "face", "faces") + ", " + io::count_of(nodes, "node", "nodes") +
         ", " + io::count_of(regions, "region", "regions") + ") match the file?";
}

// Thesis 6.13: a face coplanar with another face of the same region and lying inside it is that
// face's hole. For each such face, the smallest containing face of its region becomes hole_of.
void find_face_holes(PolyInput& in) {
  struct Info {
    Vec3 unit = Vec3::Zero(), centroid = Vec3::Zero(), lo, hi;
    double area = 0, tol = 0, offset = 0;
    int axis = 2;
  };
  Vec3 lo = in.nodes[0], hi = in.nodes[0];
  for (const Vec3& p : in.nodes) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const Vec3 mid = 0.5 * (lo + hi);
  std::vector<Info> info(in.faces.size());
  for (std::size_t f = 0; f < in.faces.size(); ++f) {
    const auto& v = in.faces[f].nodes;
    const io::FaceShape s = io::face_shape(in.nodes, v);
    Info& i = info[f];
    i.area = 0.5 * s.newell.norm();
    i.axis = io::dominant_axis(s.newell);
    // One direction per plane, so that coplanar faces given either way round share an offset.
    i.unit = s.newell.normalized() * (s.newell[i.axis] < 0 ? -1.0 : 1.0);
    i.centroid = s.centroid;
    i.offset = i.unit.dot(s.centroid - mid);
    i.tol = std::max(io::kPlanarityRelTol * s.diameter, io::kRoundoffFloor * s.scale);
    i.lo = i.hi = in.nodes[v[0]];
    for (Index n : v) i.lo = i.lo.cwiseMin(in.nodes[n]), i.hi = i.hi.cwiseMax(in.nodes[n]);
  }
  // Candidates are the faces of nearly the same plane, found through a hash of (normal, offset)
  // cells. The margins are far wider than the planarity tolerance (a small hole's own normal may
  // tilt within it) and the exact test below decides; a neighbouring cell is looked at only when
  // the face lies within the margin of its border, so a lookup or two per face is the rule.
  const double diag = (hi - lo).norm();
  const double cell[4] = {1e-3, 1e-3, 1e-3, 1e-3 * diag};
  const double margin[4] = {2e-4, 2e-4, 2e-4, 1e-4 * diag};
  using Key = std::array<std::int64_t, 4>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = 0;
      for (std::int64_t x : k) {  // splitmix64 steps: the cells are dense small integers
        h += std::uint64_t(x) + 0x9e3779b97f4a7c15ULL;
        h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
        h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
        h ^= h >> 31;
      }
      return std::size_t(h);
    }
  };
  auto coords = [](const Vec3& unit, double offset) { return std::array<double, 4>{unit.x(), unit.y(), unit.z(), offset}; };
  auto key_of = [&](const std::array<double, 4>& c) {
    Key k;
    for (int i = 0; i < 4; ++i) k[i] = std::int64_t(std::floor(c[i] / cell[i]));
    return k;
  };
  for (const PolyRegion& region : in.regions) {
    std::unordered_map<Key, std::vector<Index>, KeyHash> cells;
    for (Index f : region.faces) cells[key_of(coords(info[f].unit, info[f].offset))].push_back(f);
    for (Index h : region.faces) {
      const Info& hi = info[h];
      Index best = -1;
      std::vector<Index> near;
      // Both signs: the canonical direction can differ between two nearly equal normals whose
      // largest components are nearly tied.
      for (const auto& c : {coords(hi.unit, hi.offset), coords(-hi.unit, -hi.offset)}) {
        const Key base = key_of(c);
        std::array<int, 4> lo_step{}, hi_step{};
        for (int i = 0; i < 4; ++i) {
          lo_step[i] = c[i] - double(base[i]) * cell[i] < margin[i] ? -1 : 0;
          hi_step[i] = double(base[i] + 1) * cell[i] - c[i] < margin[i] ? 1 : 0;
        }
        Key k;
        for (k[0] = base[0] + lo_step[0]; k[0] <= base[0] + hi_step[0]; ++k[0])
          for (k[1] = base[1] + lo_step[1]; k[1] <= base[1] + hi_step[1]; ++k[1])
            for (k[2] = base[2] + lo_step[2]; k[2] <= base[2] + hi_step[2]; ++k[2])
              for (k[3] = base[3] + lo_step[3]; k[3] <= base[3] + hi_step[3]; ++k[3]) {
                const auto it = cells.find(k);
                if (it != cells.end()) near.insert(near.end(), it->second.begin(), it->second.end());
              }
      }
      for (Index p : near) {
        const Info& pi = info[p];
        if (p == h || !(pi.area > hi.area) || std::abs(pi.unit.dot(hi.unit)) < 1 - 1e-8) continue;
        const Vec3 slack = Vec3::Constant(pi.tol);
        if ((hi.lo.array() < (pi.lo - slack).array()).any() || (hi.hi.array() > (pi.hi + slack).array()).any())
          continue;
        // A hole lies inside and shares no node with the face: a coplanar neighbour that shares
        // an edge with it (two pieces of one side of a convex cell, say) is no hole.
        bool inside = true;
        for (Index n : in.faces[h].nodes) {
          if (std::abs(pi.unit.dot(in.nodes[n] - pi.centroid)) > pi.tol) inside = false;
          if (std::find(in.faces[p].nodes.begin(), in.faces[p].nodes.end(), n) != in.faces[p].nodes.end()) inside = false;
        }
        if (!inside) continue;
        std::vector<Vec2> polygon;
        for (Index n : in.faces[p].nodes) polygon.push_back(io::project(in.nodes[n], pi.axis));
        for (Index n : in.faces[h].nodes)
          if (io::locate_in_polygon(polygon, io::project(in.nodes[n], pi.axis), pi.tol) < 0) inside = false;
        if (inside && (best < 0 || pi.area < info[best].area)) best = p;
      }
      if (best >= 0 && in.faces[h].hole_of < 0) in.faces[h].hole_of = best;
    }
  }
}

}  // namespace

PolyInput read_poly(std::istream& stream, const std::string& name) {
  LineScanner s(stream, name, "--");
  PolyInput in;
  in.source = name;
  s.first("the header 'faces nodes regions required_elements'");
  // The thesis's second listing starts with a title line ("Re-entry box"); allow one.
  double probe = 0;
  if (!io::parse_real(s.token(0), probe))
    s.expect("the header 'faces nodes regions required_elements' (after the title line)");
  if (s.size() != 4 && s.size() != 3)
    s.fail("the header must hold 4 numbers: faces, nodes, regions, required elements; found " +
           io::count_of(s.size(), "number", "numbers") + " ('" + s.rest(0) + "')");
  const std::int64_t nf = count_field(s, 0, "the face count", 1);
  const std::int64_t nn = count_field(s, 1, "the node count", 3);
  const std::int64_t nr = count_field(s, 2, "the region count", 1);
  in.required_elements = s.size() == 4 ? s.integer(3, "the required number of elements") : 0;
  if (in.required_elements < 0)
    s.fail("the required number of elements is " + std::to_string(in.required_elements) + "; it cannot be negative");
  const std::string hint = header_hint(nf, nn, nr);

  in.nodes.reserve(std::min(nn, kMaxReserve));
  for (std::int64_t i = 1; i <= nn; ++i) {
    const std::string node = "node " + std::to_string(i);
    s.expect(node + " (the header says " + io::count_of(nn, "node", "nodes") + ")");
    if (s.size() != 3)
      s.fail(node + " has " + io::count_of(s.size(), "number", "numbers") + " ('" + s.rest(0) +
             "'); a node is 3 coordinates x y z" + hint);
    in.nodes.emplace_back(s.real(0, "the x coordinate of " + node), s.real(1, "the y coordinate of " + node),
                          s.real(2, "the z coordinate of " + node));
  }

  const io::Naming naming;
  std::vector<int> face_line;
  in.faces.reserve(std::min(nf, kMaxReserve));
  for (std::int64_t i = 1; i <= nf; ++i) {
    const std::string face = "face " + std::to_string(i);
    s.expect(face + " (the header says " + io::count_of(nf, "face", "faces") + ")");
    const std::int64_t k = s.integer(0, "the node count of " + face);
    PolyFace pf;
    if (k >= 0 && std::int64_t(s.size()) - 1 == k)
      for (std::size_t t = 1; t < s.size(); ++t) pf.nodes.push_back(node_ref(s, t, face, in.nodes.size()));
    if (k < 3) s.fail(face + " has " + io::count_of(k, "node", "nodes") + "; a face needs at least 3");
    if (std::int64_t(s.size()) - 1 != k)
      s.fail(face + " says it has " + std::to_string(k) + " nodes but lists " + std::to_string(s.size() - 1) +
             (std::int64_t(s.size()) - 1 < k ? "" : hint));
    in.faces.push_back(std::move(pf));
    face_line.push_back(s.line());
  }

  std::vector<std::vector<Index>> regions_of_face(in.faces.size());
  std::vector<int> region_line;
  for (std::int64_t i = 1; i <= nr; ++i) {
    const std::string region = "region " + std::to_string(i);
    s.expect(region + hint);
    const std::int64_t k = s.integer(0, "the face count of " + region);
    if (k < -kMaxCount || k > kMaxCount) s.fail("the face count of " + region + " is out of range");
    PolyRegion pr;
    pr.cavity = k < 0;
    const std::int64_t listed = std::int64_t(s.size()) - 1;
    if (k == 0) s.fail(region + " has no faces");
    if (listed != std::abs(k))
      s.fail(region + " says it has " + std::to_string(std::abs(k)) + " faces but lists " + std::to_string(listed) +
             (listed < std::abs(k) ? "" : hint));
    for (std::size_t t = 1; t < s.size(); ++t) {
      const std::int64_t v = s.integer(t, "a face number of " + region);
      if (v < 1 || v > std::int64_t(in.faces.size()))
        s.fail(region + " refers to face " + std::to_string(v) + ", but there are " +
               std::to_string(in.faces.size()) + " faces (numbered from 1)" + hint);
      const Index f = Index(v - 1);
      auto& owners = regions_of_face[f];
      if (!owners.empty() && owners.back() == Index(i - 1)) s.fail(region + " lists face " + std::to_string(v) + " twice");
      owners.push_back(Index(i - 1));
      if (owners.size() > 2)
        s.fail("face " + std::to_string(v) + " belongs to regions " + std::to_string(owners[0] + 1) + ", " +
               std::to_string(owners[1] + 1) + " and " + std::to_string(i) +
               "; a face can bound at most two regions");
      pr.faces.push_back(f);
    }
    in.regions.push_back(std::move(pr));
    region_line.push_back(s.line());
  }
  if (s.next())
    s.fail("extra data after the last region: '" + s.rest(0) + "'" + hint);
  // Geometry only once the layout is known to match the header: a miscount turns a region line
  // into a "face", and the count is what the message should then be about.
  for (std::size_t f = 0; f < in.faces.size(); ++f) {
    const std::string at = io::where(name, face_line[f]);
    io::check_distinct_nodes(in.faces[f].nodes, Index(f), at, naming);
    io::check_face_shape(in.nodes, in.faces[f].nodes, Index(f), at, naming, true);
  }
  for (std::size_t f = 0; f < in.faces.size(); ++f)
    if (regions_of_face[f].empty())
      io::fail(name, face_line[f], "face " + std::to_string(f + 1) + " belongs to no region");

  find_face_holes(in);

  // Every region must be a closed surface (ARCHITECTURE.md 4: open shells are bad input). A hole's
  // edges are exempt: they also bound the inner loop of the face the hole lies in, which is how a
  // hole face listed only to mark an interface (and not closing a pocket) still closes.
  std::vector<bool> is_hole(in.faces.size());
  for (std::size_t f = 0; f < in.faces.size(); ++f) is_hole[f] = in.faces[f].hole_of >= 0;
  for (std::size_t r = 0; r < in.regions.size(); ++r) {
    if (auto e = io::first_odd_edge(in.faces, in.regions[r].faces, &is_hole))
      io::fail(name, region_line[r], "region " + std::to_string(r + 1) + " is not closed: " +
                                         io::describe(*e, in.nodes, naming) + " of the region");
  }
  return in;
}

PolyInput read_poly(const std::string& path) {
  std::ifstream f = open_text(path);
  return read_poly(f, path);
}

Poly2Input read_poly2(std::istream& stream, const std::string& name) {
  LineScanner s(stream, name, "--");
  Poly2Input in;
  in.source = name;
  s.first("the required number of elements");
  if (s.size() != 1)
    s.fail("the first line must hold one number, the required number of elements; found '" + s.rest(0) + "'");
  in.required_elements = s.integer(0, "the required number of elements");
  if (in.required_elements < 0)
    s.fail("the required number of elements is " + std::to_string(in.required_elements) + "; it cannot be negative");
  s.expect("the line 'nodes polygons'");
  if (s.size() != 2) s.fail("expected 2 numbers, the node and polygon counts; found '" + s.rest(0) + "'");
  const std::int64_t nn = count_field(s, 0, "the node count", 3);
  const std::int64_t np = count_field(s, 1, "the polygon count", 1);
  const std::string hint = "; does the line 'nodes polygons' (" + std::to_string(nn) + " " + std::to_string(np) +
                           ") match the file?";

  s.expect("the node counts of the " + io::count_of(np, "polygon", "polygons"));
  if (std::int64_t(s.size()) != np)
    s.fail("expected " + io::count_of(np, "node count", "node counts") + " (one per polygon), found " +
           std::to_string(s.size()) + " ('" + s.rest(0) + "')");
  std::vector<std::int64_t> sizes;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const std::string polygon = "polygon " + std::to_string(i + 1);
    const std::int64_t k = s.integer(i, "the node count of " + polygon);
    if (k < -kMaxCount || k > kMaxCount) s.fail("the node count of " + polygon + " is out of range");
    if (std::abs(k) < 3)
      s.fail(polygon + " has " + io::count_of(std::abs(k), "node", "nodes") + "; a polygon needs at least 3");
    sizes.push_back(k);
  }

  in.nodes.reserve(std::min(nn, kMaxReserve));
  for (std::int64_t i = 1; i <= nn; ++i) {
    const std::string node = "node " + std::to_string(i);
    s.expect(node + " (the file says " + io::count_of(nn, "node", "nodes") + ")");
    if (s.size() != 2)
      s.fail(node + " has " + io::count_of(s.size(), "number", "numbers") + " ('" + s.rest(0) +
             "'); a node is 2 coordinates x y" + hint);
    in.nodes.emplace_back(s.real(0, "the x coordinate of " + node), s.real(1, "the y coordinate of " + node));
  }

  std::vector<int> line_of;
  for (std::int64_t i = 1; i <= np; ++i) {
    const std::string polygon = "polygon " + std::to_string(i);
    s.expect(polygon + " (the file says " + io::count_of(np, "polygon", "polygons") + ")");
    const std::int64_t k = std::abs(sizes[i - 1]);
    if (std::int64_t(s.size()) != k)
      s.fail(polygon + " should list " + std::to_string(k) + " nodes (its count on the third line) but lists " +
             std::to_string(s.size()) + (std::int64_t(s.size()) < k ? "" : hint));
    Poly2Input::Polygon p;
    p.hole = sizes[i - 1] < 0;
    for (std::size_t t = 0; t < s.size(); ++t) p.nodes.push_back(node_ref(s, t, polygon, in.nodes.size()));
    io::Naming naming;
    naming.face = "polygon", naming.faces = "polygons";
    io::check_distinct_nodes(p.nodes, Index(i - 1), io::where(name, s.line()), naming);
    double twice_area = 0, diameter = 0;
    Vec2 lo = in.nodes[p.nodes[0]], hi = lo;
    for (std::size_t a = 0; a < p.nodes.size(); ++a) {
      const Vec2 u = in.nodes[p.nodes[a]] - in.nodes[p.nodes[0]];  // local, for less cancellation
      const Vec2 v = in.nodes[p.nodes[(a + 1) % p.nodes.size()]] - in.nodes[p.nodes[0]];
      twice_area += u.x() * v.y() - v.x() * u.y();
      lo = lo.cwiseMin(in.nodes[p.nodes[a]]), hi = hi.cwiseMax(in.nodes[p.nodes[a]]);
      if (p.nodes.size() <= 256)  // beyond, the box's diagonal (the pairwise scan is quadratic)
        for (std::size_t b = a + 1; b < p.nodes.size(); ++b)
          diameter = std::max(diameter, (in.nodes[p.nodes[b]] - in.nodes[p.nodes[a]]).norm());
    }
    if (p.nodes.size() > 256) diameter = (hi - lo).norm();
    if (!(std::abs(twice_area) > io::kZeroAreaRelTol * diameter * diameter))
      s.fail(polygon + " has zero area (its nodes are collinear or coincide, or it folds onto itself)");
    io::check_simple_polygon(in.nodes, p.nodes, Index(i - 1), io::where(name, s.line()));
    in.polygons.push_back(std::move(p));
    line_of.push_back(s.line());
  }
  if (s.next()) s.fail("extra data after the last polygon: '" + s.rest(0) + "'" + hint);

  // A hole (negative count) must lie in some region polygon, or it is a hole in nothing.
  for (std::size_t h = 0; h < in.polygons.size(); ++h) {
    if (!in.polygons[h].hole) continue;
    bool held = false;
    for (std::size_t p = 0; p < in.polygons.size() && !held; ++p) {
      if (in.polygons[p].hole) continue;
      std::vector<Vec2> outline;
      double size = 0;
      for (Index n : in.polygons[p].nodes) outline.push_back(in.nodes[n]);
      for (const Vec2& q : outline) size = std::max(size, (q - outline[0]).norm());
      held = true;
      for (Index n : in.polygons[h].nodes)
        if (io::locate_in_polygon(outline, in.nodes[n], io::kPlanarityRelTol * size) < 0) held = false;
    }
    if (!held)
      io::fail(name, line_of[h], "polygon " + std::to_string(h + 1) + " is a hole (negative node count) but lies "
                                 "inside no region polygon");
  }
  return in;
}

Poly2Input read_poly2(const std::string& path) {
  std::ifstream f = open_text(path);
  return read_poly2(f, path);
}

PolyInput read_polyhedral(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  std::string ext = dot == std::string::npos || (slash != std::string::npos && dot < slash) ? "" : path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".poly") return read_poly(path);
  if (ext == ".stl") return read_stl(path);
  if (ext == ".off") return read_off(path);
  if (ext == ".poly2")
    throw InputError(path + ": a .poly2 file is a 2D input (thesis 4.6.1), not a polyhedral one");
  throw InputError(path + ": unknown polyhedral format '" + ext + "' (expected .poly, .stl or .off)");
}

}  // namespace bisect
