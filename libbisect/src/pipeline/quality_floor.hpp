// The count floor for quality's sake (issue 17), polyhedral route: when the mesh made for the
// count R asks (R, or the count the facets or walls held it at) has poor elements and is coarse
// (up to 5,000 tetrahedra), more elements are used, and --stats says so (count_floor and
// count_floor_reason "quality: ...", quality_meshes).
//
// Why a floor and not a local rule: on lug.stl (a 4 x 2 x 0.5 plate whose holes are 64-gons of
// facets 0.1 wide, each its own face) the mean alpha at R = 1,000 was 0.214 and at 3,000 0.239.
// The local rules tried all fell short: the walls' cap (cell_walls.hpp), --grading from the fine
// facets (at most 0.226), the bisector first at nearly flat edges (0.223) and a face-corner limit
// (0.217). The quality over the spacing is not monotonic there (-s 0.45: 0.214; 0.33: 0.213 and a
// smallest dihedral of 8.5 degrees; 0.25: 0.218; 0.2: 0.234; 0.18: 0.245), so no cap by the
// plate's thickness short of a third of it reaches the bar, and such a cap would multiply the
// count of every thick part at coarse R (cantilever.stl: 160 tetrahedra at R = 50, 1,819 at a
// third of its 10 mm). Measuring the mesh and asking for more where it falls
// short costs at most four more meshes of at most 4 times its count, and only at coarse counts.
// The walls' cap alone can leave a coarse mesh poor too: a 4 x 2 x 1 plate with a round end of 32
// facets at R = 300 came out at 811 tetrahedra, mean alpha 0.129 and 4.1 degrees.
//
// The bars are the ones the project holds the generator to: a mean alpha of 0.20, and 0.24 from
// 1,000 tetrahedra on (below that a part has too few elements across it for a mean of 0.24: Gmsh's
// coarsest cantilever has 0.203), and a smallest dihedral angle of 10 degrees. The mean alone
// starts the floor: it grows with the count, while the smallest angle, where it is under 10
// degrees at R, often comes from the input's facets more than from the spacing (part.stl: 4.6, 4.2,
// 4.9, 6.0 and 5.9 degrees at 5,000 to 20,000 tetrahedra), and more elements would not lift it.
// A mesh the floor keeps meets the mean's bar and has a smallest angle of at least 10 degrees,
// or, where the first mesh's was less, at least 0.8 times that: such angles move by a degree from
// one count to the next (part.stl's first mesh at R = 1,000 had 6.6 degrees, and the meshes of
// 6,000 to 16,000 tetrahedra, mean alpha up to 0.25, 5.3 to 5.5).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "bisect/quality.hpp"

namespace bisect::pipeline {

struct QualityBars {
  double dihedral_deg = 10;  // smallest dihedral angle of any tetrahedron
  double alpha_mean = 0.20;  // mean alpha (r_in / R_circ; 1/3 for the regular tetrahedron)
};

// The counts of the mesh made for R (R, or the count the facets or walls held it at) above which
// no floor is sought: the floor is for coarse meshes, and four more meshes of a larger one would
// cost seconds (Angled.stl's facets hold it at 2.5 * 10^4 tetrahedra, 1.3 s a mesh).
inline constexpr std::int64_t kQualityFloorMaxTets = 5000;
// The most tetrahedra the floor may ask, as a multiple of that count.
inline constexpr double kQualityFloorMaxFactor = 4;
// The share of the first mesh's smallest dihedral angle (where under the bar) that a mesh the
// floor keeps must have.
inline constexpr double kFloorDihedralSlack = 0.8;
// The step between the counts tried.
inline constexpr double kQualityFloorStep = 1.5;

// The bars for a mesh of n tetrahedra (the larger of R and the count made for it: a mesh the
// facets hold at 1,200 for R = 300 has the elements for the bar of 1,200).
QualityBars quality_bars(std::int64_t n);

// Whether the mesh at R leaves the floor alone: its mean alpha meets the bar.
bool meets_mean_bar(const QualitySummary& q, const QualityBars& bars);

// Whether the floor keeps a mesh of more elements: it meets the mean's bar, and its smallest
// dihedral angle is at least the bar's, or kFloorDihedralSlack times that of the mesh at R where
// that was under the bar.
bool floor_keeps(const QualitySummary& more, const QualitySummary& at_asked, const QualityBars& bars);

// The counts the floor asks after the count `made` for R, in order: made times 1.5, 2.25, 3.375,
// then 4 (the last clipped to kQualityFloorMaxFactor); none when made is over
// kQualityFloorMaxTets or not positive.
std::vector<std::int64_t> quality_floor_counts(std::int64_t made);

// count_floor_reason for a floor the quality set: what the mesh made for R gave, what the kept
// count gives, e.g. "quality: the mesh for R = 1000 (1195 tetrahedra) had a mean alpha of 0.214
// (bar 0.24) and a smallest dihedral of 12.2 deg; 3263 tetrahedra give 0.243 and 13.1 deg".
std::string quality_floor_reason(std::int64_t asked, const QualitySummary& at_asked, const QualityBars& bars, std::int64_t kept_tets,
                                 const QualitySummary& kept);

}  // namespace bisect::pipeline
