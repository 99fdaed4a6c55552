// The mesh validator (validate.hpp): every violation of the invariants of ARCHITECTURE.md §3.
//
// Everything is a linear pass or a sort of flat records (faces, edges, nodes), so a mesh of 10^6
// tetrahedra validates in well under a few seconds; no per-element heap objects and no O(n²)
// searches.
#include "bisect/validate.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>

#include "bisect/errors.hpp"
#include "geom/predicates.hpp"
#include "tet/face_file.hpp"
#include "util/progress_poll.hpp"
#include "util/edge_key.hpp"

namespace bisect {

const char* to_string(ViolationKind k) {
  switch (k) {
    case ViolationKind::BadNodeIndex: return "bad_node_index";
    case ViolationKind::RepeatedNode: return "repeated_node";
    case ViolationKind::InvertedTet: return "inverted_tet";
    case ViolationKind::ZeroVolumeTet: return "zero_volume_tet";
    case ViolationKind::NonManifoldFace: return "non_manifold_face";
    case ViolationKind::OpenBoundary: return "open_boundary";
    case ViolationKind::DuplicateNode: return "duplicate_node";
    case ViolationKind::UnusedNode: return "unused_node";
    case ViolationKind::BadMidNode: return "bad_mid_node";
    case ViolationKind::NonFiniteNode: return "non_finite_node";
    case ViolationKind::NonPositiveJacobian: return "non_positive_jacobian";
  }
  return "Unknown";
}

namespace {

// Shortest round-trip text, independent of the C locale (FreeCAD may run with a decimal comma).
std::string num(double x) {
  char buf[32];
  auto res = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, res.ptr);
}

std::string num(std::int64_t x) {
  char buf[24];
  auto res = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, res.ptr);
}

std::string point(const Vec3& p) { return "(" + num(p.x()) + ", " + num(p.y()) + ", " + num(p.z()) + ")"; }

// An edge of a tetrahedron by its sorted corner nodes packed into one key, with the mid-edge
// node the tetrahedron puts on it.
struct EdgeRecord {
  std::uint64_t key;
  Index mid, t;
};


// Orders coordinates with NaN after every number and all NaNs equivalent: a strict weak order
// for any input, so std::sort stays well defined on a mesh with non-finite coordinates.
bool coord_less(double x, double y) {
  const bool nx = std::isnan(x), ny = std::isnan(y);
  if (nx || ny) return !nx && ny;
  return x < y;
}

class Validator {
public:
  Validator(const TetMesh& mesh, const std::function<bool(double)>& progress)
      : m_(mesh), nn_(mesh.nodes.size()), nt_(mesh.num_tets()), npt_(mesh.nodes_per_tet()), poll_(progress) {}

  // The passes' shares of the bar, measured at 2e5 tetra10 (the face sort and the Jacobians
  // take most of the time).
  std::vector<Violation> run() {
    pass(0.0), check_node_coordinates();
    pass(0.02), check_elements();
    pass(0.15), check_triangles();
    pass(0.17), check_faces();
    pass(0.55), check_duplicate_nodes();
    pass(0.65), check_unused_nodes();
    if (m_.order == 2) pass(0.67), check_mid_nodes();
    if (m_.order == 2) pass(0.8), check_jacobians();
    pass(1.0);
    std::stable_sort(out_.begin(), out_.end(), [](const Violation& x, const Violation& y) {
      if (x.kind != y.kind) return x.kind < y.kind;
      return x.ids < y.ids;
    });
    return std::move(out_);
  }

private:
  // Stop between passes, and within the per-element loops (every 4096 elements a clock read;
  // the callback itself at most every 50 ms): a check of 10^6 tetrahedra takes seconds.
  void pass(double fraction) {
    if (poll_.report(fraction)) throw Cancelled();
  }
  void poll(std::size_t t) {
    if ((t & 4095) == 4095 && poll_.cancelled()) throw Cancelled();
  }

  bool valid_node(Index n) const { return n >= 0 && std::size_t(n) < nn_; }

  std::string node_at(Index n) const { return num(m_.node_id(n)) + " " + point(m_.nodes[n]); }

  std::string corners(std::size_t t) const {
    std::string s;
    for (int i = 0; i < 4; ++i) s += (i ? ", " : "") + node_at(m_.tet_node(t, i));
    return s;
  }

  void add(ViolationKind kind, std::vector<std::int64_t> ids, std::string message) {
    out_.push_back(Violation{kind, std::move(ids), std::move(message)});
  }

  // NaN or infinite coordinates (a division by zero upstream, a corrupt file): such a node has
  // no place, so the orientation of the tetrahedra using it means nothing and is not judged.
  void check_node_coordinates() {
    finite_.assign(nn_, 1);
    for (std::size_t n = 0; n < nn_; ++n)
      if (!m_.nodes[n].allFinite()) {
        finite_[n] = 0;
        const std::int64_t id = m_.node_id(n);
        add(ViolationKind::NonFiniteNode, {id}, "node " + num(id) + " has a non-finite coordinate " + point(m_.nodes[n]));
      }
  }

  // Node indices, repeated nodes and orientation, one tetrahedron at a time. Tetrahedra that
  // name a missing node or repeat one are kept out of the face and edge checks: their faces
  // are not triangles of the mesh.
  void check_elements() {
    used_.assign(nn_, 0);
    well_formed_.assign(nt_, 0);
    for (std::size_t t = 0; t < nt_; ++t) {
      poll(t);
      const Index* v = &m_.tets[t * npt_];
      std::string bad;
      for (int i = 0; i < npt_; ++i) {
        if (valid_node(v[i])) used_[v[i]] = 1;
        else bad += (bad.empty() ? "" : ", ") + num(std::int64_t(v[i]));
      }
      const std::int64_t id = m_.tet_id(t);
      if (!bad.empty()) {
        add(ViolationKind::BadNodeIndex, {id},
            "tetrahedron " + num(id) + " refers to node index " + bad + " (0-based), but the mesh has " +
                num(std::int64_t(nn_)) + " nodes");
        continue;
      }
      if (report_repeated(t, v)) continue;
      well_formed_[t] = 1;
      if (!finite_[v[0]] || !finite_[v[1]] || !finite_[v[2]] || !finite_[v[3]]) continue;
      const int sign = geom::orient3d(m_.nodes[v[0]], m_.nodes[v[1]], m_.nodes[v[2]], m_.nodes[v[3]]);
      if (sign < 0)
        add(ViolationKind::InvertedTet, {id}, "tetrahedron " + num(id) + " is inverted (orient3d < 0): " + corners(t));
      else if (sign == 0)
        add(ViolationKind::ZeroVolumeTet, {id},
            "tetrahedron " + num(id) + " has zero volume (coplanar corners): " + corners(t));
    }
  }

  bool report_repeated(std::size_t t, const Index* v) {
    for (int i = 0; i < npt_; ++i)
      for (int j = i + 1; j < npt_; ++j)
        if (v[i] == v[j]) {
          const std::int64_t id = m_.tet_id(t);
          add(ViolationKind::RepeatedNode, {id},
              "tetrahedron " + num(id) + " uses node " + num(m_.node_id(v[i])) + " twice (local slots " +
                  num(std::int64_t(i)) + " and " + num(std::int64_t(j)) + ")");
          return true;
        }
    return false;
  }

  // Triangles have no file numbers of their own: they are named by position, 1-based.
  void check_triangles() {
    const std::size_t npr = m_.nodes_per_tri();
    for (std::size_t k = 0; k < m_.num_tris(); ++k) {
      std::string bad;
      for (std::size_t i = 0; i < npr; ++i) {
        const Index n = m_.tris[k * npr + i];
        if (!valid_node(n)) bad += (bad.empty() ? "" : ", ") + num(std::int64_t(n));
      }
      if (!bad.empty()) {
        const std::int64_t id = std::int64_t(k) + 1;
        add(ViolationKind::BadNodeIndex, {id},
            "triangle " + num(id) + " refers to node index " + bad + " (0-based), but the mesh has " +
                num(std::int64_t(nn_)) + " nodes");
      }
    }
  }

  // Faces by sorted node triple: a run of one is a boundary face, a run of more than two a
  // non-manifold face. The boundary faces' edges must each be used an even number of times
  // for the boundary to be a closed surface.
  void check_faces() {
    // the file skips faces naming nodes that are not there; well_formed_ leaves out the rest
    // of what check_tets reported
    const tet::FaceFile file = tet::file_faces(
        nn_, nt_, 1,
        [&](std::size_t t, std::array<Index, 4>& v) {
          poll(t);
          if (!well_formed_[t]) return false;
          for (int k = 0; k < 4; ++k) v[static_cast<std::size_t>(k)] = m_.tet_node(t, k);
          return true;
        },
        [] {});
    std::vector<std::uint64_t> boundary_edges;
    tet::for_each_face(file, 0, file.nodes(), [&](Index a, const tet::FiledFace* i, const tet::FiledFace* j) {
      if (j - i == 1) {
        boundary_edges.push_back(edge_key(a, i->b));
        boundary_edges.push_back(edge_key(i->b, i->c));
        boundary_edges.push_back(edge_key(a, i->c));
      } else if (j - i > 2) {
        std::vector<std::int64_t> ids;
        std::string names;
        for (const tet::FiledFace* k = i; k != j; ++k) ids.push_back(m_.tet_id(static_cast<std::size_t>(k->tf / 4)));
        std::sort(ids.begin(), ids.end());
        for (auto id : ids) names += " " + num(id);
        add(ViolationKind::NonManifoldFace, ids,
            "face of nodes " + num(m_.node_id(a)) + " " + num(m_.node_id(i->b)) + " " + num(m_.node_id(i->c)) +
                " is shared by " + num(std::int64_t(j - i)) + " tetrahedra:" + names);
      }
    });

    std::sort(boundary_edges.begin(), boundary_edges.end());
    for (std::size_t i = 0; i < boundary_edges.size();) {
      std::size_t j = i + 1;
      while (j < boundary_edges.size() && boundary_edges[j] == boundary_edges[i]) ++j;
      if ((j - i) % 2 == 1) {
        std::int64_t n0 = m_.node_id(key_lo(boundary_edges[i])), n1 = m_.node_id(key_hi(boundary_edges[i]));
        std::string where = node_at(key_lo(boundary_edges[i])) + " - " + node_at(key_hi(boundary_edges[i]));
        add(ViolationKind::OpenBoundary, {std::min(n0, n1), std::max(n0, n1)},
            "boundary edge " + where + " is used by " + num(std::int64_t(j - i)) +
                " boundary faces (an odd number: the boundary surface is not closed)");
      }
      i = j;
    }
  }

  // Per node: the connected body (tetrahedra joined through shared nodes) it belongs to; -1 for a
  // node no tetrahedron uses.
  std::vector<Index> bodies() const {
    std::vector<Index> parent(nn_);
    std::iota(parent.begin(), parent.end(), Index(0));
    const auto root = [&](Index v) {
      while (parent[v] != v) v = parent[v] = parent[parent[v]];
      return v;
    };
    for (std::size_t t = 0; t < nt_; ++t) {
      const Index first = m_.tet_node(t, 0);
      if (first < 0 || static_cast<std::size_t>(first) >= nn_) continue;
      for (int k = 1; k < npt_; ++k) {
        const Index v = m_.tet_node(t, k);
        if (v >= 0 && static_cast<std::size_t>(v) < nn_) parent[root(v)] = root(first);
      }
    }
    std::vector<char> used(nn_, 0);
    for (std::size_t t = 0; t < nt_; ++t)
      for (int k = 0; k < npt_; ++k) {
        const Index v = m_.tet_node(t, k);
        if (v >= 0 && static_cast<std::size_t>(v) < nn_) used[v] = 1;
      }
    for (std::size_t v = 0; v < nn_; ++v) parent[v] = used[v] ? root(static_cast<Index>(v)) : -1;  // -1: in no body
    return parent;
  }

  // Identical coordinates found by sorting the nodes lexicographically: equal points end up
  // next to each other. Only within one body: separate bodies (an assembly's parts, which share
  // no node as the CAD shares no face) may touch, and their coincident nodes are no crack
  // (corpus/x_ring.brep's two solids, x_as1_tu_203's parts).
  void check_duplicate_nodes() {
    const std::vector<Index> body = bodies();
    std::vector<Index> order(nn_);
    std::iota(order.begin(), order.end(), Index(0));
    const auto& p = m_.nodes;
    std::sort(order.begin(), order.end(), [&](Index i, Index j) {
      for (int k = 0; k < 3; ++k) {
        if (coord_less(p[i][k], p[j][k])) return true;
        if (coord_less(p[j][k], p[i][k])) return false;
      }
      return i < j;
    });
    for (std::size_t i = 0; i < order.size();) {
      std::size_t j = i + 1;
      // == rather than the sort's equivalence: NaN is nowhere, so never a duplicate.
      while (j < order.size() && p[order[j]] == p[order[i]]) ++j;
      std::vector<Index> in_bodies;
      for (std::size_t k = i; k < j; ++k) in_bodies.push_back(body[order[k]]);
      std::sort(in_bodies.begin(), in_bodies.end());
      // a node of no body is a duplicate of any (and reported unused as well)
      const bool one_body = in_bodies.front() < 0 || std::adjacent_find(in_bodies.begin(), in_bodies.end()) != in_bodies.end();
      if (j - i > 1 && one_body) {
        std::vector<std::int64_t> ids;
        for (std::size_t k = i; k < j; ++k) ids.push_back(m_.node_id(order[k]));
        std::sort(ids.begin(), ids.end());
        std::string names;
        for (auto id : ids) names += " " + num(id);
        add(ViolationKind::DuplicateNode, ids, "nodes" + names + " are all at " + point(p[order[i]]));
      }
      i = j;
    }
  }

  void check_unused_nodes() {
    for (std::size_t n = 0; n < nn_; ++n)
      if (!used_[n]) {
        const std::int64_t id = m_.node_id(n);
        add(ViolationKind::UnusedNode, {id},
            "node " + num(id) + " at " + point(m_.nodes[n]) + " is used by no tetrahedron");
      }
  }

  // Order 2: every tetrahedron around an edge must put the same mid-edge node on it.
  // Curved (order 2) elements: the Jacobian must stay positive wherever the solver evaluates it,
  // or CalculiX refuses the mesh.
  void check_jacobians() {
    for (std::size_t t = 0; t < nt_; ++t) {
      poll(t);
      if (!well_formed_[t]) continue;
      bool finite = true;
      for (int i = 0; i < 10; ++i) finite = finite && finite_[m_.tet_node(t, i)];
      if (!finite) continue;
      const Index* v = &m_.tets[t * npt_];
      // a straight element that is inverted or flat is reported as such already
      if (geom::orient3d(m_.nodes[v[0]], m_.nodes[v[1]], m_.nodes[v[2]], m_.nodes[v[3]]) <= 0) continue;
      const double r = tet10_jacobian_ratio(m_, t);
      if (r > 0) continue;
      const std::int64_t id = m_.tet_id(t);
      add(ViolationKind::NonPositiveJacobian, {id},
          "tetrahedron " + num(id) + " (10 nodes) has a Jacobian determinant of " + std::to_string(r) +
              " times its straight one's at a corner or Gauss point: " + corners(t));
    }
  }

  void check_mid_nodes() {
    std::vector<EdgeRecord> edges;
    edges.reserve(6 * nt_);
    for (std::size_t t = 0; t < nt_; ++t) {
      poll(t);
      if (!well_formed_[t]) continue;
      for (int e = 0; e < 6; ++e)
        edges.push_back(EdgeRecord{edge_key(m_.tet_node(t, kTetEdge[e][0]), m_.tet_node(t, kTetEdge[e][1])),
                                   m_.tet_node(t, 4 + e), Index(t)});
    }
    std::sort(edges.begin(), edges.end(), [](const EdgeRecord& x, const EdgeRecord& y) {
      if (x.key != y.key) return x.key < y.key;
      if (x.mid != y.mid) return x.mid < y.mid;
      return x.t < y.t;
    });
    for (std::size_t i = 0; i < edges.size();) {
      std::size_t j = i + 1;
      while (j < edges.size() && edges[j].key == edges[i].key) ++j;
      // Sorted by mid within the run: the run is consistent iff its ends agree.
      if (edges[i].mid != edges[j - 1].mid) {
        std::vector<std::int64_t> ids;
        std::string mids;
        for (std::size_t k = i; k < j; ++k) {
          ids.push_back(m_.tet_id(edges[k].t));
          if (k == i || edges[k].mid != edges[k - 1].mid) mids += " " + num(m_.node_id(edges[k].mid));
        }
        std::sort(ids.begin(), ids.end());
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
        std::string names;
        for (auto id : ids) names += " " + num(id);
        add(ViolationKind::BadMidNode, ids,
            "edge " + num(m_.node_id(key_lo(edges[i].key))) + "-" + num(m_.node_id(key_hi(edges[i].key))) +
                " has different mid-edge nodes (" + mids.substr(1) + ") in tetrahedra" + names);
      }
      i = j;
    }
  }

  const TetMesh& m_;
  const std::size_t nn_, nt_;
  const int npt_;
  util::ProgressPoll poll_;
  std::vector<char> used_;
  std::vector<char> well_formed_;
  std::vector<char> finite_;
  std::vector<Violation> out_;
};

}  // namespace

std::vector<Violation> validate(const TetMesh& mesh, const std::function<bool(double)>& progress) {
  return Validator(mesh, progress).run();
}

}  // namespace bisect
