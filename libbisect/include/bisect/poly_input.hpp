// Polyhedral and polygonal inputs as read from files, checked but not yet prepared: the readers
// (io.hpp) fill these; the domain stage (PolyhedralModel, thesis 6.12 and 7.2) starts from them.
// Indices are 0-based here; messages name nodes, faces and regions by the file's 1-based numbers.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bisect/types.hpp"

namespace bisect {

struct PolyFace {
  std::vector<Index> nodes;  // a planar polygon, in the file's direction (either way round)
  Index hole_of = -1;        // the face this face is a hole of (it lies inside it, coplanar, in
                             // the same region: thesis 6.13), or -1
};

struct PolyRegion {
  std::vector<Index> faces;
  bool cavity = false;  // a negative face count in .poly (thesis 6.13)
};

struct PolyInput {
  std::vector<Vec3> nodes;
  std::vector<PolyFace> faces;
  std::vector<PolyRegion> regions;
  std::int64_t required_elements = 0;  // R of the .poly header; 0 when the format has none
  std::string source;                  // file name, for messages
  // Optional, one per node: the element size the node asks for (a density hint, e.g. from a CAD
  // tessellation's resolution); the face grids space their nodes no wider near it. Empty or 0:
  // no hint.
  std::vector<double> node_spacing;
  // Optional, one per face: the name messages give it. A B-rep proxy's polygons and facets are
  // named by their B-rep face ("Face12", as FreeCAD numbers it): a user cannot find the proxy's
  // own numbers. Empty: "face N", the file's numbering.
  std::vector<std::string> face_label;
};

// The name of input face f in messages: its label, else "face N" (1-based).
inline std::string input_face_name(const PolyInput& in, Index f) {
  if (f >= 0 && static_cast<std::size_t>(f) < in.face_label.size() && !in.face_label[f].empty()) return in.face_label[f];
  return "face " + std::to_string(f + 1);
}

// Thesis 4.6.1: outer polygons, holes (negative node count) and sub-domains.
struct Poly2Input {
  struct Polygon {
    std::vector<Index> nodes;
    bool hole = false;
  };
  std::vector<Vec2> nodes;
  std::vector<Polygon> polygons;
  std::int64_t required_elements = 0;
  std::string source;
};

// What `bisect-mesh info` prints. Volumes come from the divergence theorem over each region's
// faces, each closed shell oriented outward; a shell inside another shell of the same region
// (an inner boundary) and the cavities inside a region are subtracted.
struct RegionSummary {
  std::size_t faces = 0;
  std::size_t nodes = 0;    // distinct nodes used by the region's faces
  std::size_t shells = 0;   // connected closed surfaces
  std::size_t holes = 0;    // faces that are holes of another face
  bool cavity = false;
  Index inside = -1;        // the region this region lies inside (cavities, sub-domains), or -1
  double volume = 0;        // net volume: enclosed minus inner shells and contained cavities
};

struct PolySummary {
  std::vector<RegionSummary> regions;
  std::size_t faces = 0, nodes = 0;
  Vec3 bbox_min = Vec3::Zero(), bbox_max = Vec3::Zero();
  double volume = 0;  // total net volume of the non-cavity regions
};

PolySummary summarize(const PolyInput& in);

// The same for a 2D input: per polygon its area, the polygon it lies directly inside, and the net
// area of each region (a non-hole polygon minus the holes and sub-domains directly inside it).
struct Poly2Summary {
  struct PolygonSummary {
    std::size_t nodes = 0;
    bool hole = false;
    Index inside = -1;  // the smallest polygon containing this one, or -1
    double area = 0;    // enclosed area, positive whatever the polygon's direction
    double net_area = 0;  // regions: area minus what lies directly inside; holes: 0
  };
  std::vector<PolygonSummary> polygons;
  std::size_t nodes = 0;
  Vec2 bbox_min = Vec2::Zero(), bbox_max = Vec2::Zero();
  double area = 0;  // total net area of the regions
};

Poly2Summary summarize(const Poly2Input& in);

}  // namespace bisect
