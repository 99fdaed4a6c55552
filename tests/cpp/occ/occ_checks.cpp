#include "occ_checks.hpp"

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include "bisect/occ.hpp"
#include "occ_shape.hpp"

namespace bisect::test {
namespace {

// The parameter range of edge e (its curve's, or for a degenerate edge OpenCASCADE's own: the
// BrepInput has no curve there to ask).
std::pair<double, double> range_of(const BrepInput& in, Index e) {
  if (in.edges[e].curve) return {in.edges[e].curve->t_min(), in.edges[e].curve->t_max()};
  double a = 0, b = 0;
  BRep_Tool::Range(TopoDS::Edge(occ::occ_shape_of(in).edges(e + 1)), a, b);
  return {a, b};
}

Vec3 edge_point(const BrepInput& in, Index e, double t) {
  const BrepEdge& edge = in.edges[e];
  return edge.curve ? edge.curve->point(t) : in.vertices[edge.v0].point;
}

double signed_area(const std::array<Vec2, 3>& q) {
  return 0.5 * ((q[1] - q[0]).x() * (q[2] - q[0]).y() - (q[1] - q[0]).y() * (q[2] - q[0]).x());
}

}  // namespace

BrepInput input_of(const TopoDS_Shape& shape, const std::string& name) { return occ::brep_input_from_shape(shape, name); }

BrepInput input_through_string(const TopoDS_Shape& shape, const std::string& name) {
  std::ostringstream brep;
  BRepTools::Write(shape, brep);
  return load_brep_string(brep.str(), name);
}

double corner_volume(const TetMesh& m, std::size_t t) {
  const Vec3 &a = m.nodes[m.tet_node(t, 0)], &b = m.nodes[m.tet_node(t, 1)], &c = m.nodes[m.tet_node(t, 2)],
             &d = m.nodes[m.tet_node(t, 3)];
  return (b - a).dot((c - a).cross(d - a)) / 6;
}

double corner_volume(const TetMesh& m) {
  double v = 0;
  for (std::size_t t = 0; t < m.num_tets(); ++t) v += corner_volume(m, t);
  return v;
}

double size_of(const BrepInput& in) { return (in.bbox_max - in.bbox_min).norm(); }

double check_wires(const BrepInput& in) {
  const double slack = 1e-9 * size_of(in);
  double worst_gap = 0;
  int failures = 0;
  for (size_t f = 0; f < in.faces.size(); ++f) {
    const BrepFace& face = in.faces[f];
    EXPECT_FALSE(face.wires.empty()) << face_name(f);
    for (size_t w = 0; w < face.wires.size(); ++w) {
      const auto& wire = face.wires[w];
      for (size_t k = 0; k < wire.size(); ++k) {
        const BrepEdgeUse& use = wire[k];
        const BrepEdge& edge = in.edges[use.edge];
        const auto [t0, t1] = range_of(in, use.edge);
        const double tol = std::max(edge.tolerance, face.tolerance) + slack;
        for (int i = 0; i < 9; ++i) {
          // off the adapter's own sampling of the deviation (65 equidistant points)
          const double t = t0 + (t1 - t0) * (i + 0.37) / 9.0;
          const double d = (face.surface->point(use.pcurve->uv(t)) - edge_point(in, use.edge, t)).norm();
          if (d > tol && ++failures <= 5)
            ADD_FAILURE() << in.source << ": " << edge_name(use.edge) << " in " << face_name(f) << " at t = " << t
                          << ": the pcurve's point is " << d << " from the edge (tolerance " << tol << ")";
        }
        // the next use starts where this one ends: at the same vertex, and at the same point of the surface
        const BrepEdgeUse& next = wire[(k + 1) % wire.size()];
        const Index end = use.reversed ? edge.v0 : edge.v1;
        const Index start = next.reversed ? in.edges[next.edge].v1 : in.edges[next.edge].v0;
        if (end != start && ++failures <= 5)
          ADD_FAILURE() << in.source << ": " << face_name(f) << " wire " << w << ": " << edge_name(use.edge) << " ends at "
                        << vertex_name(end) << ", " << edge_name(next.edge) << " starts at " << vertex_name(start);
        const auto [n0, n1] = range_of(in, next.edge);
        const Vec3 a = face.surface->point(use.pcurve->uv(use.reversed ? t0 : t1));
        const Vec3 b = face.surface->point(next.pcurve->uv(next.reversed ? n1 : n0));
        const double gap = (a - b).norm();
        worst_gap = std::max(worst_gap, gap);
        const double vtol = 2 * in.vertices[end].tolerance + 2 * std::max(edge.tolerance, in.edges[next.edge].tolerance) + slack;
        if (gap > vtol && ++failures <= 5)
          ADD_FAILURE() << in.source << ": " << face_name(f) << " wire " << w << ": the pcurves of " << edge_name(use.edge)
                        << " and " << edge_name(next.edge) << " meet " << gap << " apart (tolerance " << vtol << ")";
      }
    }
  }
  return worst_gap;
}

void check_closest_points(const BrepInput& in) {
  const double size = size_of(in), slack = 1e-7 * size;
  int failures = 0;
  for (size_t f = 0; f < in.faces.size(); ++f) {
    const ParametricSurface& s = *in.faces[f].surface;
    const Vec2 lo = s.uv_min(), hi = s.uv_max();
    for (int i = 1; i <= 3; ++i)
      for (int j = 1; j <= 3; ++j) {
        const Vec2 uv = lo + Vec2(0.25 * i * (hi - lo).x(), 0.25 * j * (hi - lo).y());
        const Vec3 p = s.point(uv);
        const Vec2 guess = uv + 0.02 * (hi - lo);
        const double d = (s.point(s.closest_point(p, guess)) - p).norm();
        if (d > slack && ++failures <= 5)
          ADD_FAILURE() << in.source << ": " << face_name(f) << ": closest_point of the point at (" << uv.transpose()
                        << ") is " << d << " away";
        // a point off the surface: the answer is no farther than the point it was lifted from
        Vec3 du, dv;
        s.derivatives(uv, &du, &dv);
        const Vec3 n = du.cross(dv);
        if (!(n.norm() > 0)) continue;
        const double k = s.max_curvature(uv);
        const double lift = std::min(0.01 * size, k > 0 ? 0.2 / k : 0.01 * size);
        const Vec3 q = p + lift * n.normalized();
        const double dq = (s.point(s.closest_point(q, guess)) - q).norm();
        if (dq > lift * (1 + 1e-6) + slack && ++failures <= 5)
          ADD_FAILURE() << in.source << ": " << face_name(f) << ": closest_point of a point " << lift
                        << " off the surface is " << dq << " away";
      }
  }
  for (size_t e = 0; e < in.edges.size(); ++e) {
    if (!in.edges[e].curve) continue;
    const ParametricCurve& c = *in.edges[e].curve;
    const double span = c.t_max() - c.t_min();
    for (int i = 1; i <= 5; ++i) {
      const double t = c.t_min() + span * i / 6.0;
      const Vec3 p = c.point(t);
      const double d = (c.point(c.closest_parameter(p, t + 0.02 * span)) - p).norm();
      if (d > slack && ++failures <= 5)
        ADD_FAILURE() << in.source << ": " << edge_name(e) << ": closest_parameter of the point at t = " << t << " is "
                      << d << " away";
    }
  }
}

TessellationReport check_tessellation(const BrepInput& in, const BrepTessellation& t, const BrepChecker& checker,
                                      double volume_tolerance, size_t max_checked) {
  const occ::OccShape& m = occ::occ_shape_of(in);
  const double slack = 1e-7 * size_of(in);
  TessellationReport r;
  r.nodes = t.nodes.size();
  const size_t n = t.nodes.size();
  EXPECT_EQ(t.node_vertex.size(), n);
  EXPECT_EQ(t.node_edge.size(), n);
  EXPECT_EQ(t.node_t.size(), n);
  EXPECT_EQ(t.faces.size(), in.faces.size());
  EXPECT_EQ(t.edges.size(), in.edges.size());
  int failures = 0;
  auto fail = [&](const std::string& what) {
    if (++failures <= 8) ADD_FAILURE() << in.source << ": " << what;
  };

  // edges: from v0 to v1, every inner node on that edge
  for (size_t e = 0; e < in.edges.size(); ++e) {
    const auto& nodes = t.edges[e].nodes;
    if (nodes.empty()) {
      fail(edge_name(e) + " has no nodes");
      continue;
    }
    if (nodes.front() != in.edges[e].v0 || t.node_vertex[nodes.front()] != in.edges[e].v0)
      fail(edge_name(e) + " does not start at its v0");
    if (in.edges[e].degenerate) {
      if (nodes.size() != 1) fail(edge_name(e) + " is degenerate and has " + std::to_string(nodes.size()) + " nodes");
      continue;
    }
    if (nodes.back() != in.edges[e].v1) fail(edge_name(e) + " does not end at its v1");
    for (size_t k = 1; k + 1 < nodes.size(); ++k) {
      if (t.node_edge[nodes[k]] != static_cast<Index>(e)) fail(edge_name(e) + " lists a node of another edge");
      if (k > 1 && !(t.node_t[nodes[k]] > t.node_t[nodes[k - 1]])) fail(edge_name(e) + ": parameters do not rise");
    }
  }

  // faces: counter-clockwise in (u, v), each corner's (u, v) on its node
  std::vector<Index> node_face(n, -1);
  for (size_t f = 0; f < in.faces.size(); ++f) {
    const auto& tf = t.faces[f];
    EXPECT_EQ(tf.tris.size(), tf.uv.size());
    if (tf.tris.empty()) fail(face_name(f) + " has no triangles");
    r.triangles += tf.tris.size();
    const ParametricSurface& s = *in.faces[f].surface;
    int clockwise = 0;
    for (size_t k = 0; k < tf.tris.size(); ++k) {
      if (!(signed_area(tf.uv[k]) > 0)) ++clockwise;
      for (int c = 0; c < 3; ++c) {
        const Index v = tf.tris[k][c];
        if (t.node_vertex[v] < 0 && t.node_edge[v] < 0) node_face[v] = static_cast<Index>(f);
        const double tol = t.node_vertex[v] >= 0 ? in.vertices[t.node_vertex[v]].tolerance
                           : t.node_edge[v] >= 0 ? in.edges[t.node_edge[v]].tolerance
                                                 : 0.0;
        const double d = (s.point(tf.uv[k][c]) - t.nodes[v]).norm();
        if (d > std::max(tol, in.faces[f].tolerance) + slack)
          fail(face_name(f) + ": a corner's (u, v) maps " + std::to_string(d) + " from its node (" +
               (t.node_vertex[v] >= 0   ? vertex_name(t.node_vertex[v])
                : t.node_edge[v] >= 0 ? edge_name(t.node_edge[v])
                                      : std::string("inside")) +
               ", tolerance " + std::to_string(std::max(tol, in.faces[f].tolerance)) + ")");
      }
    }
    if (clockwise) fail(face_name(f) + ": " + std::to_string(clockwise) + " triangles not counter-clockwise in (u, v)");
  }

  // every node (or an even spread of them) on its vertex, edge or face, by OpenCASCADE's own distance
  const size_t stride = std::max<size_t>(1, (n + max_checked - 1) / max_checked);
  for (size_t v = 0; v < n; v += stride) {
    double d = 0, tol = 0;
    std::string what;
    if (t.node_vertex[v] >= 0) {
      d = checker.distance_to_vertex(t.node_vertex[v], t.nodes[v]);
      tol = in.vertices[t.node_vertex[v]].tolerance, what = vertex_name(t.node_vertex[v]);
    } else if (t.node_edge[v] >= 0) {
      d = checker.distance_to_edge(t.node_edge[v], t.nodes[v]);
      tol = in.edges[t.node_edge[v]].tolerance, what = edge_name(t.node_edge[v]);
    } else if (node_face[v] >= 0) {
      d = checker.distance_to_face(node_face[v], t.nodes[v]);
      tol = in.faces[node_face[v]].tolerance, what = face_name(node_face[v]);
    } else {
      continue;  // a node of dropped triangles only
    }
    ++r.nodes_checked;
    r.worst_node_distance = std::max(r.worst_node_distance, d / (tol + slack));
    if (d > tol + slack) fail("node " + std::to_string(v) + " is " + std::to_string(d) + " from " + what);
  }

  // closed per solid: outward, every directed side once each way; volume
  for (size_t s = 0; s < in.solids.size(); ++s) {
    std::map<std::pair<Index, Index>, int> sides;
    double volume = 0;
    std::set<Index> seen;
    for (TopExp_Explorer ex(m.solids[s], TopAbs_FACE); ex.More(); ex.Next()) {
      const Index f = m.faces.FindIndex(ex.Current()) - 1;
      if (!seen.insert(f).second) continue;
      const bool flip = ex.Current().Orientation() == TopAbs_REVERSED;  // du x dv points into the solid
      for (auto tri : t.faces[f].tris) {
        if (flip) std::swap(tri[1], tri[2]);
        for (int c = 0; c < 3; ++c) ++sides[{tri[c], tri[(c + 1) % 3]}];
        volume += t.nodes[tri[0]].dot(t.nodes[tri[1]].cross(t.nodes[tri[2]])) / 6;
      }
    }
    EXPECT_EQ(seen.size(), in.solids[s].faces.size());
    int open = 0;
    for (const auto& [side, count] : sides)
      if (count != 1 || sides.count({side.second, side.first}) != 1) ++open;
    if (open) fail(solid_name(s) + ": " + std::to_string(open) + " triangle sides not matched once the other way");
    const double exact = checker.solid_volume(s);
    const double err = std::abs(volume - exact) / std::abs(exact);
    r.worst_volume_error = std::max(r.worst_volume_error, err);
    if (err > volume_tolerance)
      fail(solid_name(s) + ": the tessellation's volume " + std::to_string(volume) + " is not BRepGProp's " +
           std::to_string(exact));
  }
  return r;
}

}  // namespace bisect::test
