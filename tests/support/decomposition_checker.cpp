#include "decomposition_checker.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <unordered_map>

namespace bisect::testing {
namespace {

struct Plane {
  Vec3 n;     // unit
  double c;   // n · x = c
};

Vec3 newell(const std::vector<Vec3>& p, const std::vector<Index>& loop) {
  Vec3 n = Vec3::Zero();
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec3 &a = p[loop[i]], &b = p[loop[(i + 1) % loop.size()]];
    n += Vec3((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()), (a.x() - b.x()) * (a.y() + b.y()));
  }
  return n;
}

// A face of a file: its loops (outer first), gathered from hole_of.
struct FileFace {
  std::vector<std::vector<Index>> loops;
  Plane plane;
  double area = 0;  // net
};

std::vector<FileFace> gather(const PolyInput& in, std::vector<Index>* face_of) {
  std::vector<FileFace> out;
  face_of->assign(in.faces.size(), -1);
  for (std::size_t f = 0; f < in.faces.size(); ++f) {
    if (in.faces[f].hole_of >= 0) continue;
    (*face_of)[f] = static_cast<Index>(out.size());
    FileFace ff;
    ff.loops.push_back(in.faces[f].nodes);
    out.push_back(ff);
  }
  for (std::size_t f = 0; f < in.faces.size(); ++f)
    if (in.faces[f].hole_of >= 0) {
      Index parent = in.faces[f].hole_of;  // a hole of a hole still belongs to the outer face
      for (int guard = 0; in.faces[parent].hole_of >= 0 && guard < 100; ++guard) parent = in.faces[parent].hole_of;
      if (in.faces[parent].hole_of >= 0) continue;
      (*face_of)[f] = (*face_of)[parent];
      out[(*face_of)[f]].loops.push_back(in.faces[f].nodes);
    }
  for (FileFace& ff : out) {
    const Vec3 n = newell(in.nodes, ff.loops[0]);
    ff.plane.n = n.normalized();
    Vec3 c = Vec3::Zero();
    for (Index v : ff.loops[0]) c += in.nodes[v];
    ff.plane.c = ff.plane.n.dot(c / static_cast<double>(ff.loops[0].size()));
    ff.area = 0.5 * n.norm();
    for (std::size_t l = 1; l < ff.loops.size(); ++l) ff.area -= 0.5 * newell(in.nodes, ff.loops[l]).norm();
  }
  return out;
}

// 2D frame of a plane.
struct Frame {
  Vec3 u, v;
  explicit Frame(const Vec3& n) {
    const Vec3 a = std::abs(n.x()) < 0.5 ? Vec3::UnitX() : Vec3::UnitY();
    u = n.cross(a).normalized();
    v = n.cross(u);
  }
  Vec2 at(const Vec3& p) const { return {p.dot(u), p.dot(v)}; }
};

bool inside_loops(const Vec2& p, const std::vector<std::vector<Vec2>>& loops) {
  bool in = false;
  for (const auto& l : loops)
    for (std::size_t i = 0, j = l.size() - 1; i < l.size(); j = i++)
      if ((l[i].y() > p.y()) != (l[j].y() > p.y()) &&
          p.x() < l[j].x() + (p.y() - l[j].y()) * (l[i].x() - l[j].x()) / (l[i].y() - l[j].y()))
        in = !in;
  return in;
}

// A point well inside a planar polygon with holes: the middle of the longest inside interval of
// a horizontal line through the middle of its extent.
Vec2 inner_point(const std::vector<std::vector<Vec2>>& loops) {
  double lo = 1e300, hi = -1e300;
  for (const auto& l : loops)
    for (const Vec2& p : l) lo = std::min(lo, p.y()), hi = std::max(hi, p.y());
  Vec2 best(0, 0);
  double width = -1;
  for (double frac : {0.5, 0.37, 0.61, 0.23, 0.79}) {
    const double y = lo + frac * (hi - lo);
    std::vector<double> xs;
    for (const auto& l : loops)
      for (std::size_t i = 0, j = l.size() - 1; i < l.size(); j = i++)
        if ((l[i].y() > y) != (l[j].y() > y))
          xs.push_back(l[j].x() + (y - l[j].y()) * (l[i].x() - l[j].x()) / (l[i].y() - l[j].y()));
    std::sort(xs.begin(), xs.end());
    for (std::size_t i = 0; i + 1 < xs.size(); i += 2)
      if (xs[i + 1] - xs[i] > width) width = xs[i + 1] - xs[i], best = Vec2(0.5 * (xs[i] + xs[i + 1]), y);
    if (width > 0) break;
  }
  return best;
}

std::string at(const Vec3& p) {
  std::ostringstream s;
  s.precision(6);
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

}  // namespace

std::vector<Index> cell_regions_of_file(const std::string& path) {
  std::ifstream in(path);
  std::vector<Index> out;
  std::string line;
  while (std::getline(in, line)) {
    long cell = 0, region = 0;
    if (std::sscanf(line.c_str(), "-- cell %ld of input region %ld", &cell, &region) == 2) {
      if (cell != static_cast<long>(out.size()) + 1) return {};
      out.push_back(static_cast<Index>(region - 1));
    }
  }
  return out;
}

CellCheck check_decomposition(const PolyInput& input, const PolyInput& cells, const std::vector<Index>& cell_region,
                              double geom_tol, double measure_tol) {
  CellCheck res;
  auto problem = [&](const std::string& s) {
    if (res.problems.size() < 50) res.problems.push_back(s);
  };
  res.cells = cells.regions.size();
  if (cell_region.size() != cells.regions.size()) {
    problem("the cells file names the input region of " + std::to_string(cell_region.size()) + " of its " +
            std::to_string(cells.regions.size()) + " cells");
    return res;
  }
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const Vec3& p : input.nodes) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double size = (hi - lo).norm(), tol = geom_tol * size;

  std::vector<Index> cface_of, iface_of;
  const std::vector<FileFace> cf = gather(cells, &cface_of);
  const std::vector<FileFace> inf = gather(input, &iface_of);
  const PolySummary in_sum = summarize(input);

  // (a, b) per cell: closed, planar, convex, positive volume.
  std::vector<std::vector<Index>> cell_faces(cells.regions.size());
  std::vector<int> users(cf.size(), 0);
  std::vector<std::vector<int>> outward(cells.regions.size());
  std::vector<double> region_volume(input.regions.size(), 0);
  for (std::size_t c = 0; c < cells.regions.size(); ++c) {
    std::vector<Index>& faces = cell_faces[c];
    for (Index f : cells.regions[c].faces)
      if (std::find(faces.begin(), faces.end(), cface_of[f]) == faces.end()) faces.push_back(cface_of[f]);
    Vec3 centre = Vec3::Zero();
    std::size_t count = 0;
    for (Index f : faces)
      for (const auto& l : cf[f].loops)
        for (Index v : l) centre += cells.nodes[v], ++count;
    centre /= static_cast<double>(std::max<std::size_t>(count, 1));
    std::map<std::pair<Index, Index>, int> directed;
    double volume = 0;
    for (Index f : faces) {
      ++users[f];
      const FileFace& F = cf[f];
      const int s = F.plane.n.dot(centre) < F.plane.c ? 1 : -1;  // +1: the normal points out
      outward[c].push_back(s);
      for (std::size_t l = 0; l < F.loops.size(); ++l) {
        // outer loops run counter-clockwise about the outward normal, holes clockwise
        const bool ccw = newell(cells.nodes, F.loops[l]).dot(F.plane.n) * s > 0;
        const bool want = l == 0;
        const auto& loop = F.loops[l];
        for (std::size_t i = 0; i < loop.size(); ++i) {
          Index a = loop[i], b = loop[(i + 1) % loop.size()];
          if (ccw != want) std::swap(a, b);
          ++directed[{a, b}];
          if (std::abs(F.plane.n.dot(cells.nodes[a]) - F.plane.c) > tol)
            problem("cell " + std::to_string(c + 1) + ": face " + std::to_string(f + 1) + " is not planar at node " +
                    std::to_string(a + 1));
        }
      }
      volume += s * F.plane.c * F.area / 3.0;
    }
    // closed: every edge used by exactly two of the cell's loops; oriented: in opposite
    // directions once each face points away from the centre (which only holds when convex, so
    // a failure there is reported with the convexity check below)
    std::map<std::pair<Index, Index>, int> undirected;
    bool oriented = true;
    for (const auto& [e, n] : directed) {
      undirected[{std::min(e.first, e.second), std::max(e.first, e.second)}] += n;
      const auto back = directed.find({e.second, e.first});
      oriented &= n == 1 && back != directed.end() && back->second == 1;
    }
    for (const auto& [e, n] : undirected)
      if (n != 2) {
        problem("cell " + std::to_string(c + 1) + " is not closed at the edge from node " + std::to_string(e.first + 1) +
                " " + at(cells.nodes[e.first]) + " to node " + std::to_string(e.second + 1));
        break;
      }
    if (!oriented) problem("cell " + std::to_string(c + 1) + ": its faces cannot all point away from its centre");
    for (std::size_t k = 0; k < faces.size(); ++k) {
      const FileFace& F = cf[faces[k]];
      for (const auto& [e, n] : directed) {
        const double d = outward[c][k] * (F.plane.n.dot(cells.nodes[e.first]) - F.plane.c);
        if (d > tol) {
          problem("cell " + std::to_string(c + 1) + " is not convex: node " + std::to_string(e.first + 1) + " " +
                  at(cells.nodes[e.first]) + " lies outside the plane of face " + std::to_string(faces[k] + 1));
          k = faces.size();
          break;
        }
      }
    }
    if (volume <= 0) problem("cell " + std::to_string(c + 1) + " has volume " + std::to_string(volume));
    const Index r = cell_region[c];
    if (r < 0 || r >= static_cast<Index>(input.regions.size()) || input.regions[r].cavity)
      problem("cell " + std::to_string(c + 1) + " comes from no meshable region");
    else
      region_volume[r] += volume;
  }
  // (c) volumes
  for (std::size_t r = 0; r < input.regions.size(); ++r) {
    if (input.regions[r].cavity) continue;
    const double want = in_sum.regions[r].volume;
    const double err = std::abs(region_volume[r] - want) / std::max(std::abs(want), 1e-300);
    res.max_volume_rel_error = std::max(res.max_volume_rel_error, err);
    if (err > measure_tol)
      problem("the cells of region " + std::to_string(r + 1) + " hold volume " + std::to_string(region_volume[r]) +
              ", the region " + std::to_string(want));
  }

  // (d, e) faces: shared by two cells, or on an input face; coverage of each input face.
  std::vector<std::vector<int>> face_cells(cf.size());
  for (std::size_t c = 0; c < cell_faces.size(); ++c)
    for (Index f : cell_faces[c]) face_cells[f].push_back(static_cast<int>(c));
  // input faces in a grid by bounding box, to find the one under a cell face
  const int cells_per_axis = std::max(1, static_cast<int>(std::cbrt(static_cast<double>(inf.size()))));
  const Vec3 span = (hi - lo).cwiseMax(Vec3::Constant(1e-300));
  auto cell_of = [&](const Vec3& p, int axis) {
    return std::clamp(static_cast<int>((p[axis] - lo[axis]) / span[axis] * cells_per_axis), 0, cells_per_axis - 1);
  };
  std::unordered_map<long long, std::vector<Index>> grid;
  auto key = [&](int i, int j, int k) { return (static_cast<long long>(i) * cells_per_axis + j) * cells_per_axis + k; };
  for (std::size_t f = 0; f < inf.size(); ++f) {
    Vec3 a = Vec3::Constant(1e300), b = Vec3::Constant(-1e300);
    for (Index v : inf[f].loops[0]) a = a.cwiseMin(input.nodes[v]), b = b.cwiseMax(input.nodes[v]);
    a -= Vec3::Constant(tol), b += Vec3::Constant(tol);
    for (int i = cell_of(a, 0); i <= cell_of(b, 0); ++i)
      for (int j = cell_of(a, 1); j <= cell_of(b, 1); ++j)
        for (int k = cell_of(a, 2); k <= cell_of(b, 2); ++k) grid[key(i, j, k)].push_back(static_cast<Index>(f));
  }
  std::vector<double> covered(inf.size(), 0);
  for (std::size_t f = 0; f < cf.size(); ++f) {
    const int n = static_cast<int>(face_cells[f].size());
    if (n == 0) continue;
    if (n > 2) {
      problem("face " + std::to_string(f + 1) + " of the cells file belongs to " + std::to_string(n) + " cells");
      continue;
    }
    // the input face under it, if any
    const FileFace& F = cf[f];
    const Frame fr(F.plane.n);
    std::vector<std::vector<Vec2>> l2;
    for (const auto& l : F.loops) {
      l2.emplace_back();
      for (Index v : l) l2.back().push_back(fr.at(cells.nodes[v]));
    }
    const Vec2 q = inner_point(l2);
    const Vec3 p = q.x() * fr.u + q.y() * fr.v + F.plane.c * F.plane.n;
    Index under = -1;
    for (Index g : grid[key(cell_of(p, 0), cell_of(p, 1), cell_of(p, 2))]) {
      const FileFace& G = inf[g];
      if (std::abs(std::abs(G.plane.n.dot(F.plane.n)) - 1) > 1e-6 || std::abs(G.plane.n.dot(p) - G.plane.c) > tol) continue;
      bool on_plane = true;
      for (const auto& l : F.loops)
        for (Index v : l) on_plane &= std::abs(G.plane.n.dot(cells.nodes[v]) - G.plane.c) <= tol;
      if (!on_plane) continue;
      const Frame gf(G.plane.n);
      std::vector<std::vector<Vec2>> g2;
      for (const auto& l : G.loops) {
        g2.emplace_back();
        for (Index v : l) g2.back().push_back(gf.at(input.nodes[v]));
      }
      if (inside_loops(gf.at(p), g2)) {
        under = g;
        break;
      }
    }
    if (under >= 0) {
      covered[under] += F.area;
      ++res.boundary_faces;
    }
    if (n == 2) {
      ++res.shared_faces;
      const int a = face_cells[f][0], b = face_cells[f][1];
      const auto sa = outward[a][std::find(cell_faces[a].begin(), cell_faces[a].end(), f) - cell_faces[a].begin()];
      const auto sb = outward[b][std::find(cell_faces[b].begin(), cell_faces[b].end(), f) - cell_faces[b].begin()];
      if (sa == sb) problem("cells " + std::to_string(a + 1) + " and " + std::to_string(b + 1) + " lie on the same side of face " + std::to_string(f + 1));
      if (cell_region[a] != cell_region[b] && under < 0)
        problem("face " + std::to_string(f + 1) + " joins cells of regions " + std::to_string(cell_region[a] + 1) + " and " +
                std::to_string(cell_region[b] + 1) + " but lies on no input face");
    } else if (under < 0) {
      problem("face " + std::to_string(f + 1) + " of cell " + std::to_string(face_cells[f][0] + 1) + " at " + at(p) +
              " is matched by no other cell and lies on no input face");
    }
  }
  for (std::size_t g = 0; g < inf.size(); ++g) {
    const double err = std::abs(covered[g] - inf[g].area) / std::max(inf[g].area, 1e-300);
    res.max_coverage_rel_error = std::max(res.max_coverage_rel_error, err);
    if (err > std::max(measure_tol, 1e-12)) {
      Index file_face = 0;
      for (std::size_t k = 0; k < iface_of.size(); ++k)
        if (iface_of[k] == static_cast<Index>(g) && input.faces[k].hole_of < 0) file_face = static_cast<Index>(k);
      problem("input face " + std::to_string(file_face + 1) + " (area " + std::to_string(inf[g].area) +
              ") is covered by cell faces of area " + std::to_string(covered[g]));
    }
  }
  return res;
}

}  // namespace bisect::testing
