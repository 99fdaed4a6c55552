// The B-rep route's last check before a mesh is handed over (pipeline/brep_order2.hpp): a
// tetrahedron inside out or flat to round-off is a MeshingError naming the file, the solid and the
// place, never a mesh (corpus/Cone_1.brep's first proxy once left one of 1e-13 degrees at its
// apex; its first proxy now fails earlier, so this holds the check on its own); so is a face that
// three tetrahedra share.
#include <gtest/gtest.h>

#include <string>

#include "bisect/errors.hpp"
#include "pipeline/brep_order2.hpp"

namespace bisect::pipeline {
namespace {

TetMesh one_tet(const Vec3& d) {
  TetMesh m;
  m.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), d};
  const Index v[4] = {0, 1, 2, 3};
  m.add_tet(v, 0);
  return m;
}

std::string refusal(const TetMesh& m) {
  BrepInput in;
  in.source = "part.brep";
  try {
    refuse_degenerate_tets(in, m);
  } catch (const MeshingError& e) {
    return e.what();
  }
  return "";
}

TEST(DegenerateTets, AGoodTetrahedronPasses) { EXPECT_EQ(refusal(one_tet(Vec3(0.2, 0.2, 1))), ""); }

TEST(DegenerateTets, AThinButSolvableOnePasses) {
  // a 0.1 degree sliver's six volumes are about 1e-3 of its longest edge cubed: a solver copes
  EXPECT_EQ(refusal(one_tet(Vec3(0.3, 0.3, 1e-3))), "");
}

TEST(DegenerateTets, OneFlatToRoundOffIsRefusedNamingThePlace) {
  const std::string why = refusal(one_tet(Vec3(0.3, 0.3, 1e-13)));
  EXPECT_NE(why.find("part.brep: Solid1: the tetrahedron at ("), std::string::npos) << why;
  EXPECT_NE(why.find("is flat to round-off"), std::string::npos) << why;
}

TEST(DegenerateTets, OneInsideOutIsRefusedNamingThePlace) {
  const std::string why = refusal(one_tet(Vec3(0.2, 0.2, -1)));
  EXPECT_NE(why.find("part.brep: Solid1: a tetrahedron at ("), std::string::npos) << why;
  EXPECT_NE(why.find("came out inside out"), std::string::npos) << why;
}

TEST(DegenerateTets, AFaceOfThreeTetrahedraIsRefusedNamingThePlace) {
  // three tetrahedra on the triangle (0,0,0) (1,0,0) (0,1,0): one below it, two above (they
  // overlap), each positively oriented; the two above alone, or one above and one below, pass
  TetMesh m;
  m.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.2, 0.2, -1), Vec3(0.2, 0.2, 1), Vec3(0.3, 0.3, 2)};
  const Index below[4] = {0, 2, 1, 3}, above[4] = {0, 1, 2, 4}, over[4] = {0, 1, 2, 5};
  m.add_tet(below, 0);
  m.add_tet(above, 0);
  EXPECT_EQ(refusal(m), "");
  m.add_tet(over, 0);
  const std::string why = refusal(m);
  EXPECT_NE(why.find("part.brep: Solid1: the face at (0.3333, 0.3333, 0)"), std::string::npos) << why;
  EXPECT_NE(why.find("is shared by three tetrahedra or more"), std::string::npos) << why;
}

}  // namespace
}  // namespace bisect::pipeline
