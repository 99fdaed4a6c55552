// The size field: the base where nothing asks for less, the cone of each source with the grading
// as its slope, clamping by the minimum and maximum sizes, and the tree's answers equal to a
// brute-force minimum over every source.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bisect/errors.hpp"
#include "size/size_field.hpp"

namespace bisect::size {
namespace {

TEST(SizeField, BaseConesAndClamps) {
  SizeField h(1.0, 0.5);
  h.add(Vec3(0, 0, 0), 0.1);
  h.add(Vec3(5, 0, 0), 2.0);  // coarser than the base: dropped
  h.finish();
  EXPECT_EQ(h.sources(), 1u);
  EXPECT_NEAR(h.at(Vec3(0, 0, 0)), 0.1, 1e-15);
  EXPECT_NEAR(h.at(Vec3(1, 0, 0)), 0.6, 1e-15);
  EXPECT_NEAR(h.at(Vec3(0, 3, 0)), 1.0, 1e-15);
  EXPECT_NEAR(h.smallest(), 0.1, 1e-15);
  SizeField clamped(1.0, 0.5, 0.2, 0.8);
  clamped.add(Vec3(0, 0, 0), 0.1);
  clamped.finish();
  EXPECT_NEAR(clamped.at(Vec3(0, 0, 0)), 0.2, 1e-15);
  EXPECT_NEAR(clamped.at(Vec3(10, 0, 0)), 0.8, 1e-15);
  EXPECT_THROW(SizeField(1.0, 0.5, 0.9, 0.3), InputError);
  EXPECT_THROW(SizeField(0.0, 0.5), InputError);
  EXPECT_THROW(SizeField(1.0, -1.0), InputError);
}

TEST(SizeField, TreeEqualsBruteForce) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-10, 10), s(0.01, 1.5);
  SizeField h(1.2, 0.3);
  std::vector<std::pair<Vec3, double>> all;
  for (int i = 0; i < 5000; ++i) {
    const Vec3 p(u(rng), u(rng), 0.1 * u(rng));
    const double si = s(rng);
    h.add(p, si);
    all.push_back({p, si});
  }
  h.finish();
  for (int q = 0; q < 300; ++q) {
    const Vec3 x(u(rng), u(rng), u(rng));
    double want = 1.2;
    for (const auto& [p, si] : all) want = std::min(want, si + 0.3 * (x - p).norm());
    EXPECT_NEAR(h.at(x), want, 1e-12);
  }
  // the grading bounds the size's growth between any two points
  for (int q = 0; q < 300; ++q) {
    const Vec3 x(u(rng), u(rng), u(rng)), y = x + Vec3(0.3, -0.2, 0.1);
    EXPECT_LE(std::abs(h.at(x) - h.at(y)), 0.3 * (x - y).norm() + 1e-12);
  }
}

}  // namespace
}  // namespace bisect::size
