// The names messages give for places a user can find in FreeCAD (bisect/brep_input.hpp).
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "bisect/brep_input.hpp"

namespace bisect {
namespace {

TEST(PlaceNames, FacesBesideAreNumberedAsFreeCADNumbersThem) {
  EXPECT_EQ(beside_faces(std::set<Index>{}), "");
  EXPECT_EQ(beside_faces(std::set<Index>{4}), " beside Face5");
  EXPECT_EQ(beside_faces(std::set<Index>{0, 2, 11}), " beside Face1, Face3, Face12");
  EXPECT_EQ(beside_faces(std::vector<Index>{0, 1, 2, 3, 4, 5}), " beside Face1, Face2, Face3 and 3 more");
  EXPECT_EQ(beside_faces(std::vector<Index>{6, 7}, 1), " beside Face7 and 1 more");
}

TEST(PlaceNames, APointToFourDigits) { EXPECT_EQ(point_name(Vec3(11.273577, -6.022037, 8.466319)), "(11.27, -6.022, 8.466)"); }

}  // namespace
}  // namespace bisect
