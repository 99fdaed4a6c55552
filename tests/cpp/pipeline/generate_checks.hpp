// What every generated mesh must be, shared by the generator's tests: valid (the validator),
// of the input's volume, and every boundary triangle a face of a tetrahedron.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <string>

#include "bisect/polyhedral_model.hpp"
#include "bisect/tet_mesh.hpp"
#include "bisect/validate.hpp"

namespace bisect {

inline double mesh_volume(const TetMesh& m) {
  double v = 0;
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    const Vec3 &a = m.nodes[m.tet_node(t, 0)], &b = m.nodes[m.tet_node(t, 1)], &c = m.nodes[m.tet_node(t, 2)], &d = m.nodes[m.tet_node(t, 3)];
    v += (b - a).dot((c - a).cross(d - a)) / 6;
  }
  return v;
}

inline std::string violations(const TetMesh& m) {
  std::string s;
  for (const Violation& v : validate(m)) s += v.message + "\n";
  return s;
}

// Valid, the input's volume, every boundary triangle a face of a tetrahedron.
inline void expect_sound(const TetMesh& m, const PolyInput& in, const std::string& what) {
  EXPECT_TRUE(validate(m).empty()) << what << "\n" << violations(m);
  EXPECT_NEAR(mesh_volume(m), summarize(in).volume, 1e-9 * summarize(in).volume) << what;
  std::set<std::array<Index, 3>> faces;
  for (std::size_t t = 0; t < m.num_tets(); ++t)
    for (const auto& f : kTetFace) {
      std::array<Index, 3> k{m.tet_node(t, f[0]), m.tet_node(t, f[1]), m.tet_node(t, f[2])};
      std::sort(k.begin(), k.end());
      faces.insert(k);
    }
  std::size_t missing = 0;
  for (std::size_t b = 0; b < m.num_tris(); ++b) {
    const std::size_t at = b * static_cast<std::size_t>(m.nodes_per_tri());  // corners first
    std::array<Index, 3> k{m.tris[at], m.tris[at + 1], m.tris[at + 2]};
    std::sort(k.begin(), k.end());
    missing += faces.count(k) == 0;
  }
  EXPECT_EQ(missing, 0u) << what << ": boundary triangles that no tetrahedron has";
}

}  // namespace bisect
