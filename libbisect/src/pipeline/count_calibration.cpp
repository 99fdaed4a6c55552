#include "pipeline/count_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bisect/errors.hpp"
#include "pipeline/cell_filling.hpp"
#include "size/cell_walls.hpp"
#include "size/size_field.hpp"

namespace bisect::pipeline {
namespace {

struct NodeTally {
  double boundary = 0, interior = 0;
};
NodeTally tally_nodes(const PolyhedralModel& m, const Built& b) {
  NodeTally n;
  for (char k : node_kinds(m, b)) (k == kOnInputFace ? n.boundary : n.interior) += k != kUnused;
  return n;
}

double predict_tets(const NodeTally& n, double scale) { return scale * (6.2 * n.interior + 2.65 * n.boundary); }

// The spacing whose nodes predict `want` tetrahedra: a cube-root step from `start`, then
// bisection in log Np once two spacings bracket the count (on small models the count jumps with
// the segments per edge and the shrinking layers, so it may not be met exactly). Only the nodes
// are placed (a fraction of a filling).
double search_spacing(const Decomposition& d, const std::vector<double>& cap, double start, double want, double scale, int threads, double grading,
                      GenerateStats& st, double* best_predicted) {
  double lo = 0, hi = 0, trial = start, best = start, best_miss = 1e300, last_predicted = -1, last_trial = 0;
  int futile = 0;  // coarser trials in a row that did not lower the count
  for (int round = 0; round < 10; ++round) {
    const double predicted = predict_tets(tally_nodes(d.model, place_nodes(d, trial, cap, threads, grading, &st.gen_nodes, true)), scale);
    const double miss = std::abs(predicted - want);
    if (miss < best_miss) best_miss = miss, best = trial, *best_predicted = predicted;
    if (miss <= 0.02 * want) break;
    // Coarser spacings that give as many or more tetrahedra twice running: the count is held up
    // by the boundary (--grading grades from every boundary node finer than Np, and a coarser Np
    // makes more of them sources: flange.stl at R = 2·10^4 and G = 0.3 predicted 46,863 rising
    // to 52,149 over ten trials of up to 5 s each), so coarser still will not help.
    futile = last_predicted > 0 && trial > last_trial && predicted >= last_predicted ? futile + 1 : 0;
    if (futile >= 2) break;
    last_predicted = predicted, last_trial = trial;
    if (predicted > want) lo = std::max(lo, trial);
    else hi = hi > 0 ? std::min(hi, trial) : trial;
    const double next = lo > 0 && hi > 0 ? std::sqrt(lo * hi) : trial * std::cbrt(predicted / want);
    if (std::abs(next / trial - 1) < 1e-3) break;
    trial = next;
  }
  return best;
}

// For the element bound's message: the thinnest wall whose cap is below `spacing`, as "walls down
// to T thick get elements no larger than 0.8 T"; empty when no cap is.
std::string walls_below(const std::vector<double>& cap, double spacing) {
  double thinnest = 0;
  for (double c : cap)
    if (c > 0 && c < spacing) thinnest = thinnest > 0 ? std::min(thinnest, c) : c;
  return thinnest > 0 ? walls_why(thinnest / size::kWallSizeFactor) : "";
}

}  // namespace

std::string walls_floor_reason(double thickness) {
  char text[96];
  std::snprintf(text, sizeof text, "thickness: walls down to %.3g thick, elements no larger across them", thickness);
  return text;
}

std::string walls_why(double thickness) {
  char text[96];
  std::snprintf(text, sizeof text, "walls down to %.3g thick get elements no larger than %.3g", thickness, size::kWallSizeFactor * thickness);
  return text;
}

double expected_spacing(double volume, double area, double elements) {
  constexpr double k3 = 6.0, k2 = 1.7;
  if (!(volume > 0) || !(elements > 0)) return 0;
  const double a = std::max(area, 0.0);
  // Newton's method on f(x) = k3 V x^3 + k2 A x^2 - R for x = 1 / h, increasing and convex for
  // x > 0: from the volume term's root (f >= 0 there) it falls monotonically onto the root
  double x = std::cbrt(elements / (k3 * volume));
  for (int i = 0; i < 50; ++i) {
    const double f = (k3 * volume * x + k2 * a) * x * x - elements, df = (3 * k3 * volume * x + 2 * k2 * a) * x;
    const double step = f / df;
    x -= step;
    if (!(std::abs(step) > 1e-12 * x)) break;
  }
  return 1 / x;
}

void check_element_bound(double predicted, const GenerateOptions& opt, const std::string& source, const std::string& why, const char* by) {
  if (!(opt.max_elements > 0) || predicted <= opt.max_elements) return;
  char text[200];
  std::snprintf(text, sizeof text, "%s predict about %.3g tetrahedra, over the limit of %.3g", by, predicted, opt.max_elements);
  throw InputError(source + ": " + text + (why.empty() ? "" : " (" + why + ")") + (opt.limit_cause.empty() ? "" : "; " + opt.limit_cause));
}

Calibrated fill_to_count(const Decomposition& d, double start, double size, std::int64_t want, const GenerateOptions& opt,
                         const std::function<bool(double)>& fill_progress, GenerateStats& st) {
  Calibrated out;
  double np = start, last = -1, scale = 1, best_miss = 1e300;
  const double target = static_cast<double>(want);
  const int threads = opt.threads;
  const double grading = opt.sizing.grading;
  // the cells' caps: kWallSizeFactor times their walls' thickness
  std::vector<double> cap = size::cell_wall_thickness(d);
  for (double& c : cap) c *= size::kWallSizeFactor;
  // a first, cheap bound before any node is placed (the search below places them at every trial,
  // which for a thin sheet of 1000 x 1000 x 1 at R = 10^4 ran for minutes): each cell's nominal
  // count 8 V / h^3 at the start spacing or its cap
  if (opt.max_elements > 0) {
    double nominal = 0;
    for (std::size_t c = 0; c < d.cells.size(); ++c) {
      const double h = cap[c] > 0 ? std::min(start, cap[c]) : start;
      nominal += 8 * cell_polytope(d.model, d.cells[c]).volume() / (h * h * h);
    }
    const std::string why = walls_below(cap, start);
    if (!why.empty()) check_element_bound(nominal, opt, d.model.source, why, "the cells' volumes at their spacings");
  }
  for (int fill_round = 0; fill_round < 3; ++fill_round) {
    double predicted = 0;
    const double spacing = size > 0 ? size : search_spacing(d, cap, np, target, scale, threads, grading, st, &predicted);
    if (last > 0 && std::abs(spacing / last - 1) < 1e-3) break;  // nothing new to try
    last = spacing;
    if (opt.max_elements > 0) {  // refused before the filling, where the memory goes
      if (size > 0) predicted = predict_tets(tally_nodes(d.model, place_nodes(d, spacing, cap, threads, grading, &st.gen_nodes, true)), scale);
      check_element_bound(predicted, opt, d.model.source, walls_below(cap, spacing), "the nodes placed");
    }
    Built again = place_nodes(d, spacing, cap, threads, grading, &st.gen_nodes);
    fill_cells(d, again, opt.delaunay_insertion, threads, fill_progress, &st.gen_tets);
    ++out.fillings;
    const double count = static_cast<double>(again.tets.size());
    const double miss = std::abs(count - target);
    scale = count / predict_tets(tally_nodes(d.model, again), 1);
    if (miss < best_miss) best_miss = miss, out.built = std::move(again), out.spacing = spacing;
    if (size > 0 || best_miss <= 0.05 * target) break;
    np = spacing;  // the next search starts here
  }
  if (size <= 0 && best_miss > 0.2 * target) {
    // out of reach: tell what the input allows (the count at a spacing the size of the model,
    // where only the input's own nodes and edges are left), as measured by the last filling
    double scratch = 0;
    double reach = 0;  // at least half the model's diameter
    for (const Vec3& p : d.model.nodes) reach = std::max(reach, (p - d.model.nodes.front()).norm());
    const Built coarsest = place_nodes(d, 2 * reach, cap, threads, grading, &scratch, true);
    const double floor = predict_tets(tally_nodes(d.model, coarsest), scale);
    out.count_floor = std::llround(floor);
    // the walls' doing when they raise that count by more than a tenth (else the facets')
    const Built uncapped = place_nodes(d, 2 * reach, {}, threads, grading, &scratch, true);
    out.floor_by_walls = floor > 1.1 * predict_tets(tally_nodes(d.model, uncapped), scale);
  }
  for (std::size_t c = 0; c < cap.size(); ++c)
    if (cap[c] > 0 && (cap[c] < out.spacing || out.floor_by_walls)) {  // at the floor every wall caps
      const double wall = cap[c] / size::kWallSizeFactor;
      out.thinnest_wall = out.thinnest_wall > 0 ? std::min(out.thinnest_wall, wall) : wall;
    }
  return out;
}

}  // namespace bisect::pipeline
