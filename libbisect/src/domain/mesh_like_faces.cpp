#include "domain/mesh_like_faces.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace bisect::domain {
namespace {

// The outward unit normal of a planar face (zero for any other face, or a degenerate one).
Vec3 plane_normal(const BrepFace& f) {
  if (!f.planar || !f.surface) return Vec3::Zero();
  Vec2 uv = f.surface->uv_min();
  if (!std::isfinite(uv.x()) || !std::isfinite(uv.y())) uv = Vec2(0, 0);
  Vec3 du, dv;
  f.surface->derivatives(uv, &du, &dv);
  const Vec3 n = du.cross(dv);
  if (!(n.norm() > 0)) return Vec3::Zero();
  return (f.reversed ? -1.0 : 1.0) * n.normalized();
}

bool is_triangle(const BrepFace& f) { return f.planar && f.wires.size() == 1 && f.wires[0].size() == 3; }

}  // namespace

MeshLikeFaces mesh_like_faces(const BrepInput& in) {
  MeshLikeFaces out;
  std::vector<Vec3> normal(in.faces.size(), Vec3::Zero());
  std::vector<std::vector<Index>> faces_of(in.edges.size());
  for (std::size_t f = 0; f < in.faces.size(); ++f) {
    if (!is_triangle(in.faces[f])) continue;
    normal[f] = plane_normal(in.faces[f]);
    for (const BrepEdgeUse& use : in.faces[f].wires[0])
      if (use.edge >= 0 && static_cast<std::size_t>(use.edge) < faces_of.size()) faces_of[use.edge].push_back(static_cast<Index>(f));
  }
  // the same plane to within about 1.4e-5 radians: an STL's single-precision facets of one flat
  // face differ by about 1e-7
  constexpr double kSameDirection = 1 - 1e-10;
  std::vector<char> counted(in.faces.size(), 0);
  for (const std::vector<Index>& fs : faces_of) {
    if (fs.size() != 2 || fs[0] == fs[1]) continue;
    const Vec3 &n0 = normal[fs[0]], &n1 = normal[fs[1]];
    if (n0 == Vec3::Zero() || n1 == Vec3::Zero() || n0.dot(n1) < kSameDirection) continue;
    if (out.a < 0) out.a = std::min(fs[0], fs[1]), out.b = std::max(fs[0], fs[1]);
    for (Index f : fs)
      if (!counted[f]) counted[f] = 1, ++out.triangles;
  }
  return out;
}

std::string mesh_like_hint(const MeshLikeFaces& found) {
  if (found.triangles < kMeshLikeTriangles) return "";
  return face_name(found.a) + " and " + face_name(found.b) + " (and " + std::to_string(found.triangles - 2) +
         " more triangles) lie in one plane, as the triangles of a shape made from a mesh do: their edges and sharp corners "
         "bound the elements; Part's refine (Part > Create a copy > Refine shape, or Shape.removeSplitter()) merges them";
}

}  // namespace bisect::domain
