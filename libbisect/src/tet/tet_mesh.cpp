// TetMesh: appending tetrahedra and face adjacency.
#include "bisect/tet_mesh.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <unordered_map>

#include "bisect/errors.hpp"
#include "tet/face_file.hpp"
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

std::vector<Index> TetMesh::neighbours() const {
  // Faces matched through their smallest node (face_file.hpp). Faces naming a node that does
  // not exist stay on the boundary (the validator reports them). Of a face shared by more than
  // two tetrahedra only the first pair, the two lowest codes, is linked: deterministic, as the
  // header promises.
  std::vector<Index> neigh(4 * num_tets(), -1);
  const tet::FaceFile file = tet::file_faces(
      nodes.size(), num_tets(), 1,
      [&](std::size_t t, std::array<Index, 4>& v) {
        for (int k = 0; k < 4; ++k) v[static_cast<std::size_t>(k)] = tet_node(t, k);
        return true;
      },
      [] {});
  tet::for_each_face(file, 0, file.nodes(), [&](Index, const tet::FiledFace* i, const tet::FiledFace* end) {
    if (end - i < 2) return;
    neigh[static_cast<std::size_t>(i[0].tf)] = i[1].tf;
    neigh[static_cast<std::size_t>(i[1].tf)] = i[0].tf;
  });
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
