// The count of tetrahedra (thesis 6.11: the user asks for R elements). The spacing is searched
// on the count its nodes predict, before any filling: an interior node carries about 6.2
// tetrahedra and a boundary node 2.65 (fitted on lug, part, flange and plate-hole at 3,000 and
// 30,000 tetrahedra, where it predicts the count within 4%; a fixed ratio per node does not, as
// the boundary's share falls with the size). The cells are then filled; when the count misses
// R by more than 5%, the filling's own ratio corrects the prediction and the cells are filled
// again (at most three fillings; the closest count wins). When R is out of reach by more than
// 20%, the count the input's own nodes and edges allow is reported as the floor. Cells in thin
// walls (size/cell_walls.hpp) keep their spacing at kWallSizeFactor times the wall's thickness
// whatever R asks, which the floor then includes.
#pragma once
#include <cstdint>
#include <functional>
#include <string>

#include "bisect/generate.hpp"
#include "pipeline/node_placement.hpp"

namespace bisect::pipeline {

struct Calibrated {
  Built built;             // the nodes and the cells' tetrahedra of the filling kept
  double spacing = 0;      // the Np it used
  std::int64_t fillings = 0;
  std::int64_t count_floor = 0;  // 0 unless R was missed by more than 20%
  double thinnest_wall = 0;      // the thinnest cell wall that capped a cell's spacing (0: none)
  bool floor_by_walls = false;   // the walls' caps, not the input's facets, set count_floor
};

// The walls' words, the same in both routes: for count_floor_reason ("thickness: walls down to T
// thick, elements no larger across them") and for the element bound's message ("walls down to T
// thick get elements no larger than 0.8 T"), T to 3 digits.
std::string walls_floor_reason(double thickness);
std::string walls_why(double thickness);

// Where a count search starts: the spacing h at which the placed nodes are expected to predict
// `elements` tetrahedra (the rule above) in a domain of volume V bounded by faces of area A,
// k3 V / h^3 + k2 A / h^2 = R. The constants are the route's: its nodes on the faces are placed
// differently (NodeLaw's comments). Where curvature, short edges, thin walls or an input's own
// facets bound the sizes, it predicts too few, and the search goes on from there.
struct NodeLaw {
  double k3, k2;
};
// The B-rep route's: fitted on the search's rounds over the shared B-rep models at 10^5 and 10^6
// tetrahedra, where it is within 4% on most (the thesis's nominal 8 V / h^3 predicted 20% too few
// there, so that nearly every search placed its nodes twice): its surface mesher's nodes come
// denser than the volume's.
inline constexpr NodeLaw kBrepNodes{6.0, 1.7};
// The polyhedral route's: fitted on the search's rounds over the shared STL models and the
// thesis's .poly examples at 10^4 to 10^6 tetrahedra (230 rounds, those held up by the facets
// left out), where it is within 4% on half and 8% on 72% (the B-rep's constants 11% and 33%; the
// nominal 8 V / h^3 predicted 25% too few): its face grids' nodes stand where the interior's would
// have, so that the area adds little.
inline constexpr NodeLaw kPolyhedralNodes{5.9, 0.15};
double expected_spacing(double volume, double area, double elements, NodeLaw law);

// The count the placed nodes predict before any filling (the rule above): 6.2 tetrahedra per
// interior node, 2.65 per boundary node, times the last filling's ratio `scale` of its count to
// this prediction (1 before any filling).
double predicted_tets(double inside_nodes, double boundary_nodes, double scale = 1);

// One count search's rounds, the same in both routes: the count predicted at each trial spacing
// decides the next. While every trial lies on one side of R, the next steps by the count's power
// of the spacing: 3 (a cube root) at first, then the last two trials', between 1 and 3, as the
// boundary's nodes hold the count up (Angled.stl at 3*10^4 predicted 36.7k and 35.1k 7% coarser,
// where cube-root steps took ten placements to reach 32k); never past `largest`. Once two
// spacings bracket R, the next lies between them where the count's local power law (log-log
// between the two) puts R, at least a fifth of the bracket from either end (a box's count jumps
// with its lattices of nodes: cantilever.brep at 10^5 predicted 91.5k at one spacing and 108.5k
// 3% finer, and plain bisection went back and forth five times). The search ends when a
// prediction is within `tolerance` (a fraction) of R; at a jump, when the bracket is under 2%
// wide or the step under 1%; and at the floor: while no trial has come below R, a coarser one
// that lowered the count slower than h^-0.25 (curvature, the smallest features or the input's
// own facets keep it up: Angled.stl at 10^4 predicted 33.6k, 30.9k, 30.5k, 30.5k for spacings up
// to six times apart) or raised it (--grading grades from every boundary node finer than Np, and
// a coarser Np makes more of them sources: flange.stl at 2*10^4 and G = 0.3 predicted 46.9k
// rising to 52.1k over ten trials).
class CountSearch {
 public:
  CountSearch(double want, double tolerance, double largest) : want_(want), tolerance_(tolerance), largest_(largest) {}
  // Records the count predicted at spacing np; true when the search goes on at next().
  bool step(double np, double predicted);
  double next() const { return next_; }
  bool at_floor() const { return at_floor_; }
  // The search ended inside a bracket, with no better spacing between (under 2% wide, or a next
  // step under 1%): the count jumps across R. Would it still bracket R were every prediction
  // `factor` times what it was (a filling's ratio of its count to its prediction)? Then a search
  // with that ratio ends at the same jump, and another filling would only land beside it.
  bool jumps_across(double factor) const { return jumped_ && over_predicted_ * factor > want_ && under_predicted_ * factor < want_; }

 private:
  double want_, tolerance_, largest_;
  double next_ = 0, last_np_ = 0, last_predicted_ = 0;
  // the spacings that bracket R: the coarsest seen above it and the finest seen below it
  double over_np_ = 0, over_predicted_ = 0, under_np_ = 0, under_predicted_ = 0;
  bool at_floor_ = false, jumped_ = false;
};

// Throws InputError when `predicted` tetrahedra exceed opt.max_elements (when set), naming
// `source`, what predicted them (`by`), what keeps the elements small (`why`, may be empty) and
// opt.limit_cause.
void check_element_bound(double predicted, const GenerateOptions& opt, const std::string& source, const std::string& why,
                         const char* by = "the nodes placed");

// Fills the cells of d at the spacing `size` when > 0, else at the spacing whose count comes
// nearest `want`, starting the search from `start`. fill_progress(fraction of one filling's
// cells) is called on this thread; false cancels. Adds stage times to st.
Calibrated fill_to_count(const Decomposition& d, double start, double size, std::int64_t want, const GenerateOptions& opt,
                         const std::function<bool(double)>& fill_progress, GenerateStats& st);

}  // namespace bisect::pipeline
