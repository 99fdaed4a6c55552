// Parts far from the origin (issue 20): a unit cube at 1e8, a rotated cube at 1e6 and a unit
// square at 1e8 mesh as they do at the origin. The entry points mesh a copy moved near the origin
// by an exact shift and move the result back, so the input's nodes come back bit for bit.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "bisect/generate.hpp"
#include "bisect/io.hpp"
#include "bisect/polyhedral_model.hpp"
#include "bisect/validate.hpp"
#include "geom/predicates.hpp"
#include "geom/recentre.hpp"
#include "mesh2d/planar_mesher.hpp"
#include "pipeline/generate_checks.hpp"

namespace bisect {
namespace {

std::string data(const std::string& name) { return std::string(BISECT_TEST_DATA) + "/" + name; }

// Volume about a point of the part: the coordinates' own magnitude does not enter.
double volume_about(const TetMesh& m, const Vec3& o) {
  double v = 0;
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    const Vec3 a = m.nodes[m.tet_node(t, 0)] - o, b = m.nodes[m.tet_node(t, 1)] - o, c = m.nodes[m.tet_node(t, 2)] - o,
               d = m.nodes[m.tet_node(t, 3)] - o;
    v += (b - a).dot((c - a).cross(d - a)) / 6;
  }
  return v;
}

void expect_input_nodes_kept(const std::vector<Vec3>& out, const std::vector<Vec3>& input, const std::string& what) {
  std::set<std::array<double, 3>> have;
  for (const Vec3& p : out) have.insert({p.x(), p.y(), p.z()});
  for (const Vec3& p : input) EXPECT_TRUE(have.count({p.x(), p.y(), p.z()})) << what << ": input node moved";
}

TEST(FarFromOrigin, TheShiftIsExactAndLeavesNearPartsAlone) {
  const std::vector<Vec3> near{{0, 0, 0}, {1, 1, 1}}, offset{{2, 0, 0}, {3, 1, 1}};
  EXPECT_EQ(geom::recentring_shift(near), Vec3::Zero());
  EXPECT_EQ(geom::recentring_shift(offset), Vec3::Zero());  // within a few extents: as given
  const std::vector<Vec3> far{{1e8 + 0.1, -3e7, 1e-3}, {1e8 + 0.7, -3e7 + 0.25, 0.4}};
  const Vec3 s = geom::recentring_shift(far);
  EXPECT_EQ(s.z(), 0.0);
  for (const Vec3& p : far) {
    const Vec3 q = p - s;
    EXPECT_LT(q.lpNorm<Eigen::Infinity>(), 1.0);
    EXPECT_EQ(q + s, p);  // exact both ways
  }
}

TEST(FarFromOrigin, AUnitCubeAt1e8MeshesAsAtTheOrigin) {
  const PolyInput in = read_poly(data("cube-far.poly"));
  PolyInput at_origin = in;
  for (Vec3& p : at_origin.nodes) p -= Vec3::Constant(1e8);
  GenerateOptions opt;
  opt.sizing.elements = 2000;
  const TetMesh far = generate_mesh(in, opt), near = generate_mesh(at_origin, opt);
  EXPECT_TRUE(validate(far).empty()) << violations(far);
  EXPECT_NEAR(volume_about(far, in.nodes[0]), 1.0, 1e-6);
  EXPECT_NEAR(static_cast<double>(far.num_tets()), 2000.0, 400.0);
  EXPECT_EQ(far.num_tets(), near.num_tets());  // the same mesh, moved
  ASSERT_EQ(far.nodes.size(), near.nodes.size());
  for (std::size_t v = 0; v < far.nodes.size(); ++v) EXPECT_NEAR((far.nodes[v] - near.nodes[v] - Vec3::Constant(1e8)).norm(), 0.0, 1e-7);
  expect_input_nodes_kept(far.nodes, in.nodes, "cube at 1e8");
  // the convex cells (--cells-only) come back at the part's place too
  const Decomposition d = decompose(in);
  EXPECT_EQ(d.cells.size(), 1u);
  expect_input_nodes_kept(d.model.nodes, in.nodes, "cells at 1e8");
  for (const ModelFace& f : d.model.faces) {
    if (!f.alive) continue;
    EXPECT_NEAR(f.normal.dot(d.model.nodes[f.loops[0][0]]) - f.offset, 0.0, 1e-6);
  }
}

TEST(FarFromOrigin, ARotatedCubeAt1e6) {
  const PolyInput in = read_poly(data("rotated-cube-far.poly"));
  for (std::int64_t n : {2000, 10000}) {
    GenerateOptions opt;
    opt.sizing.elements = n;
    const TetMesh m = generate_mesh(in, opt);
    EXPECT_TRUE(validate(m).empty()) << violations(m);
    EXPECT_NEAR(volume_about(m, in.nodes[0]), 1.0, 1e-8);
    EXPECT_NEAR(static_cast<double>(m.num_tets()), static_cast<double>(n), 0.2 * n);
    expect_input_nodes_kept(m.nodes, in.nodes, "rotated cube at 1e6");
    for (const Vec3& p : m.nodes) EXPECT_LT((p - Vec3::Constant(1e6)).norm(), 1.7321);  // within the cube's reach
  }
}

TEST(FarFromOrigin, AUnitSquareAt1e8) {
  const Poly2Input in = read_poly2(data("square-far.poly2"));
  mesh2d::PlanarStats st;
  const mesh2d::TriMesh2 m = mesh2d::mesh_planar(in, {}, &st);
  EXPECT_NEAR(static_cast<double>(m.tris.size()), 200.0, 30.0);
  const Vec2 o = in.nodes[0];
  double area = 0;
  for (const auto& t : m.tris) {
    EXPECT_GT(geom::orient2d(m.nodes[t[0]], m.nodes[t[1]], m.nodes[t[2]]), 0);
    const Vec2 a = m.nodes[t[0]] - o, b = m.nodes[t[1]] - o, c = m.nodes[t[2]] - o;
    area += 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
  }
  EXPECT_NEAR(area, 1.0, 1e-6);
  for (const Vec2& p : m.nodes) {
    EXPECT_GE(p.x(), 1e8);
    EXPECT_LE(p.x(), 1e8 + 1);
    EXPECT_GE(p.y(), 1e8);
    EXPECT_LE(p.y(), 1e8 + 1);
  }
  std::set<std::pair<double, double>> have;
  for (const Vec2& p : m.nodes) have.insert({p.x(), p.y()});
  for (const Vec2& p : in.nodes) EXPECT_TRUE(have.count({p.x(), p.y()})) << "corner moved";
  EXPECT_GE(st.min_angle_deg, 20.0);
}

}  // namespace
}  // namespace bisect
