// Geometry preparation (thesis 6.12): orientation by rays, interfaces, cavities, sub-domains and
// the errors for inputs that cannot be prepared.
#include <gtest/gtest.h>

#include <sstream>

#include "bisect/io.hpp"
#include "bisect/polyhedral_model.hpp"
#include "input_error.hpp"
#include "poly_shapes.hpp"

namespace bisect {
namespace {

using test::error_of;

using test::poly;

// A unit cube; faces 1, 3 and 5 run clockwise seen from outside, as .poly allows.
const char* kCube = R"(6 8 1 0
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
4 1 2 3 4
4 5 6 7 8
4 5 6 2 1
4 2 3 7 6
4 7 8 4 3
4 4 1 5 8
6 1 2 3 4 5 6
)";

TEST(Prepare, EveryFaceLearnsWhichSideIsInside) {
  const PolyhedralModel m = prepare_model(poly(kCube));
  ASSERT_EQ(m.regions.size(), 1u);
  int kept_reversed = 0;
  for (std::size_t i = 0; i < m.faces.size(); ++i) {
    const ModelFace& f = m.faces[i];
    EXPECT_TRUE((f.back == 0) != (f.front == 0));  // the cube on one side, nothing on the other
    const Vec3 centre = 0.5 * (m.nodes[f.loops[0][0]] + m.nodes[f.loops[0][2]]);
    EXPECT_GT(m.outward(static_cast<Index>(i), 0).dot(centre - Vec3(0.5, 0.5, 0.5)), 0.4);
    kept_reversed += f.front == 0;  // the normal the file gave, pointing in (9.1.1: kept)
  }
  EXPECT_EQ(kept_reversed, 3);
  EXPECT_NEAR(m.region_volume(0), 1.0, 1e-15);
}

TEST(Prepare, InterfacesCavitiesAndHoles) {
  PreparationReport rep;
  const PolyhedralModel m = prepare_model(read_poly(std::string(BISECT_TEST_DATA) + "/cube-cavity-adjacent-cube.poly"), &rep);
  EXPECT_EQ(rep.interfaces, 1u);
  EXPECT_EQ(rep.cavities, 1u);
  ASSERT_EQ(m.regions.size(), 2u);  // the cavity is no region of the model, only a boundary
  EXPECT_NEAR(m.region_volume(0), 1.0 - 0.125, 1e-12);
  EXPECT_NEAR(m.region_volume(1), 1.0, 1e-12);
  EXPECT_EQ(rep.region_of_input[2], -1);

  PreparationReport rep2;
  prepare_model(read_poly(std::string(BISECT_TEST_DATA) + "/reentry-box.poly"), &rep2);
  EXPECT_EQ(rep2.face_holes, 1u);
}

TEST(Prepare, SubDomainBoundsTheRegionAroundIt) {
  // a small cube inside a big one, as its own region: its faces are interfaces
  const PolyInput in = poly(R"(12 16 2 0
0 0 0
4 0 0
4 4 0
0 4 0
0 0 4
4 0 4
4 4 4
0 4 4
1 1 1
2 1 1
2 2 1
1 2 1
1 1 2
2 1 2
2 2 2
1 2 2
4 1 2 3 4
4 5 6 7 8
4 1 2 6 5
4 2 3 7 6
4 3 4 8 7
4 4 1 5 8
4 9 10 11 12
4 13 14 15 16
4 9 10 14 13
4 10 11 15 14
4 11 12 16 15
4 12 9 13 16
6 1 2 3 4 5 6
6 7 8 9 10 11 12
)");
  PreparationReport rep;
  const PolyhedralModel m = prepare_model(in, &rep);
  EXPECT_EQ(rep.sub_domains, 1u);
  EXPECT_EQ(rep.interfaces, 6u);
  EXPECT_NEAR(m.region_volume(0), 63.0, 1e-12);
  EXPECT_NEAR(m.region_volume(1), 1.0, 1e-12);
  const Decomposition d = decompose(in);
  double v0 = 0;
  for (const ConvexCell& c : d.cells)
    for (std::size_t k = 0; k < c.faces.size(); ++k)
      if (c.source_region == 0) v0 += (c.outward[k] ? 1 : -1) * d.model.faces[c.faces[k]].offset * d.model.face_area(c.faces[k]) / 3;
  EXPECT_NEAR(v0, 63.0, 1e-9);
}

TEST(Prepare, InnerShellOfOneRegionIsACavity) {
  // STL and OFF have no cavity flag: a shell inside another shell of the same region is one
  PolyInput in = poly(kCube);
  const std::size_t base = in.nodes.size(), faces = in.faces.size();
  for (std::size_t i = 0; i < base; ++i) in.nodes.push_back(0.25 * in.nodes[i] + Vec3(0.375, 0.375, 0.375));
  for (std::size_t f = 0; f < faces; ++f) {
    PolyFace pf = in.faces[f];
    for (Index& v : pf.nodes) v += static_cast<Index>(base);
    in.faces.push_back(pf);
    in.regions[0].faces.push_back(static_cast<Index>(faces + f));
  }
  PreparationReport rep;
  const PolyhedralModel m = prepare_model(in, &rep);
  EXPECT_EQ(rep.inner_shells_as_cavities, 1u);
  EXPECT_NEAR(m.region_volume(0), 1.0 - 1.0 / 64, 1e-12);
}

TEST(Prepare, RejectsAnOpenRegion) {
  PolyInput in = poly(kCube);
  in.regions[0].faces.pop_back();  // readers reject this too; prepare_model must not rely on it
  const std::string e = error_of([&] { prepare_model(in); });
  EXPECT_NE(e.find("region 1 is not closed"), std::string::npos) << e;
  EXPECT_NE(e.find("node"), std::string::npos) << e;
}

TEST(Prepare, RejectsRegionsClaimingTheSameSide) {
  PolyInput in = poly(kCube);
  in.regions.push_back(in.regions[0]);  // a second region on top of the first
  const std::string e = error_of([&] { prepare_model(in); });
  EXPECT_NE(e.find("inconsistent interface"), std::string::npos) << e;
  EXPECT_NE(e.find("face"), std::string::npos) << e;
}

TEST(Prepare, RejectsAFaceOfThreeRegions) {
  PolyInput in = poly(kCube);
  in.regions.push_back(in.regions[0]);
  in.regions.push_back(in.regions[0]);
  const std::string e = error_of([&] { prepare_model(in); });
  EXPECT_NE(e.find("face 1 belongs to 3 regions"), std::string::npos) << e;
}

TEST(Prepare, RejectsACavityOutsideEveryRegion) {
  PolyInput in = poly(kCube);
  const std::size_t base = in.nodes.size(), faces = in.faces.size();
  for (std::size_t i = 0; i < base; ++i) in.nodes.push_back(in.nodes[i] + Vec3(5, 0, 0));
  PolyRegion cav;
  cav.cavity = true;
  for (std::size_t f = 0; f < faces; ++f) {
    PolyFace pf = in.faces[f];
    for (Index& v : pf.nodes) v += static_cast<Index>(base);
    in.faces.push_back(pf);
    cav.faces.push_back(static_cast<Index>(faces + f));
  }
  in.regions.push_back(cav);
  const std::string e = error_of([&] { prepare_model(in); });
  EXPECT_NE(e.find("cavity region 2 lies inside no region"), std::string::npos) << e;
}

}  // namespace
}  // namespace bisect
