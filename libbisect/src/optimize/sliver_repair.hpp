// Sliver repair: a tetrahedron with a small dihedral angle that the local transformations
// leave (typically a sliver: four nodes near one circle, which no flip among its neighbours
// improves) has one of its free nodes moved off the plane of the face opposite it, or to its
// neighbours' mean, whichever gives the tetrahedra around that node the largest smallest
// dihedral angle; one whose four nodes are all fixed gets a new free node half an edge inside
// it (a Delaunay insertion), which the next round moves; the transformations run again
// around every change. After the rounds, a tetrahedron still under the bound with two free
// nodes has their edge collapsed (one node kept, where it was, at the edge's middle or at the
// mean of the merged star's nodes) when that raises the worst dihedral angle of the two nodes'
// stars.
#pragma once
#include <cstdint>
#include <vector>

#include "tet/tet_complex.hpp"

namespace bisect::optimize {

// Up to `rounds` rounds of moves (and insertions: X grows) on the tetrahedra whose smallest
// dihedral angle is below `below_deg`, starting from the live ones of `start` whose key is
// below sliver_key(below_deg) (every such tetrahedron's is: a list that holds all tetrahedra
// under that key misses none); each later round looks only at what the last one changed and at
// the tetrahedra it could not improve. cx must work on X and hold every tetrahedron's current
// key. fixed[v]: node v never moves; nodes past its end (inserted by an earlier repair) are free.
// Returns the moves, insertions and collapses made.
std::size_t repair_slivers(tet::TetComplex& cx, std::vector<Vec3>& X, const std::vector<char>& fixed, double below_deg, int rounds,
                           std::vector<Index> start);

// A bound on the key (tet_angle_key) of a tetrahedron with a dihedral angle under `below_deg`.
double sliver_key(double below_deg);

// The cosine of a tetrahedron's smallest dihedral angle (1 for a flat one), 2 when it is not
// positively oriented: smaller is better.
double worst_dihedral_cos(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace bisect::optimize
