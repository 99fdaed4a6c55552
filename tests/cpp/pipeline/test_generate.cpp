// The 3D generator end to end (thesis 6.9.2): every mesh passes the validator, fills the input's
// volume, keeps cavities empty, shares interface nodes between regions, and lands near the
// requested count; on the ../shared models when they are here.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <thread>

#include "bisect/errors.hpp"
#include "bisect/generate.hpp"
#include "bisect/io.hpp"
#include "bisect/polyhedral_model.hpp"
#include "bisect/quality.hpp"
#include "bisect/shared_models.hpp"
#include "bisect/validate.hpp"
#include "pipeline/generate_checks.hpp"
#include "generated_solids.hpp"
#include "poly_shapes.hpp"

namespace bisect {
namespace {

namespace fs = std::filesystem;

TEST(Generate, CubeAndLPrismNearTheRequestedCount) {
  for (const std::string& text : {test::unit_cube(), test::l_prism()})
    for (std::int64_t n : {2000, 10000}) {
      const PolyInput in = test::poly(text);
      GenerateOptions opt;
      opt.sizing.elements = n;
      GenerateStats st;
      const TetMesh m = generate_mesh(in, opt, &st);
      expect_sound(m, in, text.substr(0, 12) + std::to_string(n));
      EXPECT_NEAR(static_cast<double>(m.num_tets()), static_cast<double>(n), 0.2 * n) << n;
      EXPECT_EQ(st.tets, static_cast<std::int64_t>(m.num_tets()));
      const QualitySummary q = summarize_quality(element_quality(m));
      EXPECT_GT(q.alpha.mean, 0.2) << n;  // the regular tetrahedron has 1/3
      RecordProperty("alpha_mean_" + std::to_string(n), std::to_string(q.alpha.mean));
    }
}

// A 100 x 5 x 1 plate (each plate of FreeCAD's bimetal strip) at 2*10^5 was one convex cell: its
// star fill, all needles, left tetrahedra of 3.3 degrees (0.017% under 10) in 7.0 s. Cut into
// eight cells 12.5 long (bisect/slender_split.hpp): none under 10 degrees, in 2 s.
TEST(Generate, ASlenderPlateIsCutIntoCellsAndKeepsItsAngles) {
  const PolyInput in = test::poly(test::prism({{0, 0}, {100, 0}, {100, 5}, {0, 5}}));
  GenerateOptions opt;
  opt.sizing.elements = 200000;
  GenerateStats st;
  const TetMesh m = generate_mesh(in, opt, &st);
  expect_sound(m, in, "plate");
  EXPECT_EQ(st.convex_cells, 8);
  const QualitySummary q = summarize_quality(element_quality(m));
  EXPECT_GE(q.dihedral_min.min, 5.0);
  EXPECT_LT(q.pct_dihedral_below_10, 0.005);
}

TEST(Generate, TwoRegionsShareTheirInterfaceAndLeaveTheCavityEmpty) {
  // the thesis's cube with a cavity beside a second cube (6.13 example 1)
  const PolyInput in = read_poly(std::string(BISECT_TEST_DATA) + "/cube-cavity-adjacent-cube.poly");
  for (bool delaunay : {true, false}) {
    GenerateOptions opt;
    opt.sizing.elements = 4000;
    opt.delaunay_insertion = delaunay;
    GenerateStats st;
    const TetMesh m = generate_mesh(in, opt, &st);
    expect_sound(m, in, delaunay ? "delaunay" : "minmax");
    EXPECT_EQ(st.regions, 2);
    std::map<Index, double> volume;
    std::map<std::array<Index, 3>, std::set<Index>> face_regions;
    for (std::size_t t = 0; t < m.num_tets(); ++t) {
      const Vec3 &a = m.nodes[m.tet_node(t, 0)], &b = m.nodes[m.tet_node(t, 1)], &c = m.nodes[m.tet_node(t, 2)], &d = m.nodes[m.tet_node(t, 3)];
      volume[m.region[t]] += (b - a).dot((c - a).cross(d - a)) / 6;
      const Vec3 g = (a + b + c + d) / 4;
      EXPECT_FALSE(g.x() > 0.25 && g.x() < 0.75 && g.y() > 0.25 && g.y() < 0.75 && g.z() > 0.25 && g.z() < 0.75) << "a tetrahedron in the cavity";
      for (const auto& f : kTetFace) {
        std::array<Index, 3> k{m.tet_node(t, f[0]), m.tet_node(t, f[1]), m.tet_node(t, f[2])};
        std::sort(k.begin(), k.end());
        face_regions[k].insert(m.region[t]);
      }
    }
    ASSERT_EQ(volume.size(), 2u);
    EXPECT_NEAR(volume.begin()->second, 1 - 0.125, 1e-9);  // the cube less its cavity
    EXPECT_NEAR(volume.rbegin()->second, 1, 1e-9);         // the neighbour
    // the interface x = 1: faces with a tetrahedron of each region on it, covering its unit area
    double shared = 0;
    for (const auto& [k, regions] : face_regions)
      if (regions.size() == 2) shared += 0.5 * (m.nodes[k[1]] - m.nodes[k[0]]).cross(m.nodes[k[2]] - m.nodes[k[0]]).norm();
    EXPECT_NEAR(shared, 1.0, 1e-9);
  }
}

TEST(Generate, OptionsErrorsAndCancel) {
  const PolyInput in = test::poly(test::unit_cube());
  PolyInput no_r = in;
  no_r.required_elements = 0;
  EXPECT_THROW(generate_mesh(no_r, {}), InputError);
  GenerateOptions opt;
  opt.sizing.size = 0.25;
  const TetMesh m = generate_mesh(in, opt);  // an absolute size: no calibration
  expect_sound(m, in, "size 0.25");
  int calls = 0;
  opt.progress = [&](double) { return ++calls < 2; };
  EXPECT_THROW(generate_mesh(in, opt), Cancelled);
}

// The face grids and cell fillings run on several threads; the mesh must not depend on how
// many, and the progress callback runs on the caller's thread only.
TEST(Generate, TheMeshIsTheSameForEveryThreadCount) {
  const PolyInput in = read_poly(std::string(BISECT_TEST_DATA) + "/cube-cavity-adjacent-cube.poly");
  const std::thread::id caller = std::this_thread::get_id();
  TetMesh first;
  for (int threads : {1, 2, 3, 8}) {
    GenerateOptions opt;
    opt.sizing.elements = 6000;
    opt.threads = threads;
    bool off_thread = false;
    opt.progress = [&](double) {
      off_thread |= std::this_thread::get_id() != caller;
      return true;
    };
    const TetMesh m = generate_mesh(in, opt);
    EXPECT_FALSE(off_thread) << threads;
    if (threads == 1) {
      expect_sound(m, in, "threads 1");
      first = m;
      continue;
    }
    ASSERT_EQ(m.nodes.size(), first.nodes.size()) << threads;
    ASSERT_EQ(m.num_tets(), first.num_tets()) << threads;
    EXPECT_TRUE(m.nodes == first.nodes) << threads;
    EXPECT_TRUE(m.tets == first.tets) << threads;
    EXPECT_TRUE(m.region == first.region) << threads;
    EXPECT_TRUE(m.tris == first.tris) << threads;
  }
  // cancelled while cells fill on two threads: the call ends with Cancelled, nothing left running
  GenerateOptions opt;
  opt.sizing.elements = 6000;
  opt.threads = 2;
  opt.progress = [](double x) { return x < 0.5; };
  EXPECT_THROW(generate_mesh(in, opt), Cancelled);
}

// A mesh large enough for the optimisation's passes to run in blocks on several threads
// (optimize/block_pass.hpp): still the same mesh for every thread count, regions and interface
// included, and as good as the whole-mesh passes on one thread leave it.
TEST(Generate, TheOptimisationInBlocksIsTheSameForEveryThreadCount) {
  const PolyInput in = read_poly(std::string(BISECT_TEST_DATA) + "/cube-cavity-adjacent-cube.poly");
  TetMesh first;
  for (int threads : {1, 2, 4}) {
    GenerateOptions opt;
    opt.sizing.elements = 50000;
    opt.threads = threads;
    GenerateStats st;
    const TetMesh m = generate_mesh(in, opt, &st);
    EXPECT_GT(st.optimize_blocks, 1) << threads;
    if (threads == 1) {
      expect_sound(m, in, "blocks, threads 1");
      const QualitySummary q = summarize_quality(element_quality(m));
      EXPECT_GT(q.alpha.mean, 0.25);
      EXPECT_GT(q.dihedral_min.min, 8.0);
      first = m;
      continue;
    }
    ASSERT_EQ(m.num_tets(), first.num_tets()) << threads;
    EXPECT_TRUE(m.nodes == first.nodes) << threads;
    EXPECT_TRUE(m.tets == first.tets) << threads;
    EXPECT_TRUE(m.region == first.region) << threads;
    EXPECT_TRUE(m.tris == first.tris) << threads;
  }
}

// --order 2: the same corners and tetrahedra, a mid-node at the middle of every edge, shared by
// every tetrahedron and boundary triangle on it; the validator's checks of 10-node meshes pass.
TEST(Generate, SecondOrderAddsSharedMidEdgeNodes) {
  const PolyInput in = read_poly(std::string(BISECT_TEST_DATA) + "/cube-cavity-adjacent-cube.poly");
  GenerateOptions opt;
  opt.sizing.elements = 3000;
  const TetMesh linear = generate_mesh(in, opt);
  opt.order = 2;
  GenerateStats st;
  const TetMesh quad = generate_mesh(in, opt, &st);
  ASSERT_EQ(quad.order, 2);
  expect_sound(quad, in, "order 2");
  ASSERT_EQ(quad.num_tets(), linear.num_tets());
  ASSERT_EQ(quad.num_tris(), linear.num_tris());
  EXPECT_EQ(st.nodes, static_cast<std::int64_t>(quad.nodes.size()));
  std::set<std::pair<Index, Index>> edges;
  for (std::size_t t = 0; t < linear.num_tets(); ++t)
    for (const auto& e : kTetEdge) {
      const Index a = linear.tet_node(t, e[0]), b = linear.tet_node(t, e[1]);
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  EXPECT_EQ(quad.nodes.size(), linear.nodes.size() + edges.size());  // one mid-node per edge
  for (std::size_t t = 0; t < quad.num_tets(); ++t) {
    for (int i = 0; i < 4; ++i) ASSERT_EQ(quad.tet_node(t, i), linear.tet_node(t, i));
    for (int e = 0; e < 6; ++e) {
      const Vec3 mid = 0.5 * (quad.nodes[quad.tet_node(t, kTetEdge[e][0])] + quad.nodes[quad.tet_node(t, kTetEdge[e][1])]);
      EXPECT_EQ(quad.nodes[quad.tet_node(t, 4 + e)], mid);
    }
  }
  for (std::size_t f = 0; f < quad.num_tris(); ++f)
    for (int e = 0; e < 3; ++e) {
      const Vec3 mid = 0.5 * (quad.nodes[quad.tris[6 * f + kTriEdge[e][0]]] + quad.nodes[quad.tris[6 * f + kTriEdge[e][1]]]);
      EXPECT_EQ(quad.nodes[quad.tris[6 * f + 3 + e]], mid);
    }
  opt.order = 3;
  EXPECT_THROW(generate_mesh(in, opt), InputError);
}

// --boundary-flips: the 2-2 transformation re-triangulates the outer boundary within its input
// faces; the mesh stays sound, keeps its boundary triangle count, and every boundary triangle
// still lies in the plane of the input face it is tagged with.
TEST(Generate, BoundaryFlipsKeepTheBoundaryOnItsFaces) {
  const PolyInput in = read_poly(std::string(BISECT_TEST_DATA) + "/cube-cavity-adjacent-cube.poly");
  GenerateOptions opt;
  opt.sizing.elements = 4000;
  const TetMesh plain = generate_mesh(in, opt);
  opt.optimize.boundary_flips = true;
  const TetMesh flipped = generate_mesh(in, opt);
  expect_sound(flipped, in, "boundary flips");
  EXPECT_EQ(flipped.num_tris(), plain.num_tris());
  for (std::size_t f = 0; f < flipped.num_tris(); ++f) {
    const PolyFace& face = in.faces[flipped.tri_tag[f]];
    const Vec3 &p = in.nodes[face.nodes[0]], &q = in.nodes[face.nodes[1]], &r = in.nodes[face.nodes[2]];
    const Vec3 n = (q - p).cross(r - p).normalized();
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(n.dot(flipped.nodes[flipped.tris[3 * f + k]] - p), 0, 1e-12);
  }
}

// Random CSG solids (unions of boxes and rotated prisms, some hollow): every one that decomposes
// meshes into a valid mesh of its volume. BISECT_RANDOM_SOLIDS overrides the count (default 60).
TEST(Generate, RandomCsgSolids) {
  const char* env = std::getenv("BISECT_RANDOM_SOLIDS");
  const int n = env ? std::atoi(env) : 60;
  int meshed = 0, not_decomposed = 0;
  for (int seed = 1; seed <= n; ++seed) {
    std::string what;
    const PolyInput in = testing::random_csg_polyhedron(static_cast<std::uint64_t>(seed), &what, nullptr);
    try {
      decompose(in);
    } catch (const Error&) {  // counted by the decomposition's own test
      ++not_decomposed;
      continue;
    }
    GenerateOptions opt;
    opt.sizing.elements = 3000;
    try {
      const TetMesh m = generate_mesh(in, opt);
      expect_sound(m, in, what);
      ++meshed;
    } catch (const Error& e) {
      ADD_FAILURE() << what << ": " << e.what();
    }
    if (HasFailure()) break;
  }
  std::cout << "random CSG solids meshed: " << meshed << ", not decomposed: " << not_decomposed << "\n";
  EXPECT_GE(meshed, n * 9 / 10);
}

class GenerateSharedModels : public ::testing::TestWithParam<std::string> {};

TEST_P(GenerateSharedModels, ValidMeshesOfTheInputsVolume) {
  const fs::path p = fs::path(BISECT_SHARED_DIR) / GetParam();
  if (!fs::exists(p)) GTEST_SKIP() << p << " is not here (../shared is absent)";
  const PolyInput in = read_polyhedral(p.string());
  for (std::int64_t n : {1000, 10000}) {
    GenerateOptions opt;
    opt.sizing.elements = n;
    GenerateStats st;
    const TetMesh m = generate_mesh(in, opt, &st);
    expect_sound(m, in, GetParam() + " " + std::to_string(n));
    // within 20% of R, unless the input's own facets need more tetrahedra than R
    if (std::abs(static_cast<double>(m.num_tets()) - static_cast<double>(n)) > 0.2 * static_cast<double>(n)) {
      EXPECT_GT(st.count_floor, n) << GetParam() << " " << n << ": " << m.num_tets() << " tetrahedra";
    }
    EXPECT_GE(st.fillings, 1);
    EXPECT_LE(st.fillings, 3 * (1 + st.quality_meshes));  // each count search fills at most three times
    EXPECT_LE(st.quality_meshes, 4);
    RecordProperty("tets_" + std::to_string(n), std::to_string(m.num_tets()));
  }
}

INSTANTIATE_TEST_SUITE_P(Files, GenerateSharedModels, ::testing::ValuesIn(test::kSharedPolyhedralInputs),
                         [](const ::testing::TestParamInfo<std::string>& i) { return test::test_name_of(i.param); });

}  // namespace
}  // namespace bisect
