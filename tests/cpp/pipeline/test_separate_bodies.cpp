// Several bodies in one STL (issue 20): each separate body of a region becomes its own model
// region, so that the decomposition never leaves a cell made of two convex pieces; a body inside
// another body's inner shell stays a cavity of it. Bodies touching at a vertex or along an edge
// are meshed each on its own and share those nodes.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "bisect/errors.hpp"
#include "bisect/generate.hpp"
#include "bisect/io.hpp"
#include "bisect/polyhedral_model.hpp"
#include "pipeline/generate_checks.hpp"

namespace bisect {
namespace {

PolyInput data(const std::string& name) { return read_stl(std::string(BISECT_TEST_DATA) + "/" + name); }

Vec3 centroid(const TetMesh& m, std::size_t t) {
  Vec3 c = Vec3::Zero();
  for (int i = 0; i < 4; ++i) c += m.nodes[m.tet_node(t, i)];
  return c / 4;
}

double tet_volume(const TetMesh& m, std::size_t t) {
  const Vec3 &a = m.nodes[m.tet_node(t, 0)], &b = m.nodes[m.tet_node(t, 1)], &c = m.nodes[m.tet_node(t, 2)], &d = m.nodes[m.tet_node(t, 3)];
  return (b - a).dot((c - a).cross(d - a)) / 6;
}

// Every cell convex: each cell vertex lies on the inner side of each of the cell's face planes.
void expect_convex_cells(const Decomposition& d) {
  for (std::size_t c = 0; c < d.cells.size(); ++c) {
    const ConvexCell& cell = d.cells[c];
    for (std::size_t k = 0; k < cell.faces.size(); ++k) {
      const ModelFace& f = d.model.faces[cell.faces[k]];
      const Vec3 out = cell.outward[k] ? f.normal : Vec3(-f.normal);
      for (Index g : cell.faces)
        for (const auto& loop : d.model.faces[g].loops)
          for (Index v : loop) EXPECT_LE(out.dot(d.model.nodes[v] - d.model.nodes[f.loops[0][0]]), 1e-9) << "cell " << c;
    }
  }
}

TEST(SeparateBodies, TwoDisjointCubesAreTwoModelRegionsOfOneInputRegion) {
  const PolyInput in = data("two-cubes.stl");
  ASSERT_EQ(in.regions.size(), 1u);
  PreparationReport rep;
  const PolyhedralModel m = prepare_model(in, &rep);
  EXPECT_EQ(rep.separate_bodies, 1u);
  EXPECT_EQ(rep.inner_shells_as_cavities, 0u);
  ASSERT_EQ(m.regions.size(), 2u);
  EXPECT_EQ(m.regions[0].source, 0);
  EXPECT_EQ(m.regions[1].source, 0);
  const double v0 = m.region_volume(0), v1 = m.region_volume(1);
  EXPECT_NEAR(std::min(v0, v1), 1.0, 1e-12);
  EXPECT_NEAR(std::max(v0, v1), 3.375, 1e-12);
  const Decomposition d = decompose(in);  // what --cells-only writes: two convex cells
  EXPECT_EQ(d.cells.size(), 2u);
  expect_convex_cells(d);
}

TEST(SeparateBodies, TwoDisjointCubesMeshWithTheCountSharedByVolume) {
  const PolyInput in = data("two-cubes.stl");
  for (std::int64_t n : {3000, 12000}) {
    GenerateOptions opt;
    opt.sizing.elements = n;
    GenerateStats st;
    const TetMesh m = generate_mesh(in, opt, &st);
    expect_sound(m, in, "two cubes " + std::to_string(n));
    EXPECT_NEAR(mesh_volume(m), 1.0 + 3.375, 1e-9);
    EXPECT_NEAR(static_cast<double>(m.num_tets()), static_cast<double>(n), 0.2 * n);
    EXPECT_EQ(st.regions, 1);  // one input region
    // each cube gets elements in proportion to its volume: one spacing over the total volume
    std::size_t small = 0;
    double small_volume = 0;
    for (std::size_t t = 0; t < m.num_tets(); ++t)
      if (centroid(m, t).x() < 1.5) ++small, small_volume += tet_volume(m, t);
    EXPECT_NEAR(small_volume, 1.0, 1e-9);
    const double share = static_cast<double>(small) / static_cast<double>(m.num_tets());
    EXPECT_NEAR(share, 1.0 / 4.375, 0.25 / 4.375) << n;
    RecordProperty("small_cube_share_" + std::to_string(n), std::to_string(share));
  }
}

TEST(SeparateBodies, ACubeInsideACubeIsStillACavity) {
  const PolyInput in = data("cube-with-cavity-cube.stl");
  PreparationReport rep;
  const PolyhedralModel m = prepare_model(in, &rep);
  EXPECT_EQ(rep.separate_bodies, 0u);
  EXPECT_EQ(rep.inner_shells_as_cavities, 1u);
  ASSERT_EQ(m.regions.size(), 1u);
  EXPECT_NEAR(m.region_volume(0), 7.0, 1e-12);
  GenerateOptions opt;
  opt.sizing.elements = 4000;
  const TetMesh mesh = generate_mesh(in, opt);
  expect_sound(mesh, in, "cube with cavity");
  EXPECT_NEAR(mesh_volume(mesh), 7.0, 1e-9);
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    const Vec3 c = centroid(mesh, t);
    EXPECT_FALSE((c.array() > 0.5).all() && (c.array() < 1.5).all()) << "a tetrahedron in the cavity";
  }
}

TEST(SeparateBodies, ABodyInsideACavityIsItsOwnBody) {
  // the cavity cube of cube-with-cavity-cube.stl holding a third, solid cube
  PolyInput in = data("cube-with-cavity-cube.stl");
  const PolyInput inner = data("two-cubes.stl");  // its first 12 triangles: the unit cube
  std::map<Index, Index> copy;  // node of the unit cube -> node added
  for (std::size_t f = 0; f < 12; ++f) {
    PolyFace pf = inner.faces[f];
    for (Index& v : pf.nodes) {
      const auto [it, fresh] = copy.emplace(v, static_cast<Index>(in.nodes.size()));
      if (fresh) in.nodes.push_back(0.5 * inner.nodes[v] + Vec3(0.75, 0.75, 0.75));
      v = it->second;
    }
    in.regions[0].faces.push_back(static_cast<Index>(in.faces.size()));
    in.faces.push_back(pf);
  }
  PreparationReport rep;
  const PolyhedralModel m = prepare_model(in, &rep);
  EXPECT_EQ(rep.separate_bodies, 1u);
  ASSERT_EQ(m.regions.size(), 2u);
  EXPECT_NEAR(m.region_volume(0) + m.region_volume(1), 7.125, 1e-12);
  EXPECT_NEAR(std::min(m.region_volume(0), m.region_volume(1)), 0.125, 1e-12);
  GenerateOptions opt;
  opt.sizing.elements = 4000;
  const TetMesh mesh = generate_mesh(in, opt);
  EXPECT_TRUE(validate(mesh).empty()) << violations(mesh);
  EXPECT_NEAR(mesh_volume(mesh), 7.125, 1e-9);
}

TEST(SeparateBodies, ACubeBesideAPrism) {
  const PolyInput in = data("cube-beside-prism.stl");
  PreparationReport rep;
  prepare_model(in, &rep);
  EXPECT_EQ(rep.separate_bodies, 1u);
  const double prism = 0.5 * 16 * 0.36 * std::sin(2 * M_PI / 16) * 1.2;  // 16-gon of radius 0.6, height 1.2
  for (std::int64_t n : {2000, 8000}) {
    GenerateOptions opt;
    opt.sizing.elements = n;
    const TetMesh m = generate_mesh(in, opt);
    expect_sound(m, in, "cube beside prism " + std::to_string(n));
    EXPECT_NEAR(mesh_volume(m), 1.0 + prism, 1e-9);
    EXPECT_NEAR(static_cast<double>(m.num_tets()), static_cast<double>(n), 0.2 * n);
  }
}

TEST(SeparateBodies, CubesTouchingAtAVertexOrAlongAnEdgeShareIt) {
  for (const char* name : {"cubes-touching-at-vertex.stl", "cubes-touching-along-edge.stl"}) {
    const PolyInput in = data(name);
    PreparationReport rep;
    prepare_model(in, &rep);
    EXPECT_EQ(rep.separate_bodies, 1u) << name;
    GenerateOptions opt;
    opt.sizing.elements = 4000;
    const TetMesh m = generate_mesh(in, opt);
    expect_sound(m, in, name);
    EXPECT_NEAR(mesh_volume(m), 2.0, 1e-9) << name;
    EXPECT_NEAR(static_cast<double>(m.num_tets()), 4000.0, 800.0) << name;
  }
}

}  // namespace
}  // namespace bisect
