// A compound of solids that share no face (parts that touch or lie apart, as assemblies exported
// to one file are): each group of solids is meshed on its own, the count shared by volume, the
// tetrahedra tagged with FreeCAD's solid numbers, and no node shared between bodies.
#include <gtest/gtest.h>

#include <BOPAlgo_Builder.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <gp_Ax2.hxx>

#include <cmath>
#include <set>
#include <vector>

#include "bisect/generate.hpp"
#include "bisect/occ.hpp"
#include "bisect/validate.hpp"
#include "occ_checks.hpp"
#include "occ_shapes.hpp"

namespace bisect {
namespace {

TEST(BrepCompound, SeparateBodiesAreMeshedEachOnItsOwn) {
  // through a BREP string, as FreeCAD hands a shape over (shape.exportBrepToString()); the shape
  // as built in memory fills the cylinder differently (its parameters differ in the last digits,
  // see occ_checks.hpp; FreeCAD never passes one)
  const BrepInput in = test::input_through_string(test::make_touching_compound(), "touching compound");
  ASSERT_EQ(in.solids.size(), 3u);
  const double want_volume[3] = {8, 1.28 * M_PI, 1};
  for (int s = 0; s < 3; ++s) EXPECT_NEAR(in.solids[s].volume, want_volume[s], 1e-6 * want_volume[s]);
  for (int order : {1, 2}) {
    GenerateOptions opt;
    opt.sizing.elements = 6000;
    opt.order = order;
    std::vector<double> fractions;
    opt.progress = [&](double x) {
      fractions.push_back(x);
      return true;
    };
    GenerateStats st;
    const TetMesh m = generate_brep_mesh(in, opt, &st);
    EXPECT_TRUE(validate(m).empty()) << "order " << order;
    EXPECT_NEAR(static_cast<double>(m.num_tets()), 6000, 1200) << "order " << order;
    EXPECT_EQ(st.tets, static_cast<std::int64_t>(m.num_tets()));
    EXPECT_EQ(st.regions, 3);
    // each body's volume is its solid's (the cylinder within its chords' error)
    double volume[3] = {0, 0, 0};
    std::vector<int> body(m.nodes.size(), -1);
    bool shared = false;
    for (std::size_t t = 0; t < m.num_tets(); ++t) {
      ASSERT_GE(m.region[t], 0);
      ASSERT_LT(m.region[t], 3);
      volume[m.region[t]] += test::corner_volume(m, t);
      for (int k = 0; k < m.nodes_per_tet(); ++k) {
        int& b = body[m.tet_node(t, k)];
        if (b >= 0 && b != m.region[t]) shared = true;
        b = m.region[t];
      }
    }
    EXPECT_FALSE(shared) << "a node belongs to two bodies";
    for (int s = 0; s < 3; ++s) EXPECT_NEAR(volume[s], want_volume[s], 0.02 * want_volume[s]) << "Solid" << s + 1;
    // the boundary triangles carry the B-rep faces of all three bodies (6 + 3 + 6 faces)
    std::set<Index> faces(m.tri_tag.begin(), m.tri_tag.end());
    EXPECT_EQ(faces.size(), in.faces.size());
    // progress runs from the first body to the last without going back, and ends at 1
    ASSERT_FALSE(fractions.empty());
    for (std::size_t i = 1; i < fractions.size(); ++i) EXPECT_GE(fractions[i], fractions[i - 1] - 1e-12);
    EXPECT_NEAR(fractions.back(), 1.0, 1e-9);
  }
}

}  // namespace
}  // namespace bisect

namespace bisect {
namespace {

TEST(BrepCompound, CylinderThroughABoxAsFragmentsMeshesConformingly) {
  // FreeCAD's BooleanFragments of a 10 mm box and a cylinder (r 3) through it: four solids, the
  // middle piece filling the box's hole, the end pieces on its discs. The middle piece's point
  // lies in the box's outer shell, so the box was taken to hold it as a sub-domain and to lie
  // beyond its discs too: "inconsistent interface", at every proxy.
  BOPAlgo_Builder fuse;
  fuse.AddArgument(BRepPrimAPI_MakeBox(10, 10, 10).Shape());
  fuse.AddArgument(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(5, 5, -5), gp_Dir(0, 0, 1)), 3, 20).Shape());
  fuse.Perform();
  ASSERT_FALSE(fuse.HasErrors());
  const BrepInput in = test::input_through_string(fuse.Shape(), "fragments");
  ASSERT_EQ(in.solids.size(), 4u);
  GenerateOptions opt;
  opt.sizing.elements = 6000;
  const TetMesh m = generate_brep_mesh(in, opt);
  EXPECT_TRUE(validate(m).empty());
  std::vector<double> volume(4, 0);
  std::vector<std::set<int>> regions_at(m.nodes.size());
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    volume[m.region[t]] += test::corner_volume(m, t);
    for (int k = 0; k < 4; ++k) regions_at[m.tet_node(t, k)].insert(m.region[t]);
  }
  // within the chords' loss: 12 elements per turn on a cylinder keep 95.5% of its section
  for (int s = 0; s < 4; ++s) EXPECT_NEAR(volume[s], in.solids[s].volume, 0.045 * in.solids[s].volume) << "Solid" << s + 1;
  // one conforming mesh: the interfaces' nodes belong to the solids on both sides
  int shared = 0;
  for (const std::set<int>& r : regions_at) shared += r.size() > 1;
  EXPECT_GT(shared, 100);
}

}  // namespace
}  // namespace bisect
