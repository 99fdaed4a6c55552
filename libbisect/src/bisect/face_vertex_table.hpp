// The face-vertex list of thesis 7.2.2, built from a PolyhedralModel for one region: one entry
// per corner of every loop of the model's live faces, with its successor and predecessor in the
// loop, the entries of the faces adjacent across the edge to the successor (turning clockwise
// and anticlockwise about the edge, so an interface face sees a neighbour in each of its two
// regions, Fig. 7.2.2), and the region's angle at that edge, stored in only one of the two
// entries of the edge: the one where (J - I) * alpha > 0, J this node, I its successor, alpha
// +1 when the face normal points out of the region and -1 when it points in.
#pragma once
#include <limits>
#include <vector>

#include "bisect/polyhedral_model.hpp"

namespace bisect {

struct FaceVertex {
  Index node = -1, face = -1;
  int loop = 0;
  Index succ = -1, pred = -1;         // entries in the same loop
  Index adj_cw = -1, adj_ccw = -1;    // entries of the neighbouring faces on this edge, any region
  double angle = std::numeric_limits<double>::quiet_NaN();  // region angle at the edge, stored once
};

struct FaceVertexTable {
  Index region = -1;                 // the region whose angles are stored
  std::vector<FaceVertex> entries;   // all live faces, so interfaces see both sides
  // The region's angle at the edge from entry e's node to its successor, wherever it is stored.
  double edge_angle(Index e) const;
};

FaceVertexTable build_face_vertex_table(const PolyhedralModel& m, Index region);

}  // namespace bisect
