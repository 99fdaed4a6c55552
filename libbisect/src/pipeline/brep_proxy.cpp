#include "pipeline/brep_proxy.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "bisect/errors.hpp"

namespace bisect::pipeline {
namespace {

// The boundary loops of a set of triangles (edges used once), each in the triangles' direction.
std::vector<std::vector<Index>> boundary_loops(const std::vector<std::array<Index, 3>>& tris, const std::string& where) {
  std::map<std::pair<Index, Index>, int> count;
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) ++count[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  std::multimap<Index, Index> next;
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3];
      if (count[{std::min(a, b), std::max(a, b)}] == 1) next.emplace(a, b);
    }
  std::vector<std::vector<Index>> loops;
  while (!next.empty()) {
    auto it = next.begin();
    const Index start = it->first;
    std::vector<Index> loop{start};
    Index at = it->second;
    next.erase(it);
    while (at != start) {
      loop.push_back(at);
      auto nx = next.find(at);
      if (nx == next.end()) throw InputError(where + ": its tessellation has an open boundary at node " + std::to_string(at + 1));
      at = nx->second;
      next.erase(nx);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

double loop_area(const std::vector<Vec3>& X, const std::vector<Index>& loop, const Vec3& n) {
  Vec3 s = Vec3::Zero();
  for (std::size_t i = 0; i < loop.size(); ++i) s += X[loop[i]].cross(X[loop[(i + 1) % loop.size()]]);
  return 0.5 * s.dot(n);
}

// The point nearest p on every plane n . x = d given (least squares when they do not meet in one
// point): the node shared by planar faces is put on all of them.
Vec3 onto_planes(const Vec3& p, const std::vector<std::array<double, 4>>& planes) {
  const int k = static_cast<int>(planes.size());
  Eigen::MatrixXd N(k, 3);
  Eigen::VectorXd r(k);
  for (int i = 0; i < k; ++i) {
    N.row(i) << planes[i][0], planes[i][1], planes[i][2];
    r(i) = planes[i][0] * p.x() + planes[i][1] * p.y() + planes[i][2] * p.z() - planes[i][3];
  }
  // x = p - N^T (N N^T)^+ r: the smallest move that puts p on every plane
  const Eigen::MatrixXd G = N * N.transpose();
  const Eigen::VectorXd y = G.completeOrthogonalDecomposition().solve(r);
  return p - N.transpose() * y;
}

// The distance from the triangle's centroid to the surface (from the triangle's mean parameters).
double deviation(const ParametricSurface& s, const std::vector<Vec3>& X, const std::array<Index, 3>& t, const std::array<Vec2, 3>& uv) {
  const Vec3 c = (X[t[0]] + X[t[1]] + X[t[2]]) / 3;
  return (s.point(s.closest_point(c, (uv[0] + uv[1] + uv[2]) / 3)) - c).norm();
}

// A triangle whose corners lie on one line (to round-off): no area, no normal.
bool flat_in_space(const std::vector<Vec3>& X, const std::array<Index, 3>& t) {
  const Vec3 e1 = X[t[1]] - X[t[0]], e2 = X[t[2]] - X[t[0]], e3 = X[t[2]] - X[t[1]];
  const double longest = std::max({e1.squaredNorm(), e2.squaredNorm(), e3.squaredNorm()});
  return e1.cross(e2).norm() <= 1e-9 * longest;
}
// ... with three nodes (a pole's triangle, two corners one node, is left to the proxy's own rule)
bool mendable(const std::vector<Vec3>& X, const std::array<Index, 3>& t) {
  return t[0] != t[1] && t[1] != t[2] && t[2] != t[0] && flat_in_space(X, t);
}

// Lawson flips within one curved face: two triangles sharing an edge take the other diagonal
// when their centroids then lie nearer the surface. A tessellation made in (u, v) does not bend
// the way the surface does everywhere (round a sphere's pole it has edges that turn in, where the
// sphere turns out): the decomposition would cut at each, into slivers.
//
// These flips may make triangles flat in space (three corners on one line): on a cone they lie
// on the surface, so their deviation is nil. Round a half cone's apex (a degenerate edge, one
// point in space at every u) they made a fan from the apex to the nodes of one generatrix, whose
// triangles are segments of that line lying over each other, which the proxy's check reads as
// facets that cross (corpus/Block.brep's Face478, a countersink's tip: 48 pairs at every
// deflection, so Block is refused). With `mend`, no flip makes a flat triangle and a flat one
// is flipped with its neighbour whatever the deviation (two with area and one flat triangle
// fewer each time), the passes going on while any is left. Without, the flips are as they were:
// the shapes whose proxies mesh with flat facets (corpus/Kurbelwelle.brep's cones) keep their
// meshes, mended ones being no better there (45,032 tetrahedra and 3.1 degrees at 2*10^4 became
// 64,878 and 2.0). `flat` counts what is left flat.
void follow_surface(const ParametricSurface& s, const std::vector<Vec3>& X, BrepTessellation::Face& f, bool mend, std::size_t& flat) {
  flat = 0;
  for (const auto& t : f.tris) flat += mendable(X, t);
  for (std::size_t pass = 0; pass < 8 || (mend && flat > 0 && pass < 8 + f.tris.size()); ++pass) {
    std::map<std::pair<Index, Index>, std::pair<std::size_t, int>> edge;  // (a, b) directed -> (tri, corner opposite)
    for (std::size_t t = 0; t < f.tris.size(); ++t)
      for (int k = 0; k < 3; ++k) edge[{f.tris[t][(k + 1) % 3], f.tris[t][(k + 2) % 3]}] = {t, k};
    std::vector<char> touched(f.tris.size(), 0);
    std::size_t flips = 0;
    for (const auto& [ab, tk] : edge) {
      const auto other = edge.find({ab.second, ab.first});
      if (other == edge.end()) continue;
      const auto [t, k] = tk;
      const auto [n, j] = other->second;
      if (t > n || touched[t] || touched[n]) continue;
      const Index a = ab.first, b = ab.second, c = f.tris[t][k], d = f.tris[n][j];
      if (c == d || a == b) continue;
      const Vec2 ua = f.uv[t][(k + 1) % 3], ub = f.uv[t][(k + 2) % 3], uc = f.uv[t][k], ud = f.uv[n][j];
      // the shared nodes in the same chart on both sides (not a seam)
      if ((f.uv[n][(j + 2) % 3] - ua).norm() > 1e-12 * (1 + ua.norm()) || (f.uv[n][(j + 1) % 3] - ub).norm() > 1e-12 * (1 + ub.norm())) continue;
      // new triangles (c, a, d) and (d, b, c): counter-clockwise in (u, v)
      auto ccw = [](const Vec2& p, const Vec2& q, const Vec2& r) { return (q - p).x() * (r - p).y() - (q - p).y() * (r - p).x() > 0; };
      if (!ccw(uc, ua, ud) || !ccw(ud, ub, uc)) continue;
      const std::array<Index, 3> A{c, a, d}, B{d, b, c};
      const std::array<Vec2, 3> uA{uc, ua, ud}, uB{ud, ub, uc};
      if (mend ? flat_in_space(X, A) || flat_in_space(X, B)
               : (X[d] - X[c]).cross(X[a] - X[c]).norm() <= 0 || (X[b] - X[d]).cross(X[c] - X[d]).norm() <= 0)
        continue;
      // the new triangles face the way the surface does (within 60 degrees), so a flip never
      // folds the facets over each other
      auto faces_up = [&](const std::array<Index, 3>& tri, const std::array<Vec2, 3>& uv) {
        const Vec3 m = (X[tri[1]] - X[tri[0]]).cross(X[tri[2]] - X[tri[0]]);
        Vec3 du, dv;
        s.derivatives((uv[0] + uv[1] + uv[2]) / 3, &du, &dv);
        const Vec3 sn = du.cross(dv);
        return m.dot(sn) > 0.5 * m.norm() * sn.norm();
      };
      if (!faces_up(A, uA) || !faces_up(B, uB)) continue;
      const int was_flat = mendable(X, f.tris[t]) + mendable(X, f.tris[n]);
      const double now = std::max(deviation(s, X, f.tris[t], f.uv[t]), deviation(s, X, f.tris[n], f.uv[n]));
      const double then = std::max(deviation(s, X, A, uA), deviation(s, X, B, uB));
      if ((mend && was_flat > 0) || then < now * (1 - 1e-6)) {
        f.tris[t] = A, f.uv[t] = uA, f.tris[n] = B, f.uv[n] = uB;
        touched[t] = touched[n] = 1;
        ++flips;
        flat = flat + static_cast<std::size_t>(mendable(X, A) + mendable(X, B)) - static_cast<std::size_t>(was_flat);
      }
    }
    if (flips == 0) break;
  }
}

}  // namespace

BrepProxy make_proxy(const BrepInput& in, double linear, double angular, bool mend_flat) {
  BrepProxy px;
  px.linear = linear, px.angular = angular;
  px.tess = in.tessellate(linear, angular);
  for (std::size_t f = 0; f < in.faces.size() && f < px.tess.faces.size(); ++f)
    if (!in.faces[f].planar) {
      std::size_t flat = 0;
      follow_surface(*in.faces[f].surface, px.tess.nodes, px.tess.faces[f], mend_flat, flat);
      px.flat_facets += flat;
    }
  const BrepTessellation& t = px.tess;
  if (t.faces.size() != in.faces.size() || t.edges.size() != in.edges.size())
    throw MeshingError(in.source + ": the tessellation does not match the shape's faces and edges");
  std::vector<Vec3> X = t.nodes;
  // planes of the planar faces, and every node put exactly on the planes of its planar faces
  px.plane.assign(in.faces.size(), {0, 0, 0, 0});
  std::vector<std::vector<std::array<double, 4>>> node_planes(X.size());
  for (std::size_t f = 0; f < in.faces.size(); ++f) {
    if (!in.faces[f].planar || t.faces[f].tris.empty()) continue;
    const BrepFace& face = in.faces[f];
    const Vec2 mid = 0.5 * (face.surface->uv_min() + face.surface->uv_max());
    const Vec3 n = face.surface->normal(mid);
    const double d = n.dot(face.surface->point(mid));
    px.plane[f] = {n.x(), n.y(), n.z(), d};
    for (const auto& tri : t.faces[f].tris)
      for (Index v : tri)
        if (node_planes[v].empty() || node_planes[v].back() != px.plane[f]) node_planes[v].push_back(px.plane[f]);
  }
  for (std::size_t v = 0; v < X.size(); ++v)
    if (!node_planes[v].empty()) X[v] = onto_planes(X[v], node_planes[v]);
  px.input.nodes = X;
  px.input.source = in.source;
  std::vector<std::vector<Index>> faces_of_brep(in.faces.size());
  // only the faces of the solids meshed: a face of an open shell beside them, or of another
  // group of a compound's solids (meshed on its own, brep_generate.cpp), bounds nothing here
  std::vector<char> of_solid(in.faces.size(), 0);
  for (const BrepSolid& s : in.solids)
    for (Index f : s.faces) of_solid[f] = 1;
  for (std::size_t f = 0; f < in.faces.size(); ++f) {
    if (!of_solid[f]) continue;
    const auto& tris = t.faces[f].tris;
    if (tris.empty()) throw InputError(in.source + ": " + face_name(static_cast<Index>(f)) + " could not be tessellated (no triangles)");
    if (in.faces[f].planar) {
      // one polygon with holes: the largest loop is the outer one
      std::vector<std::vector<Index>> loops = boundary_loops(tris, in.source + ": " + face_name(static_cast<Index>(f)));
      const Vec3 n(px.plane[f][0], px.plane[f][1], px.plane[f][2]);
      std::size_t outer = 0;
      for (std::size_t l = 1; l < loops.size(); ++l)
        if (std::abs(loop_area(X, loops[l], n)) > std::abs(loop_area(X, loops[outer], n))) outer = l;
      const Index id = static_cast<Index>(px.input.faces.size());
      px.input.faces.push_back({loops[outer], -1});
      px.face_brep.push_back(static_cast<Index>(f)), px.face_tri.push_back(-1);
      faces_of_brep[f].push_back(id);
      for (std::size_t l = 0; l < loops.size(); ++l)
        if (l != outer) {
          faces_of_brep[f].push_back(static_cast<Index>(px.input.faces.size()));
          px.input.faces.push_back({loops[l], id});
          px.face_brep.push_back(static_cast<Index>(f)), px.face_tri.push_back(-1);
        }
    } else {
      for (std::size_t k = 0; k < tris.size(); ++k) {
        const auto& tri = tris[k];
        // a triangle with a repeated node (a pole's fan) has no area: the surface closes without it
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) continue;
        faces_of_brep[f].push_back(static_cast<Index>(px.input.faces.size()));
        px.input.faces.push_back({{tri[0], tri[1], tri[2]}, -1});
        px.face_brep.push_back(static_cast<Index>(f)), px.face_tri.push_back(static_cast<Index>(k));
      }
    }
  }
  // messages about the proxy name the B-rep faces (prepare's and the intersection check's)
  for (Index f : px.face_brep) px.input.face_label.push_back(face_name(f));
  for (const BrepSolid& s : in.solids) {
    PolyRegion r;
    for (Index f : s.faces) r.faces.insert(r.faces.end(), faces_of_brep[f].begin(), faces_of_brep[f].end());
    px.input.regions.push_back(std::move(r));
  }
  px.node_chords.assign(X.size(), {});
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    const auto& nodes = t.edges[e].nodes;
    for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
      px.node_chords[nodes[i]].push_back({static_cast<Index>(e), static_cast<Index>(i)});
      px.node_chords[nodes[i + 1]].push_back({static_cast<Index>(e), static_cast<Index>(i)});
    }
  }
  return px;
}

double angle_keeping_deflection(const BrepInput& in, const BrepProxy& px) {
  double linear = px.linear;
  const double keep = 1 - std::cos(0.5 * px.angular);
  for (std::size_t f = 0; f < in.faces.size() && f < px.tess.faces.size(); ++f) {
    if (in.faces[f].planar || !in.faces[f].surface) continue;
    const ParametricSurface& s = *in.faces[f].surface;
    const BrepTessellation::Face& face = px.tess.faces[f];
    for (std::size_t k = 0; k < face.tris.size(); ++k) {
      const auto& t = face.tris[k];
      if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
      const double kappa = s.max_curvature((face.uv[k][0] + face.uv[k][1] + face.uv[k][2]) / 3);
      if (!(kappa > 0) || !std::isfinite(kappa)) continue;
      const double height = keep / kappa;
      // a centroid lies nearer the surface than the chord's middle does (a cylinder's facet
      // across the angle: 0.88 of the chord height at 60 degrees): past it, the angle was not kept
      if (height < linear && deviation(s, px.tess.nodes, t, face.uv[k]) > height) linear = height;
    }
  }
  return linear;
}

}  // namespace bisect::pipeline
