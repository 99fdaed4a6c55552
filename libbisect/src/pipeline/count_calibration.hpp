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

// Where the B-rep route's count search starts: the spacing h at which the placed nodes are
// expected to predict `elements` tetrahedra (the rule above) in a domain of volume V bounded by
// faces of area A, k3 V / h^3 + k2 A / h^2 = R with k3 = 6.0 and k2 = 1.7. Fitted on the search's
// rounds over the shared B-rep models at 10^5 and 10^6 tetrahedra, where it is within 4% on most
// (nominal_spacing's 8 V / h^3, the thesis's, predicted 20% too few there, so that nearly every
// search placed its nodes twice). Where curvature, short edges or thin walls bound the sizes it
// predicts too few, as nominal_spacing does, and the search goes on from there.
double expected_spacing(double volume, double area, double elements);

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
