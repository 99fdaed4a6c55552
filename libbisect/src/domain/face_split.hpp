// Thesis 7.2 operation (2), the geometric part: a planar polygon with holes split along chords
// (segments between its vertices that run through its interior).
#pragma once
#include <array>
#include <functional>
#include <vector>

#include "bisect/types.hpp"

namespace bisect {

// loops: loop 0 counter-clockwise in the 2D frame `pos` gives, holes clockwise. Returns the
// pieces, each as loops in the same convention (outer first). Holes that no chord touches go to
// the piece that contains them.
std::vector<std::vector<std::vector<Index>>> split_polygon_by_chords(
    const std::vector<std::vector<Index>>& loops, const std::vector<std::array<Index, 2>>& chords,
    const std::function<Vec2(Index)>& pos);

// Twice the signed area of a loop in 2D (positive counter-clockwise).
double loop_area2(const std::vector<Index>& loop, const std::function<Vec2(Index)>& pos);

// Thesis A3: the sum of the turning angles along a closed loop, +2 pi counter-clockwise and
// -2 pi clockwise; tells an outer boundary from an inner one whatever the loop's shape.
double turning_angle_sum(const std::vector<Vec2>& loop);

// Even-odd point-in-loops test (strict inside; points on an edge give either answer).
bool point_in_loops(const Vec2& p, const std::vector<std::vector<Vec2>>& loops);

}  // namespace bisect
