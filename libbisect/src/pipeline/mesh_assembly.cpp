#include "pipeline/mesh_assembly.hpp"

#include <algorithm>
#include <string>

#include "bisect/errors.hpp"

namespace bisect::pipeline {
namespace {

// Boundary triangles of the mesh, tagged with their input face: on the interfaces, the grids
// of the input faces between two regions; on the outer boundary, the complex's faces (the 2-2
// transformation may have re-triangulated them), outwards, grouped by input face.
void boundary_triangles(const PolyhedralModel& m, const mesh2d::FaceGrids& g, const tet::TetComplex& cx, TetMesh& out) {
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const ModelFace& face = m.faces[f];
    if (!face.alive || face.source < 0 || face.front < 0 || face.back < 0) continue;
    for (const auto& t : g.face_tris[f]) {
      out.tris.insert(out.tris.end(), t.begin(), t.end());
      out.tri_tag.push_back(face.source);
    }
  }
  std::vector<std::pair<Index, std::array<Index, 3>>> outer;
  for (std::size_t t = 0; t < cx.tet.size(); ++t)
    if (cx.alive[t])
      for (int f = 0; f < 4; ++f)
        if (cx.neighbour(t, f) < 0) {
          const auto fv = cx.face(static_cast<Index>(t), f);
          const auto tag = cx.surface_tag.find(tet::face_key(fv[0], fv[1], fv[2]));
          if (tag == cx.surface_tag.end()) throw MeshingError("a boundary face of the mesh lies on no input face (nodes " + std::to_string(fv[0] + 1) + ", " + std::to_string(fv[1] + 1) + ", " + std::to_string(fv[2] + 1) + ")");
          outer.push_back({tag->second, fv});
        }
  std::stable_sort(outer.begin(), outer.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const auto& [tag, fv] : outer) {
    out.tris.insert(out.tris.end(), fv.begin(), fv.end());
    out.tri_tag.push_back(tag);
  }
}

}  // namespace

TetMesh assemble_mesh(const PolyhedralModel& m, const mesh2d::FaceGrids& g, const tet::TetComplex& cx, const std::vector<Vec3>& X, int order) {
  const std::vector<tet::Tet> tets = cx.tets();
  const std::vector<Index> region = cx.tags();
  // used nodes only, in their order (dead model nodes, skipped nodes and removed helpers drop out)
  TetMesh out;
  std::vector<Index> id(X.size(), -1);
  for (const auto& t : tets)
    for (Index v : t) id[v] = 0;
  for (std::size_t v = 0; v < X.size(); ++v)
    if (id[v] == 0) {
      id[v] = static_cast<Index>(out.nodes.size());
      out.nodes.push_back(X[v]);
    }
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const Index v[4] = {id[tets[t][0]], id[tets[t][1]], id[tets[t][2]], id[tets[t][3]]};
    out.add_tet(v, region[t]);
  }
  boundary_triangles(m, g, cx, out);
  for (Index& v : out.tris) v = id[v];
  if (order == 2) out = to_second_order(out);
  return out;
}

}  // namespace bisect::pipeline
