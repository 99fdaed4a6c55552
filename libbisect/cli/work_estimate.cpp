#include "work_estimate.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "bisect/errors.hpp"

namespace bisect::cli {
namespace {

// Peak resident memory of a whole bisect-mesh run per element, measured (input, decomposition,
// the count's calibration and the output included): 4-node tetrahedra 190-220 bytes (lug.stl
// at 1e4 and 1e5, the thesis cubes at 3e4 and 2e5), 10-node 360, triangles 270 (2e4 to 3e5);
// rounded up by half, so that the estimate errs on the large side.
constexpr double kBytesPerTet = 320;
constexpr double kBytesPerTet10 = 540;
constexpr double kBytesPerTriangle = 400;
constexpr double kBaseMegabytes = 32;  // the program, a small input and OpenCASCADE
// -s gives 0.6-0.7 times 8 V / s^3 tetrahedra (nominal_spacing's Np = cbrt(8 V / R); the thesis
// cubes at s = 0.1 and 0.2, lug.stl); taken as 1 to err on the large side.
constexpr double kTetsPerNominal = 1.0;
// Nodes per tetrahedron, measured: 0.19-0.22 for 4-node meshes, 1.43 for 10-node ones.
constexpr double kNodesPerTet = 0.2, kNodesPerTet10 = 1.45;

std::string amount(double mb) {
  char buf[64];
  if (!std::isfinite(mb)) return "more than any machine has";
  if (mb >= 1024) std::snprintf(buf, sizeof buf, "%.3g GB", mb / 1024);
  else std::snprintf(buf, sizeof buf, "%.3g MB", mb);
  return buf;
}

std::string count(double n) {
  char buf[64];
  if (!std::isfinite(n)) return "unboundedly many";
  std::snprintf(buf, sizeof buf, n < 1e7 ? "%.0f" : "%.3g", n);
  return buf;
}

}  // namespace

WorkEstimate estimate_tet_mesh(double volume, std::int64_t elements, double size, int order, std::string cause) {
  WorkEstimate e;
  e.cause = std::move(cause);
  e.elements = size > 0 ? kTetsPerNominal * 8 * volume / (size * size * size) : static_cast<double>(elements);
  if (!(e.elements >= 0)) e.elements = INFINITY;  // NaN from a degenerate volume: refuse
  e.nodes = e.elements * (order == 2 ? kNodesPerTet10 : kNodesPerTet);
  e.megabytes = kBaseMegabytes + e.elements * (order == 2 ? kBytesPerTet10 : kBytesPerTet) / (1024.0 * 1024.0);
  return e;
}

WorkEstimate estimate_planar_mesh(std::int64_t elements, std::string cause) {
  WorkEstimate e;
  e.cause = std::move(cause);
  e.element_name = "triangles";
  e.elements = static_cast<double>(elements);
  e.nodes = e.elements / 2;
  e.megabytes = kBaseMegabytes + e.elements * kBytesPerTriangle / (1024.0 * 1024.0);
  return e;
}

double default_memory_limit_mb() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return 0;
  return static_cast<double>(pages) * static_cast<double>(page) / (1024.0 * 1024.0) / 2;
}

namespace {

// The limit in effect: --max-memory's MB, or half of the physical memory when none was given (0
// when the system does not say either), and its words for a message ("1.2 GB set by --max-memory").
struct Limit {
  double mb = 0;
  std::string words;
};
Limit memory_limit(double limit_mb) {
  const bool by_default = limit_mb <= 0;
  Limit l;
  l.mb = by_default ? default_memory_limit_mb() : limit_mb;
  if (l.mb > 0) l.words = amount(l.mb) + (by_default ? " (half of the physical memory; --max-memory MB sets another)" : " set by --max-memory");
  return l;
}

}  // namespace

double tets_within(double limit_mb, int order, std::string* cause) {
  const Limit l = memory_limit(limit_mb);
  if (l.mb <= 0) return 0;
  *cause = "the memory limit of " + l.words;
  return std::max(0.0, l.mb - kBaseMegabytes) * 1024.0 * 1024.0 / (order == 2 ? kBytesPerTet10 : kBytesPerTet);
}

void check_memory(const WorkEstimate& e, double limit_mb) {
  const Limit l = memory_limit(limit_mb);
  if (l.mb <= 0) return;  // the system does not say how much it has, and none was set
  if (e.megabytes <= l.mb) return;
  throw InputError(e.cause + ": an estimated " + count(e.elements) + " " + e.element_name + " and " + count(e.nodes) +
                   " nodes need about " + amount(e.megabytes) + " of memory, over the limit of " + l.words);
}

}  // namespace bisect::cli
