#include "pipeline/brep_boundary.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "bisect/errors.hpp"

namespace bisect::pipeline {
namespace {

// Barycentric coordinates of p in the triangle (a, b, c), p near its plane (least squares).
Eigen::Vector3d barycentric(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p) {
  Eigen::Matrix<double, 3, 2> M;
  M.col(0) = b - a, M.col(1) = c - a;
  const Eigen::Vector2d st = M.colPivHouseholderQr().solve(p - a);
  return {1 - st.x() - st.y(), st.x(), st.y()};
}

// The parameter of chord (e, i)'s end node (end 0: nodes[i], 1: nodes[i + 1]).
double chord_end_param(const BrepInput& in, const BrepProxy& px, Index e, Index i, int end) {
  const auto& nodes = px.tess.edges[e].nodes;
  const Index v = nodes[i + end];
  if (px.tess.node_vertex[v] < 0 && px.tess.node_edge[v] == e) return px.tess.node_t[v];
  const ParametricCurve& c = *in.edges[e].curve;
  // a vertex: the edge's first or last parameter (a closed edge starts and ends at it)
  if (i + end == 0) return c.t_min();
  if (static_cast<std::size_t>(i + end) + 1 == nodes.size()) return c.t_max();
  return (c.closest_parameter(px.tess.nodes[v], 0.5 * (c.t_min() + c.t_max())));
}

}  // namespace

BrepBoundary::BrepBoundary(const BrepInput& input, const BrepProxy& proxy, const PolyhedralModel& m) : in(input), px(proxy), model(m) {
  pole_.assign(in.vertices.size(), 0);
  for (const BrepEdge& e : in.edges)
    if (e.degenerate && e.v0 >= 0) pole_[e.v0] = 1;
  node_on_.resize(model.nodes.size());
  for (std::size_t v = 0; v < model.nodes.size(); ++v) node_on_[v] = classify(static_cast<Index>(v));
}

bool BrepBoundary::on_chord(Index v, Index e, Index i, double* t) const {
  const auto& nodes = px.tess.edges[e].nodes;
  const Vec3 &a = model.nodes[nodes[i]], &b = model.nodes[nodes[i + 1]], &p = model.nodes[v];
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  if (!(len2 > 0)) return false;
  const double f = (p - a).dot(ab) / len2;
  if (f < -1e-9 || f > 1 + 1e-9) return false;
  if ((a + f * ab - p).norm() > 1e-9 * std::sqrt(len2)) return false;
  const double ta = chord_end_param(in, px, e, i, 0), tb = chord_end_param(in, px, e, i, 1);
  *t = ta + std::clamp(f, 0.0, 1.0) * (tb - ta);
  return true;
}

PointOn BrepBoundary::classify(Index v) const {
  PointOn on;
  const std::size_t tess_nodes = px.tess.nodes.size();
  if (static_cast<std::size_t>(v) < tess_nodes) {
    if (px.tess.node_vertex[v] >= 0) {
      on.kind = PointOn::kVertex, on.id = px.tess.node_vertex[v];
      return on;
    }
    if (px.tess.node_edge[v] >= 0) {
      on.kind = PointOn::kEdge, on.id = px.tess.node_edge[v], on.t = px.tess.node_t[v];
      for (const auto& c : px.node_chords[v])
        if (c[0] == on.id) on.chord = c[1];
      return on;
    }
  }
  Index proxy = -1;
  for (Index f : model.faces_of_node(v))
    if (model.faces[f].source >= 0) {
      proxy = model.faces[f].source;
      break;
    }
  if (proxy < 0) return on;  // only on cut faces: inside the solid
  on.kind = PointOn::kFace, on.id = px.face_brep[proxy], on.proxy = proxy;
  if (static_cast<std::size_t>(v) < tess_nodes) return on;
  // a node the cuts made: on a chord of a B-rep edge, or inside its proxy face
  std::vector<std::pair<Index, Index>> segments;  // (A, B) proxy-face boundary segments
  auto add_loop = [&](const std::vector<Index>& loop) {
    for (std::size_t i = 0; i < loop.size(); ++i) segments.push_back({loop[i], loop[(i + 1) % loop.size()]});
  };
  add_loop(px.input.faces[proxy].nodes);
  if (px.face_tri[proxy] < 0)
    for (std::size_t h = 0; h < px.input.faces.size(); ++h)
      if (px.input.faces[h].hole_of == proxy) add_loop(px.input.faces[h].nodes);
  for (const auto& [A, B] : segments)
    for (const auto& ca : px.node_chords[A])
      for (const auto& cb : px.node_chords[B]) {
        double t = 0;
        if (ca == cb && on_chord(v, ca[0], ca[1], &t)) {
          on.kind = PointOn::kEdge, on.id = ca[0], on.chord = ca[1], on.t = t, on.proxy = -1;
          return on;
        }
      }
  return on;
}

Vec2 BrepBoundary::uv_on_proxy(Index s, const Vec3& p) const {
  const Index k = px.face_brep[s];
  const ParametricSurface& surf = *in.faces[k].surface;
  if (px.face_tri[s] < 0) return surf.closest_point(p, 0.5 * (surf.uv_min() + surf.uv_max()));
  const auto& tri = px.tess.faces[k].tris[px.face_tri[s]];
  std::array<Vec2, 3> uv = px.tess.faces[k].uv[px.face_tri[s]];
  // a corner at a pole has whatever u the tessellation gave it; the pole's points lie at every u,
  // so it takes the u of the triangle's other corners (else a point near the pole would get a u
  // from the far side of it)
  for (int c = 0; c < 3; ++c) {
    const Index v = px.tess.node_vertex[tri[c]];
    if (v >= 0 && pole_[v]) uv[c].x() = 0.5 * (uv[(c + 1) % 3].x() + uv[(c + 2) % 3].x());
  }
  const Eigen::Vector3d l = barycentric(model.nodes[tri[0]], model.nodes[tri[1]], model.nodes[tri[2]], p);
  return l(0) * uv[0] + l(1) * uv[1] + l(2) * uv[2];
}

Vec3 BrepBoundary::image(const PointOn& on, const Vec3& p) const {
  switch (on.kind) {
    case PointOn::kVertex:
      return in.vertices[on.id].point;
    case PointOn::kEdge: {
      const BrepEdge& e = in.edges[on.id];
      return e.curve ? e.curve->point(on.t) : in.vertices[e.v0].point;
    }
    case PointOn::kFace: {
      // the surface point nearest the proxy point, from its interpolated parameters
      const ParametricSurface& surf = *in.faces[on.id].surface;
      return surf.point(surf.closest_point(p, uv_on_proxy(on.proxy, p)));
    }
    default:
      return p;
  }
}

PointOn BrepBoundary::edge_on(Index a, Index b) const {
  PointOn on;
  // along a chord: both ends on the same chord of one B-rep edge
  auto chords = [&](Index v) {
    std::vector<std::array<Index, 2>> c;
    const PointOn& o = node_on_[v];
    if (static_cast<std::size_t>(v) < px.tess.nodes.size()) c = px.node_chords[v];
    else if (o.kind == PointOn::kEdge) c.push_back({o.id, o.chord});
    return c;
  };
  const auto ca = chords(a), cb = chords(b);
  for (const auto& x : ca)
    for (const auto& y : cb)
      if (x == y) {
        on.kind = PointOn::kEdge, on.id = x[0], on.chord = x[1];
        return on;
      }
  // inside a proxy face: a live face with source >= 0 that has a and b next to each other
  for (Index f : model.faces_of_node(a)) {
    const ModelFace& face = model.faces[f];
    if (face.source < 0) continue;
    for (const auto& loop : face.loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Index u = loop[i], w = loop[(i + 1) % loop.size()];
        if ((u == a && w == b) || (u == b && w == a)) {
          on.kind = PointOn::kFace, on.id = px.face_brep[face.source], on.proxy = face.source;
          return on;
        }
      }
  }
  return on;
}

// The parameters of model edge (a, b)'s ends on the B-rep edge it runs along (a chord of it).
void BrepBoundary::edge_params(Index a, Index b, const PointOn& along, double* ta, double* tb) const {
  auto param = [&](Index v) {
    const PointOn& o = node_on_[v];
    if (o.kind == PointOn::kEdge && o.id == along.id) return o.t;
    const auto& en = px.tess.edges[along.id].nodes;  // a vertex: which end of the chord
    return chord_end_param(in, px, along.id, along.chord, en[along.chord] == v ? 0 : 1);
  };
  *ta = param(a), *tb = param(b);
}

void BrepBoundary::discretise_edges(const size::SizeField& h) {
  nodes = {};
  edge_nodes.clear();
  for (std::size_t v = 0; v < model.nodes.size(); ++v) {
    nodes.p.push_back(model.nodes[v]);
    nodes.x.push_back(image(node_on_[v], model.nodes[v]));
    nodes.on.push_back(node_on_[v]);
  }
  // model edges along B-rep edges are discretised as chains per B-rep edge (below), the others
  // one by one
  std::map<Index, std::vector<ChordPiece>> along_edge;
  for (const ModelFace& f : model.faces) {
    if (!f.alive) continue;
    for (const auto& loop : f.loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Index a = std::min(loop[i], loop[(i + 1) % loop.size()]), b = std::max(loop[i], loop[(i + 1) % loop.size()]);
        if (edge_nodes.count({a, b})) continue;
        edge_nodes[{a, b}];
        const PointOn along = edge_on(a, b);
        if (along.kind == PointOn::kEdge && in.edges[along.id].curve) {
          ChordPiece c{a, b, along, 0, 0};
          edge_params(a, b, along, &c.ta, &c.tb);
          along_edge[along.id].push_back(c);
        } else {
          discretise_one(a, b, along, h);
        }
      }
  }
  for (auto& [e, pieces] : along_edge) discretise_chain(e, pieces, h);
}

// The integral of ds / h along the true curve of a model edge, as a function of s in [0, 1]
// sampled at m steps: cum[j] at s = j / m.
double BrepBoundary::integrate(const std::function<Vec3(double)>& point_at, const size::SizeField& h, int m, std::vector<double>* cum) {
  cum->assign(m + 1, 0.0);
  Vec3 prev = point_at(0);
  for (int j = 1; j <= m; ++j) {
    const Vec3 cur = point_at(static_cast<double>(j) / m);
    (*cum)[j] = (*cum)[j - 1] + (cur - prev).norm() / h.at(0.5 * (cur + prev));
    prev = cur;
  }
  return cum->back();
}

// Where the k-th of n equal steps of the integral falls, as s in [0, 1].
double BrepBoundary::step_at(const std::vector<double>& cum, double target) {
  const int m = static_cast<int>(cum.size()) - 1;
  const int j = static_cast<int>(std::upper_bound(cum.begin(), cum.end(), target) - cum.begin());
  const int j0 = std::clamp(j - 1, 0, m - 1);
  const double span = cum[j0 + 1] - cum[j0];
  return (j0 + (span > 0 ? (target - cum[j0]) / span : 0.5)) / m;
}

int BrepBoundary::finer_factor(Index a, Index b) const {
  const auto more = finer.find({std::min(a, b), std::max(a, b)});
  return more == finer.end() ? 1 : more->second;
}

void BrepBoundary::discretise_one(Index a, Index b, const PointOn& along, const size::SizeField& h) {
  auto& inner = edge_nodes[{a, b}];
  const Vec3 pa = model.nodes[a], pb = model.nodes[b];
  // the edge as a curve of s in [0, 1]: its true point, what that point lies on, and its proxy
  // point
  double ta = 0, tb = 0;
  const ParametricCurve* curve = nullptr;
  if (along.kind == PointOn::kEdge) {
    curve = in.edges[along.id].curve.get();
    edge_params(a, b, along, &ta, &tb);
  }
  auto point_on = [&](double s, PointOn* on) -> Vec3 {
    const Vec3 p = pa + s * (pb - pa);
    *on = along;
    if (along.kind == PointOn::kEdge) {
      on->t = ta + s * (tb - ta);
      return curve ? curve->point(on->t) : p;
    }
    if (along.kind == PointOn::kFace) return image(along, p);
    return p;
  };
  auto point_at = [&](double s) {
    PointOn scratch;
    return point_on(s, &scratch);
  };
  // the number of segments: the integral of ds / h along the true curve, sampled, with nodes at
  // equal steps of it (graded with h)
  std::vector<double> cum;
  const double rough = integrate(point_at, h, 16, &cum);
  const int m = static_cast<int>(std::clamp(4 * rough, 16.0, 4096.0));
  const double total = m == 16 ? rough : integrate(point_at, h, m, &cum);
  const int n = std::max(1, static_cast<int>(std::lround(total))) * finer_factor(a, b);
  for (int k = 1; k < n; ++k) {
    const double s = step_at(cum, total * k / n);
    PointOn on;
    const Vec3 x = point_on(s, &on);
    nodes.p.push_back(pa + s * (pb - pa));
    nodes.x.push_back(x);
    nodes.on.push_back(on);
    inner.push_back(static_cast<Index>(nodes.x.size() - 1));
  }
}

// The model edges along one B-rep edge: chords of the proxy's tessellation, cut where the cut
// faces cross. Discretised one by one, every chord and every piece of a chord would get a node
// at each end: the proxy's own nodes (every 25-60 degrees of a curve) and a cut close to one of
// them would make short segments, and slivers on the surface beside them. So the chain is
// discretised as one curve between its fixed nodes (B-rep vertices and the nodes the cuts made,
// which the cut faces hold), and the proxy's nodes between them, which nothing else holds, slide
// along the curve onto the nearest of the equal steps (their proxy positions stay: the proxy's
// geometry does not change, only their image on the true edge).
void BrepBoundary::discretise_chain(Index e, std::vector<ChordPiece>& pieces, const size::SizeField& h) {
  for (ChordPiece& c : pieces)
    if (c.ta > c.tb) std::swap(c.a, c.b), std::swap(c.ta, c.tb);
  std::sort(pieces.begin(), pieces.end(), [](const ChordPiece& x, const ChordPiece& y) { return x.ta < y.ta; });
  bool path = true;
  for (std::size_t i = 1; i < pieces.size(); ++i)
    if (pieces[i].a != pieces[i - 1].b || std::abs(pieces[i].ta - pieces[i - 1].tb) > 1e-9 * (1 + std::abs(pieces[i].ta))) path = false;
  if (!path) {  // not one chain (never seen; kept safe): each piece alone
    for (const ChordPiece& c : pieces) discretise_one(std::min(c.a, c.b), std::max(c.a, c.b), c.along, h);
    return;
  }
  const ParametricCurve& curve = *in.edges[e].curve;
  const std::size_t tess_nodes = px.tess.nodes.size();
  auto fixed = [&](Index v) {
    if (node_on_[v].kind != PointOn::kEdge || static_cast<std::size_t>(v) >= tess_nodes) return true;
    for (Index f : model.faces_of_node(v))
      if (model.faces[f].alive && model.faces[f].source < 0) return true;  // on a cut face
    return false;
  };
  std::size_t first = 0;
  while (first < pieces.size()) {
    std::size_t last = first;  // pieces first..last run between two fixed nodes
    while (last + 1 < pieces.size() && !fixed(pieces[last].b)) ++last;
    const double t0 = pieces[first].ta, t1 = pieces[last].tb;
    auto point_at = [&](double s) { return curve.point(t0 + s * (t1 - t0)); };
    std::vector<double> cum;
    const double rough = integrate(point_at, h, 16, &cum);
    const int m = static_cast<int>(std::clamp(4 * rough * static_cast<double>(last - first + 1), 16.0, 4096.0));
    const double total = m == 16 ? rough : integrate(point_at, h, m, &cum);
    const int movable = static_cast<int>(last - first);
    int factor = 1;
    for (std::size_t i = first; i <= last; ++i) factor = std::max(factor, finer_factor(pieces[i].a, pieces[i].b));
    const int n = std::max(movable + 1, std::max(1, static_cast<int>(std::lround(total))) * factor);
    std::vector<double> t(n + 1);
    t[0] = t0, t[n] = t1;
    for (int k = 1; k < n; ++k) t[k] = t0 + step_at(cum, total * k / n) * (t1 - t0);
    // the step each chain node takes: the ends 0 and n, the movable nodes the nearest free one
    std::vector<int> step(movable + 2);
    step[0] = 0, step[movable + 1] = n;
    for (int i = 1; i <= movable; ++i) {
      const double s = (pieces[first + i - 1].tb - t0) / (t1 - t0);
      const double c = cum[std::clamp(static_cast<int>(std::lround(s * m)), 0, m)];
      const int want = static_cast<int>(std::lround(total > 0 ? c / total * n : i));
      step[i] = std::clamp(want, step[i - 1] + 1, n - (movable + 1 - i));
      const Index v = pieces[first + i - 1].b;
      nodes.on[v].t = t[step[i]];
      nodes.x[v] = curve.point(t[step[i]]);
    }
    for (int i = 0; i <= movable; ++i) {
      const ChordPiece& c = pieces[first + i];
      const Index lo = std::min(c.a, c.b), hi = std::max(c.a, c.b);
      auto& inner = edge_nodes[{lo, hi}];
      inner.clear();
      const double ta = t[step[i]], tb = t[step[i + 1]];
      const Vec3 pa = model.nodes[c.a], pb = model.nodes[c.b];
      for (int k = step[i] + 1; k < step[i + 1]; ++k) {
        PointOn on = c.along;
        on.t = t[k];
        const double s = (t[k] - ta) / (tb - ta);
        nodes.p.push_back(pa + s * (pb - pa));
        nodes.x.push_back(curve.point(t[k]));
        nodes.on.push_back(on);
        inner.push_back(static_cast<Index>(nodes.x.size() - 1));
      }
      if (c.a > c.b) std::reverse(inner.begin(), inner.end());
    }
    first = last + 1;
  }
}

}  // namespace bisect::pipeline
