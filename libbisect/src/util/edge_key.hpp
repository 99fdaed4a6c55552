// An edge of a mesh as one 64-bit key: its two node ids, the lower in the high half. The same
// edge gives the same key whichever way it is named, and a key is never 0 for a real edge (its
// nodes differ), which tet/edge_table.hpp uses as the empty slot.
#pragma once
#include <cstdint>
#include <utility>

#include "bisect/types.hpp"

namespace bisect {

inline std::uint64_t edge_key(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}
// The lower and the higher node id of a key.
inline Index key_lo(std::uint64_t k) { return static_cast<Index>(k >> 32); }
inline Index key_hi(std::uint64_t k) { return static_cast<Index>(k & 0xffffffffu); }

}  // namespace bisect
