// A tetrahedral complex that changes in place: the working structure of the boundary-constrained
// min-max triangulation (thesis 7.6) and of the local transformations (7.5). Tetrahedra are
// positively oriented (tet_mesh.hpp), face f lies opposite corner f, and adj[t][f] is 4 u + g
// for the tetrahedron u across it and u's face g there (HXT's convention: the way back is
// stored, never searched), -1 on the boundary of what is being meshed. Every change goes through
// `replace`, which swaps a set of tetrahedra for another set filling the same space and relinks
// the new ones to each other and to the old outside neighbours, so a flip, a point insertion
// and the removal of a helper vertex are each a few lines.
//
// Constrained faces (the boundary of a cell, or input faces and region interfaces in the global
// pass) are the faces with no neighbour plus the faces given to `constrain`: no transformation
// crosses or removes them. They are kept as a bit per tetrahedron face, handed on by `replace`
// (the hottest test of the transformations: a hash lookup per face step cost a tenth of the time).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "bisect/types.hpp"
#include "tet/edge_table.hpp"

namespace bisect::tet {

using Tet = std::array<Index, 4>;

// A face's three nodes, sorted.
struct FaceKey {
  Index a, b, c;
  bool operator==(const FaceKey& o) const { return a == o.a && b == o.b && c == o.c; }
};
FaceKey face_key(Index a, Index b, Index c);
// A triangle's nodes turned so that the smallest comes first: equal for the same triangle with the
// same orientation, whichever node it starts from (face_key forgets the orientation).
inline std::array<Index, 3> smallest_first(const std::array<Index, 3>& t) {
  const int k = t[0] < t[1] ? (t[0] < t[2] ? 0 : 2) : (t[1] < t[2] ? 1 : 2);
  return {t[k], t[(k + 1) % 3], t[(k + 2) % 3]};
}
struct FaceKeyHash {
  std::size_t operator()(const FaceKey& k) const {
    return (static_cast<std::size_t>(k.a) * 73856093u) ^ (static_cast<std::size_t>(k.b) * 19349663u) ^ (static_cast<std::size_t>(k.c) * 83492791u);
  }
};

class TetComplex {
 public:
  explicit TetComplex(const std::vector<Vec3>& nodes) : X(nodes) {}

  const std::vector<Vec3>& X;
  std::vector<Tet> tet;
  std::vector<Tet> adj;  // 4 u + g, or -1 (above)
  // 4 u + g fits a 32-bit Index up to this many tetrahedra (the complex alone would hold some
  // 30 GB then, which the memory bound refuses first; build and replace throw past it all the same).
  static constexpr std::size_t kMaxTets = std::size_t{1} << 29;
  // The tetrahedron across face f of t (-1: none), and its face there (when there is one).
  Index neighbour(Index t, int f) const { return adj[t][f] < 0 ? -1 : adj[t][f] >> 2; }
  int neighbour_face(Index t, int f) const { return adj[t][f] & 3; }
  std::vector<char> alive;
  std::vector<Index> tag;  // per tetrahedron (its region); new ones take the first old one's
  std::vector<double> q;   // per tetrahedron: tet_angle_key, the min-max criterion
  // The outer boundary's faces with the (planar) input face each lies in. With boundary_flips,
  // two boundary faces of one input face that meet at an edge take the quadrilateral's other
  // diagonal when that raises the smallest solid angle (7.5, the 2-2 transformation) and keeps
  // the boundary triangles' angles (at least 20 degrees, or the old ones); the map follows.
  std::unordered_map<FaceKey, Index, FaceKeyHash> surface_tag;
  bool boundary_flips = false;
  // Edge removal (a small dynamic programme per edge) is tried only where a tetrahedron's
  // smallest solid angle is below this key (tet_angle_key); above it the gain is small and the
  // cost is not. The default, tan(0.1), is Ω < 0.2 sr (the regular tetrahedron's is 0.551).
  static constexpr double kEdgeRemovalBelow = 0.10033467208545055;
  double edge_removal_below = kEdgeRemovalBelow;
  // When set, `replace` and `moved` append the tetrahedra they make or change: the optimiser's
  // work lists follow the changes without a scan of the mesh.
  std::vector<Index>* changed = nullptr;
  // When set, `replace` appends the ids it takes out and the ids it makes: a consumer that keeps
  // its own per-tetrahedron data (face recovery's count of the present faces and edges) brings
  // just those up to date.
  std::vector<Index>* touched = nullptr;
  // When set, `replace` appends what it did (the tetrahedra it made, those it took out and their
  // tags), and undo() takes such a record back, last change first: a trial that came out worse
  // is undone without a copy of the complex. Node moves are the caller's to put back (X) first,
  // and afterwards the keys of the tetrahedra they moved (moved()).
  struct Replacement {
    std::vector<Tet> made;
    std::vector<Tet> old;
    std::vector<Index> old_tags;
    bool new_boundary = false;  // replace()'s: a change of the outer boundary (a 2-2 flip)
  };
  std::vector<Replacement>* journal = nullptr;
  // among: when given, the ids the journalled changes made are all in it (the `touched` log of
  // a local change), and only those are searched, not the whole complex.
  void undo(std::vector<Replacement>& entries, const std::vector<Index>* among = nullptr);
  // undo()'s step for a change of the outer boundary: replace() with new_boundary, and the
  // surface tags of the triangles it gives back. Returns the ids of `old` put back.
  std::vector<Index> undo_boundary_change(const std::vector<Index>& made, const std::vector<Tet>& old);
  // When set, the long loops (the transformations' queue, the smoothing, the sliver repair) call
  // it now and then (every kPollEvery steps); true stops them with Cancelled. The optimiser sets
  // it from the progress callback, so that Stop takes effect within a pass.
  std::function<bool()> cancelled;
  static constexpr std::size_t kPollEvery = 2048;
  void poll(std::size_t step) const;  // throws Cancelled when cancelled() says so (every kPollEvery steps)

  // Builds the adjacency of a fresh set of tetrahedra (faces matched by their nodes); tags
  // default to 0. The quality keys, the sort of the faces and their pairing run on `threads`
  // (0: every core); the complex is the same for any count.
  void build(std::vector<Tet> tets, std::vector<Index> tags = {}, int threads = 1);
  // The live tetrahedra, and their tags in the same order.
  std::vector<Tet> tets() const;
  std::vector<Index> tags() const;
  // Marks these faces (of the current tetrahedra) as constrained; faces not in the complex are
  // ignored.
  void constrain(const std::unordered_set<FaceKey, FaceKeyHash>& faces, int threads = 1);
  void refresh_quality();  // after the nodes moved (smoothing)
  void moved(const std::vector<Index>& tets);  // after some tetrahedra's nodes moved
  // the same with their keys (tet_angle_key) already known: keys[i] is tets[i]'s
  void moved(const std::vector<Index>& tets, const std::vector<double>& keys);
  std::size_t live_count() const { return tet.size() - free_.size(); }

  // Swaps the tetrahedra `old` for `fresh` (same region of space). Returns the new ids.
  // new_boundary: faces of `fresh` that match nothing are outer boundary (the 2-2
  // transformation re-triangulates it), else that is an error; and an old set's outside face
  // that no new one takes up becomes the outer boundary of the tetrahedron beyond it (a
  // tetrahedron with two faces on the boundary taken out: the surface's edge flips).
  std::vector<Index> replace(const std::vector<Index>& old, const std::vector<Tet>& fresh, bool new_boundary = false);

  // Face f's nodes, ordered so that their right-hand normal points out of t.
  std::array<Index, 3> face(Index t, int f) const;
  bool is_constrained(Index t, int f) const;
  // Marks face f of t, and the same face of the tetrahedron across it, as constrained (a face a
  // change made where one was before: an interface's triangles after an edge flip on it).
  void hold(Index t, int f);
  int corner_of(Index t, Index v) const;  // -1 when v is not a corner
  std::vector<Index> tets_at(Index v) const;  // the live tetrahedra with corner v (a full scan)
  // The live tetrahedra with corner v, found from t0 (one of them) across the faces at v, in
  // the order they are reached, t0 first; the search stops once more than `limit` are found.
  std::vector<Index> star(Index v, Index t0, std::size_t limit) const;
  // The face of t shared with `other`, -1 if none: a search, for checks; the complex's own
  // steps read it from adj.
  int face_towards(Index t, Index other) const;

  // The live tetrahedron whose closure holds p, by a visibility walk from `start` (a full scan
  // when the walk does not settle); -1 when p is outside every tetrahedron.
  // near_only: when the walk does not settle, only the tetrahedra nearest p reached from where
  // it stopped are searched, not the whole complex (for a point placed beside a tetrahedron,
  // which may lie outside the mesh: a whole search cost 0.15 s at 10^6 each time): those whose
  // centroid lies within twice the longest edge of `start` and of the walk's last tetrahedron,
  // plus start's own distance, of p, and at most kNearSearch of them. Every holder the search
  // found (the sliver repair's trials on lug, flange and part at 10^5, corpus Zylkopf, x_ring and
  // Kurbelwelle at 2*10^4) was among the first 26 it tried; where the bound held thousands of
  // long flat tetrahedra (a wall 0.05 thick gridded at 2.9: 3,167 searches went to 4,096, 19
  // million tetrahedra tried in all, 9 of a 12.8 s run in the sliver repair) they were tried in
  // vain, so the count is cut at ten times that.
  static constexpr std::size_t kNearSearch = 256;
  Index locate(const Vec3& p, Index start, bool near_only = false) const;
  // How many tetrahedra the last locate's near search tried (0 when its walk settled): for
  // the tests, which hold the search near.
  mutable std::size_t near_searched = 0;
  // Inserts node v (its position already in X) inside the complex: the tetrahedra whose
  // closure holds it are split (1-4 inside, 2-6 on a face, n-2n on an edge). Returns the new
  // tetrahedra, empty when v lies outside or on an existing node.
  std::vector<Index> insert(Index v, Index start);
  // The same insertion with a Delaunay cavity (Bowyer-Watson, exact insphere): every
  // tetrahedron reachable without crossing a constrained face whose circumsphere holds v is
  // replaced too, the cavity shrunk until v sees all its faces from inside. `replaced`, if
  // given, receives the cavity's tetrahedra: replace(made, *replaced) undoes the insertion.
  // near_only: v is looked for only near `start` (locate's near_only).
  std::vector<Index> insert_delaunay(Index v, Index start, std::vector<Tet>* replaced = nullptr, bool near_only = false);

  // Local min-max transformations (7.5) from the given faces onwards, whenever they raise the
  // smallest solid angle of the tetrahedra involved: 2-3 across a face, 2-2 at the outer
  // boundary (boundary_flips), and the removal of an
  // interior edge whose ring has 3 to kMaxRing tetrahedra, the ring's polygon triangulated at
  // its best (3-2 and the 4-4 of 7.5 are its rings of 3 and 4; larger rings reach further out
  // of the local minima 7.6.1 describes). Returns the number applied.
  std::int64_t improve(std::vector<std::pair<Index, int>> queue, std::int64_t max_ops);
  // Removes the interior node v by flips (7.6: the helper vertex): edges at v are taken out of
  // their rings (the ring's best triangulation, whatever its quality) until v is in four
  // tetrahedra, which a 4-1 flip merges. False, with v still in the complex, when no edge at v
  // can go (its ring is longer than kMaxRing or has no valid triangulation).
  bool remove_vertex(Index v);
  // The three tetrahedra a 2-3 transformation across face f of t would make (each corner of the
  // face replaced by the node beyond it), into `fresh`; false when f is on the boundary or
  // constrained. Their orientation is the caller's to test, with positive_all, after its quality
  // keys: one that is not positive means the segment between the two apexes misses the face.
  // An exact orientation is dearer than a key, and most trials fail on the key (tested first,
  // flange.stl at 2*10^5 on one thread spent 4% of its run in orient3d's exact stage here, on
  // the coplanar nodes of the cells' flat faces).
  bool flip23_unchecked(Index t, int f, std::vector<Tet>* fresh) const;
  bool positive_all(const std::vector<Tet>& tets) const;
  // improve() from every face of the given tetrahedra (new or changed ones), without a bound.
  std::int64_t improve_around(const std::vector<Index>& tets);
  // improve() from every unconstrained interior face.
  std::int64_t improve_all(std::int64_t max_ops);

  // The tetrahedra around the edge (a, b) of t, in order, into ring (at most `cap`; cap + 1 is
  // returned when there are more), and apex[i], the node that ring[i] shares with ring[i + 1]
  // besides a and b. `closed`: the ring closes (an interior edge); `held`: it ends at a
  // constrained face (the edge lies on one).
  int edge_ring(Index t, Index a, Index b, int cap, Index* ring, Index* apex, bool* closed, bool* held) const;
  // The ring polygon p[0..k) around edge (a, b) (k <= kMaxRing) triangulated at its best by
  // dynamic programming, every tetrahedron's key above `need`: each triangle joined to a and to b,
  // the tetrahedra into `fresh`; false when none is. The polygon's side p[k-1] p[0] may be a chord
  // of an open ring (an edge on the boundary: the surface's edge flips take the edge (a, b) out
  // of the boundary that way, pipeline/brep_surface_flips.hpp).
  bool ring_triangulation(Index a, Index b, const Index* p, std::size_t k, double need, std::vector<Tet>* fresh) const;
  static constexpr std::size_t kMaxRing = 7;

 private:
  std::vector<Index> free_;
  std::vector<unsigned char> cmask_;  // bit f: face f is constrained (besides adj < 0)
  // Edge removal remembers its failures: an edge whose ring of tetrahedra is unchanged since
  // (every one born before the failure, and no node moved) fails again, so its dynamic
  // programme is skipped. born_: a clock value per tetrahedron, set when made or moved.
  std::vector<std::uint64_t> born_;
  std::uint64_t clock_ = 0;
  void stamp_moved(const std::vector<Index>& tets);  // moved()'s clock, born_ and log
  // A failure: the clock then and the ring; kForever for an edge on a constrained face.
  static constexpr std::uint64_t kForever = ~std::uint64_t{0};
  struct Failure {
    std::uint64_t stamp;
    int k;
    std::array<Index, kMaxRing> ring;
  };
  EdgeTable<Failure> failed_;  // edge (low node << 32 | high) -> failure
  // The 2-3 transformation remembers its failures the same way, per face (4 t + f, both sides):
  // the clock when it failed there, 0 for never. Its outcome depends on the two tetrahedra
  // alone, so while neither is born after that it fails again: a later pass's list and the
  // second side of a face hold many such. 32 bits a face: a clock past them records nothing.
  std::vector<std::uint32_t> flip_failed_;
  // per-tetrahedron marks for set membership in replace and insert_delaunay (a stamp per use,
  // so nothing is cleared): cavities of thousands of tetrahedra made linear searches quadratic
  mutable std::vector<unsigned> mark_;
  // replace's working lists, kept from call to call (a flip's are a few dozen entries, and
  // allocating them anew was a sixth of replace's time): the old set's outside faces with the
  // tetrahedron across, and every face to be matched
  struct Outer {
    FaceKey key;
    Index n;
    int nf;
    bool held;  // constrained
  };
  struct Side {
    FaceKey key;
    Index t;
    int f;
    bool fresh, held;
  };
  std::vector<Outer> outer_;
  std::vector<Side> sides_;
  struct Slot {
    int first = -1, second = -1, more = 0;  // sides with one key: the first two, and how many after the first
  };
  std::vector<Slot> slots_;
  // the transformations' candidate tetrahedra and the ring they replace, kept the same way
  std::vector<Tet> fresh_;
  std::vector<Index> old_;
  mutable unsigned stamp_ = 0;
  unsigned new_stamp() const {
    mark_.resize(tet.size(), 0);
    if (++stamp_ == 0) std::fill(mark_.begin(), mark_.end(), 0), stamp_ = 1;
    return stamp_;
  }
  bool marked(Index t, unsigned s) const { return t >= 0 && static_cast<std::size_t>(t) < mark_.size() && mark_[t] == s; }
  // The tetrahedra whose closure holds p, from t0 (which does) across the faces p lies on;
  // false when p is on a node or on a constrained face.
  bool holders(const Vec3& p, Index t0, std::vector<Index>* hold) const;
  bool try_flip23(Index t, int f, std::vector<std::pair<Index, int>>& queue);
  bool try_flip22(Index t, int f, std::vector<std::pair<Index, int>>& queue);
  bool try_edge_removal(Index t, Index a, Index b, std::vector<std::pair<Index, int>>& queue);
};

// Positive orientation test of a tetrahedron given by node ids.
bool positive(const std::vector<Vec3>& X, const Tet& t);
// The min-max criterion's key: tan(Ω/2) of the smallest solid angle Ω, which orders tetrahedra
// as Ω does without an arctangent; negative for a tetrahedron inside out (a fold the morph onto
// the true surface left), so that a transformation or a node move that undoes it counts as a
// gain. With |6V| a fold could grade better than the tetrahedra that would replace it, and
// stayed: on corpus/Kurbelwelle.brep 29 folds reached the refill, now 24 (its caps over a
// fillet's tangent edge need a new node, which no transformation adds).
double tet_angle_key(const std::vector<Vec3>& X, const Tet& t);

}  // namespace bisect::tet
