// Tetrahedral quality measures (ARCHITECTURE.md §3), defined once and used by the tests, the
// CLI, the Python module and the workbench.
//
// Units: dihedral angles in degrees, solid angles in steradians. For the regular tetrahedron:
// dihedral angles arccos(1/3) = 70.5288°, solid angles arccos(23/27) = 0.5513 sr, gamma 1,
// alpha 1/3. All measures are invariant under reflection (an inverted tetrahedron grades as its
// mirror image; validity is the validator's job) and are 0 for a degenerate tetrahedron.
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "bisect/tet_mesh.hpp"

namespace bisect {

struct TetQuality {
  double volume = 0;           // signed: positive for the orientation of tet_mesh.hpp
  double dihedral_min = 0;     // degrees
  double dihedral_max = 0;     // degrees
  double solid_angle_min = 0;  // steradians, Van Oosterom–Strackee (thesis 2.4.1)
  double gamma = 0;            // 374.123 V^2 / S^3 (thesis 2.4.2), 1 when regular
  double alpha = 0;            // inradius / circumradius (thesis 8.3.1), 1/3 when regular
};

TetQuality tet_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// α̂ = r / R of the tetrahedron whose edges from one corner are u, v, w and whose surface area is
// `area`: with 6V = u·(v×w), r = 3V / S and R = |N| / (2·6V), N = |u|²(v×w) + |v|²(w×u) +
// |w|²(u×v) the circumcentre's numerator, α̂ = (6V)² / (S |N|), no division by a small volume.
// 0 for a degenerate one. tet_quality's α̂, and the measure of the optimiser's mean-shape passes.
double alpha_from_edges(const Vec3& u, const Vec3& v, const Vec3& w, double area);

// The smallest corner solid angle alone (steradians, the same formula as tet_quality's), for the
// min-max criterion of the local transformations (thesis 7.5), which evaluates it millions of
// times. Orientation is not judged: the callers check it exactly with orient3d.
double min_solid_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
// tan(Ω/2) of that smallest angle: increases with it, so comparisons may use it and skip the
// arctangent (min_solid_angle = 2 atan of it).
double min_solid_angle_tan_half(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
// The same with the sign of the tetrahedron's volume (in floating point): negative for one that
// is inside out, so that a key below every valid tetrahedron's marks it as the worst.
double signed_min_solid_angle_tan_half(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// The smallest corner angle of the triangle a, b, c in 3D (radians): the surface grids' measure.
double triangle_min_angle(const Vec3& a, const Vec3& b, const Vec3& c);
// The same in degrees (the unit of the statistics and the reports).
double triangle_min_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c);
// The smallest of those over the mesh's boundary and interface triangles, at their corner nodes
// (degrees; 180 for a mesh without triangles).
double surface_min_angle_deg(const TetMesh& mesh);

// Per tetrahedron of the mesh (corner nodes only; mid-edge nodes do not enter the measures).
// cancelled (optional) is asked every 4096 tetrahedra, on the calling thread; true stops with
// Cancelled. threads: as GenerateOptions::threads (0: one per core); the result is the same.
std::vector<TetQuality> element_quality(const TetMesh& mesh, const std::function<bool()>& cancelled = {}, int threads = 1);

struct MeasureStats {
  double min = 0, mean = 0, max = 0;
  double lo = 0, hi = 0;                // histogram range; bins are equal slices of [lo, hi]
  std::vector<std::size_t> histogram;   // values outside [lo, hi] are clamped into the end bins
};

struct QualitySummary {
  std::size_t tets = 0;
  MeasureStats dihedral_min;     // histogram over [0, 90] degrees, 18 bins of 5 degrees
  MeasureStats dihedral_max;     // over [0, 180], 18 bins of 10 degrees
  MeasureStats solid_angle_min;  // over [0, 0.6] sr, 12 bins
  MeasureStats gamma;            // over [0, 1], 10 bins
  MeasureStats alpha;            // over [0, 1/3], 10 bins
  double pct_dihedral_below_10 = 0;  // percentage of tetrahedra whose minimum dihedral < 10°
};

QualitySummary summarize_quality(const std::vector<TetQuality>& q);

// The summary as the JSON object of the --stats "quality" contract (ARCHITECTURE.md §3) plus the
// per-measure statistics and histograms: {"tets":..,"dihedral_min":..,"dihedral_max":..,
// "solid_angle_min":..,"solid_angle_mean":..,"gamma_mean":..,"gamma_min":..,"alpha_mean":..,
// "pct_dihedral_below_10":.., "measures": {"dihedral_min": {"min","mean","max","lo","hi",
// "histogram"}, ...}}
std::string quality_json(const QualitySummary& s);

}  // namespace bisect
