// A loop over [0, n) cut into contiguous chunks, run on several threads: for passes whose items
// are independent and write only their own slots (the tetrahedral complex's build at 10^6
// tetrahedra: on one thread, a quarter of a second for the scatter of its faces, an eighth for
// their pairing). The chunks depend on n and the grain alone, not on the threads that take
// them. An exception from a chunk reaches the caller (the first chunk's in order, as
// ordered_parallel.hpp does).
#pragma once
#include <algorithm>
#include <cstddef>

#include "util/ordered_parallel.hpp"

namespace bisect::util {

// body(begin, end) for consecutive ranges of about `grain` items covering [0, n).
template <class Body>
void parallel_chunks(std::size_t n, int threads, std::size_t grain, Body&& body) {
  grain = std::max<std::size_t>(grain, 1);
  const std::size_t chunks = (n + grain - 1) / grain;
  ordered_parallel(
      chunks, thread_count(threads), [&](std::size_t k) { body(k * grain, std::min(n, (k + 1) * grain)); }, [](std::size_t) {});
}

}  // namespace bisect::util
