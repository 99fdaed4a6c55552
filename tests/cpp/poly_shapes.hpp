// Small polyhedral inputs that many tests use, as .poly text, and the helpers that read them.
#pragma once
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "bisect/io.hpp"
#include "bisect/poly_input.hpp"

namespace bisect::test {

inline PolyInput poly(const std::string& text) {
  std::istringstream in(text);
  return read_poly(in, "test.poly");
}

// An extruded outline (counter-clockwise, z from 0 to 1) as .poly text: the bottom face, the top
// face, then one side face per outline edge; nodes bottom ring first.
inline std::string prism(const std::vector<Vec2>& outline) {
  const std::size_t n = outline.size();
  std::ostringstream s;
  s << n + 2 << ' ' << 2 * n << " 1 0\n";
  for (int z = 0; z < 2; ++z)
    for (const Vec2& p : outline) s << p.x() << ' ' << p.y() << ' ' << z << '\n';
  for (int z = 0; z < 2; ++z) {
    s << n;
    for (std::size_t i = 0; i < n; ++i) s << ' ' << z * n + i + 1;
    s << '\n';
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    s << "4 " << i + 1 << ' ' << j + 1 << ' ' << n + j + 1 << ' ' << n + i + 1 << '\n';
  }
  s << n + 2;
  for (std::size_t f = 1; f <= n + 2; ++f) s << ' ' << f;
  s << '\n';
  return s.str();
}

// The unit cube and the L-shaped prism (one reflex edge, from node 4 (1,1,0) to node 10 (1,1,1)).
inline std::string unit_cube() { return prism({{0, 0}, {1, 0}, {1, 1}, {0, 1}}); }
inline const std::vector<Vec2> kLOutline = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
inline std::string l_prism() { return prism(kLOutline); }

// A 4 x 2 x 1 plate: the rectangle 0..3 x 0..2 and a half disc of radius 1 round (3, 1) at its
// end, in 32 facets 0.1 wide (lug.stl's rounded end at twice its thickness). Its mesh for R = 300
// is poor where the walls' cap holds the count (the quality floor's case, test_quality_floor.cpp).
inline std::string round_ended_plate() {
  std::vector<Vec2> outline{{0, 0}, {3, 0}};
  constexpr int kSegments = 32;
  const double pi = std::acos(-1.0);
  for (int k = 1; k < kSegments; ++k) {
    const double a = -pi / 2 + pi * k / kSegments;
    outline.emplace_back(3 + std::cos(a), 1 + std::sin(a));
  }
  outline.emplace_back(3, 2);
  outline.emplace_back(0, 2);
  return prism(outline);
}

}  // namespace bisect::test
