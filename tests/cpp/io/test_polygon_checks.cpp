// The .poly2 reader refuses polygons that are not simple (issue 20: a self-crossing polygon made
// the planar mesher fail deep inside with "a flat triangle"): crossing and touching edges and an
// edge turning back are named by their nodes and a point; simple polygons, however many nodes,
// pass quickly.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

#include "bisect/errors.hpp"
#include "bisect/io.hpp"
#include "io/polygon_checks.hpp"

namespace bisect::io {
namespace {

std::string refusal(const std::vector<Vec2>& X, const std::vector<Index>& poly) {
  try {
    check_simple_polygon(X, poly, 2, "f.poly2:9");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PolygonChecks, CrossingTouchingAndTurningBackAreNamed) {
  // a square whose last two nodes are swapped: edges 2-3 and 4-1 cross
  EXPECT_EQ(refusal({{0, 0}, {2, 0}, {0, 2}, {2, 2}}, {0, 1, 2, 3}),
            "f.poly2:9: polygon 3 crosses itself (its edges from node 2 to 3 and from node 4 to 1), at (1, 1); a polygon must be simple");
  // a node of the polygon on one of its own edges (a pinch)
  EXPECT_EQ(refusal({{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}, {0, 1, 2, 3, 4}),
            "f.poly2:9: polygon 3 touches itself (its edges from node 1 to 2 and from node 3 to 4), at (2, 0); a polygon must be "
            "simple");
  // a spike: the edge after node 2 runs back along the one before it
  EXPECT_EQ(refusal({{0, 0}, {4, 0}, {2, 0}, {2, 3}}, {0, 1, 2, 3}),
            "f.poly2:9: polygon 3 turns back on itself (its edges from node 1 to 2 and from node 2 to 3), at (4, 0); a polygon must be "
            "simple");
  // simple ones pass, collinear neighbours included
  EXPECT_EQ(refusal({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}, {0, 1, 2, 3, 4}), "");
  EXPECT_EQ(refusal({{0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}}, {0, 1, 2, 3, 4}), "");
}

TEST(PolygonChecks, ACoastlineOfManyNodesIsReadQuickly) {
  const int n = 100000;
  std::ostringstream s;
  s << "1000\n" << n << " 1\n" << n << "\n";
  s.precision(17);
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n, r = 10 + 0.1 * std::sin(97.0 * a);
    s << r * std::cos(a) << ' ' << r * std::sin(a) << '\n';
  }
  for (int i = 1; i <= n; ++i) s << i << (i == n ? '\n' : ' ');
  std::istringstream in(s.str());
  const auto t0 = std::chrono::steady_clock::now();
  const Poly2Input p = read_poly2(in, "coast.poly2");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(p.polygons.size(), 1u);
  EXPECT_LT(seconds, 5.0);
}

}  // namespace
}  // namespace bisect::io
