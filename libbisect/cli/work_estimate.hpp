// The memory a meshing job will take, estimated before any of it is allocated, so that a request
// the machine cannot hold (`-n 1e9`, `-s` far below the part's size) is refused at once with the
// option that caused it, instead of running for minutes into "out of memory".
#pragma once
#include <cstdint>
#include <string>

namespace bisect::cli {

struct WorkEstimate {
  double elements = 0;  // tetrahedra, or triangles in 2D
  double nodes = 0;
  double megabytes = 0;    // peak memory of the run
  std::string cause;       // what set the count: "-n 1000000000", "-s 0.001", "R = 5000 in FILE"
  std::string element_name = "tetrahedra";
};

// A tetrahedral mesh of `elements` tetrahedra (> 0), or of spacing `size` (> 0, which wins, as in
// SizeOptions) in a part of volume `volume`; order 1 or 2.
WorkEstimate estimate_tet_mesh(double volume, std::int64_t elements, double size, int order, std::string cause);

// A planar mesh of `elements` triangles.
WorkEstimate estimate_planar_mesh(std::int64_t elements, std::string cause);

// Half of the physical memory in megabytes (sysconf), the default of --max-memory; 0 when the
// system does not say.
double default_memory_limit_mb();

// The tetrahedra (of order 1 or 2) that fit in `limit_mb` (0: default_memory_limit_mb()), and in
// *cause the setting that says so, for GenerateOptions::max_elements; 0 when no limit is known.
double tets_within(double limit_mb, int order, std::string* cause);

// Throws InputError when the estimate exceeds `limit_mb` (0: default_memory_limit_mb()), naming
// the cause, the estimate and --max-memory.
void check_memory(const WorkEstimate& e, double limit_mb);

}  // namespace bisect::cli
