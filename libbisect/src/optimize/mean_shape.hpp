// The mean shape after the min-max passes. Those stop once the worst tetrahedron around every
// face, edge and node can rise no more, and leave the others as they came; at coarse counts most
// tetrahedra touch the boundary, whose nodes those passes never move, and the mean α̂ (inradius /
// circumradius, thesis 8.3.1) stays at what the fill gave. These passes raise it without
// giving up what the min-max passes and the sliver repair won: no change lowers the smallest key
// (tet_angle_key) of the tetrahedra it touches, nor makes a dihedral angle under 10.5 degrees.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "tet/tet_complex.hpp"

namespace bisect::optimize {

struct MeanCounts {
  std::int64_t flips = 0;  // 2-3 and 3-2 transformations
  std::int64_t moves = 0;  // node moves
};

// The fixed nodes that may move within the input face they lie inside (not on its edges) all the
// same: at coarse counts most nodes are on the boundary (two-boxes-cavity.brep at R = 1000: 272
// of 330), and the grids on the two sides of a thin wall, made one face at a time, do not line
// up; moving them in their faces lets the tetrahedra between them take better shapes. Such a
// move keeps the smallest angle of the node's boundary triangles (its constrained faces; or 30
// degrees, whichever is less) and the smallest dihedral angle of its star; a move in a plane
// normal to an axis leaves that coordinate exactly as it was.
struct FaceSlides {
  // per node (may be shorter than X): the unit normal of the flat face it lies inside; zero: none
  std::vector<Vec3> plane;
  // per node (may be shorter than X): it lies inside a curved face, on which `onto` keeps it
  std::vector<char> curved;
  // for such a node v: the point of its face nearest p, and (when normal is not null) the face's
  // unit normal there; called from several threads at once
  std::function<Vec3(Index v, const Vec3& p, Vec3* normal)> onto;
  // per node (may be shorter than X): it lies inside a B-rep edge (not at a vertex), along which
  // `along` keeps it. Only the surface angles' pass (surface_angles.hpp) moves such nodes: the
  // mean shape's face moves leave them where the edge grids put them.
  std::vector<char> edge;
  // for such a node v: the point of its edge nearest p, and (when tangent is not null) the edge's
  // unit tangent there; not finite where p is nearer another part of the edge than v's own (a
  // closed edge's far end)
  std::function<Vec3(Index v, const Vec3& p, Vec3* tangent)> along;
};

// How node v may move in its face: not at all (a free node, or a fixed one `slides` names no face
// for), in a plane, or on a curved face. (kEdge, along a B-rep edge, is the surface angles' pass's
// own: slide_of never answers it.)
enum class Slide { kNone, kPlane, kCurved, kEdge };
Slide slide_of(const FaceSlides& slides, const std::vector<char>& fixed, Index v);

// A face's unit normal as FaceSlides::plane holds it: one within round-off of an axis made exactly
// that axis (so that a move in the plane leaves that coordinate as it was); zero when n is not a
// unit vector.
Vec3 slide_normal(const Vec3& n);

// Up to `rounds` rounds, each from the tetrahedra whose α̂ is under 0.18 (its start): a pass of
// transformations across their interior faces (2-3) and round their interior edges in three
// tetrahedra (3-2), then a pass of node moves over their free nodes; a round that changes
// nothing ends the work. A transformation is made when the mesh's mean
// α̂ rises by it (the new tetrahedra's α̂ summed, less the old ones', above the running mean
// times the change in count) and the smallest key of the tetrahedra involved does not fall. A
// free node (or one that `slides` lets move in its face) moves up the gradient of its star's summed α̂ when every tetrahedron around it stays
// positive and their smallest key does not fall. The transformations in the order of the
// tetrahedra's ids, on one thread; the node moves colour by colour (no two nodes of a colour
// share a tetrahedron), each colour's on `threads` threads (0: one per core): the output is the
// same for the same input, whatever the thread count.
// fixed[v]: node v never moves (but for `slides`); nodes past its end (inserted by the sliver
// repair) are free.
MeanCounts improve_mean(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed, int rounds, int threads = 1,
                        const FaceSlides& slides = {});

}  // namespace bisect::optimize
