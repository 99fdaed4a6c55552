// Merging exactly coplanar triangles of a soup into polygon faces, holes included, before meshing.
#include <gtest/gtest.h>

#include "bisect/generate.hpp"
#include "bisect/polyhedral_model.hpp"
#include "bisect/validate.hpp"
#include "domain/merge_facets.hpp"

namespace bisect {
namespace {

// A 3 x 3 x 1 plate with a 1 x 1 square hole through it, as outward triangles.
PolyInput plate_with_hole_soup() {
  PolyInput in;
  in.source = "plate.stl";
  const double o[4][2] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}}, h[4][2] = {{1, 1}, {2, 1}, {2, 2}, {1, 2}};
  for (int z = 0; z < 2; ++z) {
    for (const auto& p : o) in.nodes.push_back({p[0], p[1], double(z)});
    for (const auto& p : h) in.nodes.push_back({p[0], p[1], double(z)});
  }
  auto O = [](int k, int z) { return static_cast<Index>(8 * z + k % 4); };
  auto H = [](int k, int z) { return static_cast<Index>(8 * z + 4 + k % 4); };
  auto quad = [&](Index a, Index b, Index c, Index d) {  // counter-clockwise from outside
    in.faces.push_back({{a, b, c}, -1});
    in.faces.push_back({{a, c, d}, -1});
  };
  for (int k = 0; k < 4; ++k) {
    quad(O(k, 1), O(k + 1, 1), H(k + 1, 1), H(k, 1));  // top ring
    quad(H(k, 0), H(k + 1, 0), O(k + 1, 0), O(k, 0));  // bottom ring
    quad(O(k, 0), O(k + 1, 0), O(k + 1, 1), O(k, 1));  // outer wall
    quad(H(k + 1, 0), H(k, 0), H(k, 1), H(k + 1, 1));  // hole wall
  }
  in.regions.push_back({});
  for (std::size_t f = 0; f < in.faces.size(); ++f) in.regions[0].faces.push_back(static_cast<Index>(f));
  in.required_elements = 3000;
  return in;
}

TEST(MergeFacets, PlateWithHoleBecomesPolygonsWithHoles) {
  const PolyInput soup = plate_with_hole_soup();
  ASSERT_NEAR(summarize(soup).volume, 8, 1e-12);
  std::size_t merged = 0;
  const PolyInput m = merge_coplanar_triangles(soup, &merged);
  EXPECT_EQ(merged, 10u);  // top, bottom and the eight walls
  EXPECT_EQ(m.faces.size(), 12u);  // two annuli as a face and its hole each, eight quads
  std::size_t holes = 0;
  for (const PolyFace& f : m.faces) {
    holes += f.hole_of >= 0;
    EXPECT_EQ(f.nodes.size(), 4u);
  }
  EXPECT_EQ(holes, 2u);
  EXPECT_NEAR(summarize(m).volume, 8, 1e-12);
  PreparationReport rep;
  prepare_model(m, &rep);
  EXPECT_EQ(rep.face_holes, 2u);
  // and the mesh of it is valid and fills the plate
  const TetMesh mesh = generate_mesh(soup, {});
  EXPECT_TRUE(validate(mesh).empty());
  double v = 0;
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    const Vec3 &a = mesh.nodes[mesh.tet_node(t, 0)], &b = mesh.nodes[mesh.tet_node(t, 1)], &c = mesh.nodes[mesh.tet_node(t, 2)],
               &d = mesh.nodes[mesh.tet_node(t, 3)];
    v += (b - a).dot((c - a).cross(d - a)) / 6;
  }
  EXPECT_NEAR(v, 8, 1e-9);
}

TEST(MergeFacets, FoldedOrOffPlaneNeighboursStayApart) {
  // a tetrahedron's faces: no two coplanar, nothing merges
  PolyInput in;
  in.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  in.faces = {{{0, 2, 1}, -1}, {{0, 1, 3}, -1}, {{1, 2, 3}, -1}, {{0, 3, 2}, -1}};
  in.regions = {{{0, 1, 2, 3}, false}};
  std::size_t merged = 7;
  const PolyInput m = merge_coplanar_triangles(in, &merged);
  EXPECT_EQ(merged, 0u);
  EXPECT_EQ(m.faces.size(), 4u);
  // a square split in two triangles that face opposite ways is not merged either
  PolyInput flip;
  flip.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  flip.faces = {{{0, 1, 2}, -1}, {{0, 3, 2}, -1}};
  flip.regions = {{{0, 1}, false}};
  EXPECT_EQ(merge_coplanar_triangles(flip, &merged).faces.size(), 2u);
  EXPECT_EQ(merged, 0u);
}

}  // namespace
}  // namespace bisect
