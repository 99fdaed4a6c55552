// Checks every decomposition test applies to the library's own result: each cell closed and
// convex, cut faces shared by exactly two cells, input faces by one, volumes adding up. (The
// independent checker of tests/support checks the written cells from the outside as well.)
#pragma once
#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "bisect/polyhedral_model.hpp"

namespace bisect::test {

inline void expect_valid_cells(const Decomposition& d, double input_volume, double convex_tol = 1e-9) {
  const PolyhedralModel& m = d.model;
  double total = 0;
  std::map<Index, int> users;
  for (std::size_t c = 0; c < d.cells.size(); ++c) {
    const ConvexCell& cell = d.cells[c];
    std::map<std::pair<Index, Index>, int> directed;  // outward-oriented loop edges
    std::vector<Index> nodes;
    for (std::size_t k = 0; k < cell.faces.size(); ++k) {
      const ModelFace& f = m.faces[cell.faces[k]];
      ASSERT_TRUE(f.alive);
      ++users[cell.faces[k]];
      for (const auto& loop : f.loops)
        for (std::size_t i = 0; i < loop.size(); ++i) {
          Index a = loop[i], b = loop[(i + 1) % loop.size()];
          if (!cell.outward[k]) std::swap(a, b);
          ++directed[{a, b}];
          nodes.push_back(a);
        }
    }
    for (const auto& [e, n] : directed) {
      const auto back = directed.find({e.second, e.first});
      EXPECT_TRUE(n == 1 && back != directed.end() && back->second == 1)
          << "cell " << c << " is not closed at edge " << e.first << "-" << e.second;
    }
    for (std::size_t k = 0; k < cell.faces.size(); ++k) {
      const ModelFace& f = m.faces[cell.faces[k]];
      const double s = cell.outward[k] ? 1 : -1;
      for (Index v : nodes)
        EXPECT_LE(s * (f.normal.dot(m.nodes[v]) - f.offset), convex_tol * m.size)
            << "cell " << c << " is not convex: node " << v << " outside face " << cell.faces[k];
    }
    // volume by the divergence theorem over the outward faces
    double vol = 0;
    for (std::size_t k = 0; k < cell.faces.size(); ++k) {
      const ModelFace& f = m.faces[cell.faces[k]];
      vol += (cell.outward[k] ? 1 : -1) * f.offset * m.face_area(cell.faces[k]) / 3;
    }
    EXPECT_GT(vol, 0) << "cell " << c;
    total += vol;
  }
  for (const auto& [f, n] : users) {
    const ModelFace& face = m.faces[f];
    const int expected = (face.front >= 0) + (face.back >= 0);
    EXPECT_EQ(n, expected) << "face " << f << (face.source == kCutFace ? " (cut)" : "");
  }
  EXPECT_NEAR(total, input_volume, 1e-9 * std::abs(input_volume));
}

}  // namespace bisect::test
