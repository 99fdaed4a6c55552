// Plane bisection of one region (thesis 7.3.1 polyhedral cut face, 7.3.2 polyhedral splitting).
//
// The section of the region by the plane is worked out first without touching the model: where
// the plane crosses faces (chords) and where it runs along edges into the region's interior.
// These pieces, directed so that the section lies on their left seen from the plane's positive
// side, close into loops; counter-clockwise loops are outer boundaries, clockwise ones holes
// (A3). The cut face method keeps only the section polygon that holds the starting edge, the
// splitting method keeps them all. Each check that can reject the plane runs before the model
// changes, so a rejected plane leaves the model as it was.
#pragma once
#include <string>
#include <vector>

#include "bisect/edge_wedges.hpp"
#include "bisect/polyhedral_model.hpp"

namespace bisect {

struct RegionSnapshot;  // section.hpp

struct CutPlane {
  Vec3 n;    // unit normal
  double c;  // n · x = c
};

struct CutOutcome {
  bool ok = false;
  std::string reason;               // why the plane was rejected (a DecomposeStats.rejected key)
  std::vector<Index> regions;       // the regions that now cover the old one (ok only)
  std::size_t cut_faces = 0;        // polygons inserted
};

// Cuts region r. With whole_plane false only the section polygon bounded by edge (ea, eb) is
// inserted (cut face); otherwise every section polygon is (splitting).
// `snap`: the region's snapshot, when the caller keeps one (see build_section).
CutOutcome cut_region(PolyhedralModel& m, Index r, const CutPlane& plane, Index ea, Index eb, bool whole_plane,
                      const DecomposeOptions& opt, const RegionSnapshot* snap = nullptr);

}  // namespace bisect
