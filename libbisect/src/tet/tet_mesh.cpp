// TetMesh: appending tetrahedra and face adjacency.
#include "bisect/tet_mesh.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <unordered_map>

#include "bisect/errors.hpp"
#include "util/edge_key.hpp"

namespace bisect {

Index TetMesh::add_tet(const Index* v, Index region_id) {
  const std::size_t t = num_tets();
  if (t >= std::size_t(std::numeric_limits<Index>::max()))
    throw MeshingError("TetMesh::add_tet: more than 2^31-1 tetrahedra");
  // A reader may have filled tets without regions or file ids; keep the parallel arrays aligned
  // so that region[t] and tet_id(t) stay meaningful for every tetrahedron.
  region.resize(t, 0);
  region.push_back(region_id);
  if (!tet_ids.empty()) {
    // The new tetrahedron has no number of its own in the file; continue after the last one.
    while (tet_ids.size() < t) tet_ids.push_back(tet_ids.back() + 1);
    tet_ids.resize(t);
    tet_ids.push_back(t == 0 ? 1 : tet_ids.back() + 1);
  }
  // Copied first: v may point into tets itself, which the insertion may reallocate.
  Index copy[10];
  std::copy(v, v + nodes_per_tet(), copy);
  tets.insert(tets.end(), copy, copy + nodes_per_tet());
  return Index(t);
}

namespace {

// A face as its two larger node indices plus the face code 4*t + f; the smallest node index is
// the bucket it sits in. 12 bytes, no heap object per face.
struct FaceRecord {
  Index mid, hi, code;
};

}  // namespace

std::vector<Index> TetMesh::neighbours() const {
  const std::size_t nt = num_tets();
  const std::size_t nn = nodes.size();
  std::vector<Index> neigh(4 * nt, -1);

  // Sort the faces by their sorted node triple. A counting sort on the smallest node puts the
  // faces into one short bucket per node (about 24 faces in a typical mesh), and each bucket is
  // then sorted on the remaining two nodes: O(n) scatter plus short sorts, cache friendly.
  auto sorted_face = [&](std::size_t t, int f, Index& a, Index& b, Index& c) {
    a = tet_node(t, kTetFace[f][0]);
    b = tet_node(t, kTetFace[f][1]);
    c = tet_node(t, kTetFace[f][2]);
    if (a > b) std::swap(a, b);
    if (b > c) std::swap(b, c);
    if (a > b) std::swap(a, b);
    // Faces naming a node that does not exist stay on the boundary; the validator reports them.
    return a >= 0 && std::size_t(c) < nn;
  };

  std::vector<Index> start(nn + 1, 0);
  for (std::size_t t = 0; t < nt; ++t)
    for (int f = 0; f < 4; ++f) {
      Index a, b, c;
      if (sorted_face(t, f, a, b, c)) ++start[a + 1];
    }
  for (std::size_t n = 0; n < nn; ++n) start[n + 1] += start[n];

  std::vector<FaceRecord> faces(start[nn]);
  std::vector<Index> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < nt; ++t)
    for (int f = 0; f < 4; ++f) {
      Index a, b, c;
      if (sorted_face(t, f, a, b, c)) faces[fill[a]++] = FaceRecord{b, c, Index(4 * t + f)};
    }
  // Ties broken by code, so that of a face shared by more than two tetrahedra the two lowest
  // codes pair up: deterministic, as the header promises "the first pair".
  auto less = [](const FaceRecord& x, const FaceRecord& y) {
    if (x.mid != y.mid) return x.mid < y.mid;
    if (x.hi != y.hi) return x.hi < y.hi;
    return x.code < y.code;
  };
  auto same_face = [&](std::size_t i, std::size_t j) { return faces[i].mid == faces[j].mid && faces[i].hi == faces[j].hi; };
  for (std::size_t n = 0; n < nn; ++n) {
    const std::size_t first = start[n], last = start[n + 1];
    if (last - first > 1) std::sort(faces.begin() + first, faces.begin() + last, less);
    for (std::size_t i = first; i < last;) {
      std::size_t j = i + 1;
      while (j < last && same_face(i, j)) ++j;
      if (j - i >= 2) {  // of a longer run only the first pair is linked
        neigh[faces[i].code] = faces[i + 1].code;
        neigh[faces[i + 1].code] = faces[i].code;
      }
      i = j;
    }
  }
  return neigh;
}

TetMesh to_second_order(const TetMesh& linear, const std::function<bool()>& cancelled) {
  if (linear.order == 2) return linear;
  TetMesh out = linear;
  out.order = 2;
  out.tets.clear();
  out.tris.clear();
  out.tet_ids.clear();
  out.region.clear();
  std::unordered_map<std::uint64_t, Index> mid;  // edge (lo << 32 | hi) -> its mid-node
  mid.reserve(linear.num_tets() * 2);
  auto middle = [&](Index a, Index b) {
    const std::uint64_t key = edge_key(a, b);
    auto [it, fresh] = mid.emplace(key, Index(out.nodes.size()));
    if (fresh) {
      if (out.nodes.size() >= std::size_t(std::numeric_limits<Index>::max())) throw MeshingError("to_second_order: more than 2^31-1 nodes");
      out.nodes.push_back(0.5 * (linear.nodes[a] + linear.nodes[b]));
      if (!out.node_ids.empty()) out.node_ids.push_back(out.node_ids.back() + 1);
    }
    return it->second;
  };
  out.tets.reserve(linear.num_tets() * 10);
  for (std::size_t t = 0; t < linear.num_tets(); ++t) {
    if ((t & 4095) == 4095 && cancelled && cancelled()) throw Cancelled();  // 1.8 s at 10^6
    Index v[10];
    for (int i = 0; i < 4; ++i) v[i] = linear.tet_node(t, i);
    for (int e = 0; e < 6; ++e) v[4 + e] = middle(v[kTetEdge[e][0]], v[kTetEdge[e][1]]);
    out.add_tet(v, t < linear.region.size() ? linear.region[t] : 0);
  }
  if (!linear.tet_ids.empty()) out.tet_ids = linear.tet_ids;
  for (std::size_t f = 0; f < linear.num_tris(); ++f) {
    Index v[6];
    for (int i = 0; i < 3; ++i) v[i] = linear.tris[3 * f + i];
    for (int e = 0; e < 3; ++e) v[3 + e] = middle(v[kTriEdge[e][0]], v[kTriEdge[e][1]]);
    out.tris.insert(out.tris.end(), v, v + 6);
  }
  return out;
}

}  // namespace bisect
