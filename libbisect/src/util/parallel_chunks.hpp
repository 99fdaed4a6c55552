// A loop over [0, n) cut into contiguous chunks, run on several threads: for passes whose items
// are independent and write only their own slots (the tetrahedral complex's quality keys and
// face pairing at 10^6 tetrahedra, a third of a second each on one thread). The chunks are the
// same for every thread count, so what each writes is too. An exception from a chunk reaches
// the caller (the first chunk's in order, as ordered_parallel.hpp does).
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
