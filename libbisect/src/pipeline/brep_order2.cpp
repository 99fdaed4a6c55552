#include "pipeline/brep_order2.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "bisect/errors.hpp"
#include "geom/predicates.hpp"
#include "tet/face_file.hpp"
#include "bisect/validate.hpp"

namespace bisect::pipeline {
namespace {

// The parameter of a mesh node on B-rep edge e, or NaN when it is not on e (a vertex of e: the
// end nearer `near`).
double param_on_edge(const BrepInput& in, const PointOn& on, Index e, double near) {
  if (on.kind == PointOn::kEdge && on.id == e) return on.t;
  const BrepEdge& edge = in.edges[e];
  if (on.kind != PointOn::kVertex || (on.id != edge.v0 && on.id != edge.v1)) return std::numeric_limits<double>::quiet_NaN();
  const double lo = edge.curve->t_min(), hi = edge.curve->t_max();
  if (edge.v0 == edge.v1) return std::abs(near - lo) < std::abs(near - hi) ? lo : hi;
  return on.id == edge.v0 ? lo : hi;
}

// The B-rep edge both ends lie on, with their parameters; -1 when none.
Index common_edge(const BrepInput& in, const PointOn& a, const PointOn& b, double* ta, double* tb) {
  for (Index e : common_brep_edges(in, a, b)) {
    if (in.edges[e].degenerate || !in.edges[e].curve) continue;
    const double mid = 0.5 * (in.edges[e].curve->t_min() + in.edges[e].curve->t_max());
    const double x = param_on_edge(in, a, e, b.kind == PointOn::kEdge && b.id == e ? b.t : mid);
    const double y = param_on_edge(in, b, e, a.kind == PointOn::kEdge && a.id == e ? a.t : mid);
    if (std::isnan(x) || std::isnan(y)) continue;
    *ta = x, *tb = y;
    return e;
  }
  return -1;
}

}  // namespace

TetMesh assemble_brep_mesh(const BrepGrids& g, const tet::TetComplex& cx, const std::vector<Vec3>& X, const BrepInput& in, int order,
                           std::int64_t* straightened, const std::function<bool()>& cancelled) {
  // Stop within the order-2 passes over every element (0.9 s at 2e5 tetra10)
  const auto poll = [&cancelled](std::size_t t) {
    if ((t & 4095) == 4095 && cancelled && cancelled()) throw Cancelled();
  };
  const std::vector<tet::Tet> tets = cx.tets();
  const std::vector<Index> region = cx.tags();
  TetMesh out;
  std::vector<Index> id(X.size(), -1), back;
  for (const auto& t : tets)
    for (Index v : t) id[v] = 0;
  for (std::size_t v = 0; v < X.size(); ++v)
    if (id[v] == 0) {
      id[v] = static_cast<Index>(out.nodes.size());
      out.nodes.push_back(X[v]);
      back.push_back(static_cast<Index>(v));
    }
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const Index v[4] = {id[tets[t][0]], id[tets[t][1]], id[tets[t][2]], id[tets[t][3]]};
    out.add_tet(v, region[t]);
  }
  struct TriRef {
    std::size_t piece, k;
  };
  std::vector<TriRef> refs;
  for (std::size_t p = 0; p < g.pieces.size(); ++p)
    for (std::size_t k = 0; k < g.pieces[p].tris.size(); ++k) {
      const auto& t = g.pieces[p].tris[k];
      for (Index v : t)
        if (id[v] < 0)
          throw MeshingError(in.source + ": " + face_name(g.pieces[p].face) + ": the surface node at " + point_name(X[v]) +
                             " is in no tetrahedron (a defect of the mesher)");
      out.tris.insert(out.tris.end(), {id[t[0]], id[t[1]], id[t[2]]});
      out.tri_tag.push_back(g.pieces[p].face);
      refs.push_back({p, k});
    }
  *straightened = 0;
  if (order != 2) return out;
  out = to_second_order(out, cancelled);
  // curved positions of the boundary mid-nodes
  const std::size_t n_nodes = out.nodes.size();
  std::vector<Vec3> straight = out.nodes;
  std::vector<char> curved(n_nodes, 0);
  for (std::size_t f = 0; f < refs.size(); ++f) {
    poll(f);
    const FacePiece& piece = g.pieces[refs[f].piece];
    const auto& uv = piece.tri_uv[refs[f].k];
    const ParametricSurface& surf = *in.faces[piece.face].surface;
    for (int e = 0; e < 3; ++e) {
      const int i = kTriEdge[e][0], j = kTriEdge[e][1];
      const Index m = out.tris[6 * f + 3 + e];
      if (curved[m]) continue;
      const Index a = back[out.tris[6 * f + i]], b = back[out.tris[6 * f + j]];
      const PointOn &oa = g.nodes.on[a], &ob = g.nodes.on[b];
      const Vec3 mid = 0.5 * (X[a] + X[b]);
      double ta = 0, tb = 0;
      const Index edge = common_edge(in, oa, ob, &ta, &tb);
      Vec3 target = surf.point(0.5 * (uv[i] + uv[j]));
      if (edge >= 0) {
        const Vec3 along = in.edges[edge].curve->point(0.5 * (ta + tb));
        // the mesh edge runs along the B-rep edge (not across the face between two of its points)
        if ((along - mid).norm() <= 0.5 * (X[a] - X[b]).norm()) target = along;
      }
      out.nodes[m] = target;
      curved[m] = 1;
    }
  }
  // every element positive at its corners and Gauss points
  const std::size_t nt = out.num_tets();
  std::vector<std::vector<Index>> tets_of(n_nodes);
  for (std::size_t t = 0; t < nt; ++t) {
    poll(t);
    for (int i = 4; i < 10; ++i) tets_of[out.tet_node(t, i)].push_back(static_cast<Index>(t));
  }
  auto worst_around = [&](Index m) {
    double w = 1e300;
    for (Index t : tets_of[m]) w = std::min(w, tet10_jacobian_ratio(out, static_cast<std::size_t>(t)));
    return w;
  };
  constexpr double kMinRatio = 1e-3;  // a margin over zero: CalculiX's own check and round-off
  std::vector<Index> bad;
  for (std::size_t t = 0; t < nt; ++t) {
    poll(t);
    if (tet10_jacobian_ratio(out, t) <= kMinRatio) bad.push_back(static_cast<Index>(t));
  }
  for (int round = 0; round < 4 && !bad.empty(); ++round) {
    std::vector<Index> still;
    for (Index t : bad) {
      if (tet10_jacobian_ratio(out, static_cast<std::size_t>(t)) > kMinRatio) continue;
      Vec3 pull = Vec3::Zero();
      int count = 0;
      for (int i = 4; i < 10; ++i) {
        const Index m = out.tet_node(static_cast<std::size_t>(t), i);
        if (curved[m]) pull += out.nodes[m] - straight[m], ++count;
      }
      if (count > 0) pull /= count;
      for (int i = 4; i < 10; ++i) {
        const Index m = out.tet_node(static_cast<std::size_t>(t), i);
        if (curved[m]) continue;
        const Vec3 was = out.nodes[m];
        double best = worst_around(m);
        Vec3 best_p = was;
        for (double beta : {0.25, 0.5, 0.75, 1.0}) {
          out.nodes[m] = straight[m] + beta * pull;
          const double w = worst_around(m);
          if (w > best) best = w, best_p = out.nodes[m];
        }
        out.nodes[m] = best_p;
      }
      if (tet10_jacobian_ratio(out, static_cast<std::size_t>(t)) <= kMinRatio) still.push_back(t);
    }
    bad = std::move(still);
  }
  // last resort: the element's curved edges straight again, then its interior ones
  for (Index t : bad) {
    for (int pass = 0; pass < 2 && tet10_jacobian_ratio(out, static_cast<std::size_t>(t)) <= kMinRatio; ++pass)
      for (int i = 4; i < 10; ++i) {
        const Index m = out.tet_node(static_cast<std::size_t>(t), i);
        if ((pass == 0) != (curved[m] != 0)) continue;
        if (out.nodes[m] != straight[m]) {
          out.nodes[m] = straight[m];
          if (curved[m]) ++*straightened;
        }
      }
  }
  // what a straightening changed around it, until nothing changes (nodes only go back to
  // straight, so this ends)
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t t = 0; t < nt; ++t, poll(t))
      for (int pass = 0; pass < 2 && tet10_jacobian_ratio(out, t) <= kMinRatio; ++pass)
        for (int i = 4; i < 10; ++i) {
          const Index m = out.tet_node(t, i);
          if ((pass == 0) != (curved[m] != 0)) continue;
          if (out.nodes[m] != straight[m]) {
            out.nodes[m] = straight[m];
            if (curved[m]) ++*straightened;
            changed = true;
          }
        }
  }
  for (std::size_t t = 0; t < nt; poll(t), ++t)
    if (!(tet10_jacobian_ratio(out, t) > 0)) {
      // straight, its Jacobian is the corners' own: a tetrahedron flat to round-off (Cone_1's apex)
      Vec3 centre = Vec3::Zero();
      for (int k = 0; k < 4; ++k) centre += out.nodes[out.tet_node(t, k)] / 4;
      throw MeshingError(in.source + ": " + solid_name(in, out.region[t]) + ": the tetrahedron at " + point_name(centre) +
                         " is nearly flat: its 10-node Jacobian is not positive even with straight edges (a defect of the mesher)");
    }
  return out;
}

void refuse_degenerate_tets(const BrepInput& in, const TetMesh& m) {
  constexpr double kFlat = 1e-10;
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    const Vec3 &a = m.nodes[m.tet_node(t, 0)], &b = m.nodes[m.tet_node(t, 1)], &c = m.nodes[m.tet_node(t, 2)], &d = m.nodes[m.tet_node(t, 3)];
    const std::string where = in.source + ": " + solid_name(in, m.region[t]) + ": ";
    if (geom::orient3d(a, b, c, d) <= 0)
      throw MeshingError(where + "a tetrahedron at " + point_name((a + b + c + d) / 4) + " came out inside out (a defect of the mesher)");
    const double longest = std::max({(b - a).norm(), (c - a).norm(), (d - a).norm(), (c - b).norm(), (d - b).norm(), (d - c).norm()});
    if (!((b - a).dot((c - a).cross(d - a)) > kFlat * longest * longest * longest))
      throw MeshingError(where + "the tetrahedron at " + point_name((a + b + c + d) / 4) +
                         " is flat to round-off: a solver's Jacobian there is noise (a defect of the mesher)");
  }
  // Faces of three tetrahedra (face_file.hpp): 10^6 tetrahedra, 4*10^6 faces of 12 bytes.
  const tet::FaceFile file = tet::file_faces(
      m.nodes.size(), m.num_tets(), 1,
      [&](std::size_t t, std::array<Index, 4>& v) {
        for (int k = 0; k < 4; ++k) v[static_cast<std::size_t>(k)] = m.tet_node(t, k);
        return true;
      },
      [] {});
  tet::for_each_face(file, 0, file.nodes(), [&](Index a, const tet::FiledFace* i, const tet::FiledFace* j) {
    if (j - i < 3) return;
    const Vec3 mid = (m.nodes[static_cast<std::size_t>(a)] + m.nodes[static_cast<std::size_t>(i->b)] + m.nodes[static_cast<std::size_t>(i->c)]) / 3;
    throw MeshingError(in.source + ": " + solid_name(in, m.region[static_cast<std::size_t>(i->tf / 4)]) + ": the face at " + point_name(mid) +
                       " is shared by three tetrahedra or more (they overlap: a defect of the mesher)");
  });
}

}  // namespace bisect::pipeline
