// PolyhedralModel (thesis 7.2): polyhedral regions bounded by planar polygon faces with holes,
// shared between regions at interfaces, and the convex decomposition built on it (6.5, 6.7, 7.3).
//
// A face is stored once, with the normal it was born with (9.1.1: split faces inherit it) and the
// region on each side: `front` lies on the side the normal points to, `back` on the other (-1: no
// region, outside or a cavity). A face with front == back is a double-occurring face (6.7): an
// internal cut that does not yet separate its region. Loops run counter-clockwise around the
// normal for the outer boundary and clockwise for holes, so the face lies left of every loop edge.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "bisect/poly_input.hpp"
#include "bisect/types.hpp"

namespace bisect {

struct ModelFace {
  std::vector<std::vector<Index>> loops;  // loops[0] outer (CCW around normal), then holes (CW)
  Vec3 normal = Vec3::UnitZ();            // unit
  double offset = 0;                      // plane: normal · x = offset
  Index front = -1, back = -1;            // regions on the +normal and -normal sides
  Index source = -1;                      // input face it lies on; kCutFace for cut faces
  bool alive = true;
};

struct ModelRegion {
  std::vector<Index> faces;  // its faces (dead ones are skipped); sides come from front/back
  Index source = -1;         // the input region it was cut from
  bool alive = true;
};

inline constexpr Index kCutFace = -1;

class PolyhedralModel {
 public:
  std::vector<Vec3> nodes;
  std::vector<ModelFace> faces;
  std::vector<ModelRegion> regions;  // meshable regions only: cavities are the -1 side of faces
  std::string source;                // input name, for messages
  double size = 1;                   // bounding-box diagonal: the scale of absolute tolerances
  std::vector<double> node_spacing;  // PolyInput::node_spacing of the input nodes (the first ids)

  Index add_node(const Vec3& p);
  Index add_face(ModelFace f);  // registers the face's nodes; returns its id
  // Thesis 7.2 operation (1): a vertex in the interior of edge (a, b), inserted into every live
  // face that uses the edge, so faces on both sides and in other regions stay conforming.
  Index insert_vertex_in_edge(Index a, Index b, const Vec3& p);
  // Operation (2): split face f along chords joining pairs of its vertices (after the vertices
  // are inserted). The pieces inherit normal, sides and source; f dies. Returns the pieces.
  std::vector<Index> split_face(Index f, const std::vector<std::array<Index, 2>>& chords);
  // Live faces that use node v.
  std::vector<Index> faces_of_node(Index v) const;
  // Whether region r holds face f on its +normal side (0), -normal side (1), both (2), or not (-1).
  int side_of(Index f, Index r) const;
  // The face's outward normal seen from region r (faces of r with one side in r).
  Vec3 outward(Index f, Index r) const { return faces[f].back == r ? faces[f].normal : Vec3(-faces[f].normal); }
  double face_area(Index f) const;  // net area (outer minus holes)
  double region_volume(Index r) const;
  std::vector<Index> live_faces(Index r) const;
  void drop_dead_faces(Index r);

 private:
  std::vector<std::vector<Index>> node_faces_;  // may hold dead faces; filtered on read
};

// Plane frame helpers shared by the cut code: a right-handed (e1, e2, n) frame.
struct PlaneFrame {
  Vec3 origin, e1, e2, n;
  explicit PlaneFrame(const Vec3& normal, const Vec3& origin = Vec3::Zero());
  Vec2 to2d(const Vec3& p) const { const Vec3 q = p - origin; return {q.dot(e1), q.dot(e2)}; }
};

// What preparation (6.12) found, for `info`-like reporting and the stats.
struct PreparationReport {
  std::size_t faces = 0, interfaces = 0, cavities = 0, sub_domains = 0, face_holes = 0;
  std::size_t inner_shells_as_cavities = 0;  // inner shells of one region (STL/OFF): cavities
  std::size_t separate_bodies = 0;  // model regions added because a region's boundary bounds
                                    // several bodies (disjoint parts of one STL/OFF): each its own
  std::vector<Index> region_of_input;        // model region per input region (-1: cavity)
};

// Builds the model from a read input: orients every face by a ray test per shell, finds
// interfaces, puts cavities and sub-domains into the region that contains them, makes each
// separate body of a region its own model region (with the same source), and rejects inputs that
// are not closed, self-intersect or have inconsistent interfaces (InputError naming faces and
// nodes by the file's 1-based numbers).
PolyhedralModel prepare_model(const PolyInput& in, PreparationReport* report = nullptr);

// ---- convex decomposition (6.4-6.7, 7.3) ----

struct DecomposeOptions {
  double min_angle_deg = 5;      // reject cuts meeting a face, or making a corner, under this
  double near_vertex_rel = 0.1;  // reject planes passing nearer to a vertex than this times the
                                 // shortest edge at that vertex (unless the vertex is on it)
  double preferred_near_vertex_rel = 0.3;  // the wider margin the planar cuts of a region's first
                                           // edges try before near_vertex_rel: a plane that only
                                           // just misses a vertex leaves an edge much shorter than
                                           // the input's, and the face grids grade from that edge;
                                           // no larger than near_vertex_rel: not used
  double short_edge_rel = 0.05;  // reject chords shorter than this times the shortest edge of
                                 // the face they cross
  // Reject a chord that meets the edges of the face it crosses (at its ends) under this angle,
  // on cut faces and on faces that are no facet of a curved surface (curved_faces); 0: off, as
  // in the thesis. A piece of face between the chord and that edge has a corner of that angle,
  // and no grid of it can have larger angles: the B-rep route asks for 20 degrees on its surface.
  double min_face_corner_deg = 0;
  double reflex_tol_deg = 1e-3;  // an edge is reflex when its angle exceeds 180 + this
  int max_candidates = 7;        // planes per edge (6.4.1), at least 10 degrees apart (besides the
                                 // planes through a vertex at a nearly flat edge, plane_selection.hpp)
  double band_rel = 0.4;         // edge following: relative distance of the bandwidth test (7.3.3)
  // Per input face: 1 when it is a facet of a curved surface. The B-rep route sets it from its
  // proxy (the polyhedral route clears it: a polyhedral input's facets are its surface). A nearly
  // flat reflex edge beside such a facet is cut by its bisector first (plane_selection.hpp);
  // empty: the thesis's order everywhere.
  std::vector<char> curved_faces;
  // The mesh to be made: split_size, its spacing s (> 0), else split_elements, its count R. The
  // convex cells that are long and thin and hold many of its elements (R V_cell / V, or
  // 8 V_cell / s^3) are cut again across their length (bisect/slender_split.hpp), and so are the
  // cells that hold more than a sixth of them (bisect/balance_split.hpp, unless balance_cells
  // is false: the threads' share of the filling); both 0: never.
  double split_size = 0;
  double split_elements = 0;
  bool balance_cells = true;
  std::function<bool(double)> progress;  // fraction done; return false to cancel

  // Whether the wider margin is tried at all, and these options with it off (the thesis's margin
  // alone, as the retry after a failed decomposition uses).
  bool widens_margin() const { return preferred_near_vertex_rel > near_vertex_rel; }
  DecomposeOptions thesis_margin_only() const {
    DecomposeOptions o = *this;
    o.preferred_near_vertex_rel = near_vertex_rel;
    return o;
  }
};

struct DecomposeStats {
  std::size_t convex_cells = 0;
  std::map<std::string, std::size_t> bisections;  // by method: cut_face, splitting, ...
  std::map<std::string, std::size_t> rejected;    // candidate planes by reason
  std::size_t deferred = 0;                       // reflex edges put back on the list (6.7 (3)-(4))
  bool narrow_margin_retry = false;  // decomposed again with near_vertex_rel only, after the
                                     // wider margin's cuts led to a region no plane resolved
  bool face_corner_retry = false;    // decomposed again without min_face_corner_deg, after its
                                     // cuts led to a region no plane resolved
  double prepare_seconds = 0, bisect_seconds = 0;
};

struct ConvexCell {
  std::vector<Index> faces;     // model faces
  std::vector<char> outward;    // per face: 1 when the face normal points out of the cell
  Index source_region = -1;     // input region
};

struct Decomposition {
  PolyhedralModel model;
  std::vector<ConvexCell> cells;
  DecomposeStats stats;
};

// Cavity removal and convex decomposition of every region: reflex edges in descending angle
// order, candidate planes of their inner wedge, the cut face method first, plane splitting next,
// unresolved edges deferred. Throws MeshingError naming the edge when an edge cannot be resolved.
Decomposition decompose(const PolyInput& in, const DecomposeOptions& opt = {});
Decomposition decompose(PolyhedralModel model, const DecomposeOptions& opt = {});

// The cells as a thesis .poly file: one region per cell, shared faces listed once.
void write_cells_poly(const Decomposition& d, const std::string& path);
std::string decompose_stats_json(const DecomposeStats& s);

}  // namespace bisect
