// A map from an edge key (two node ids packed in 64 bits, never 0) to a small value, kept in one
// flat array with linear probing: a lookup is one multiplication and, mostly, one cache line.
// Edge removal asks it about every edge it tries (TetComplex's failures); in a node-based hash
// map the chain's pointers and a division per step were 5% of a whole run at 3*10^5 tetrahedra.
// Only find, assignment, erase and clear: nothing walks the entries, so their order is free.
#pragma once
#include <cstdint>
#include <vector>

namespace bisect::tet {

template <class Value>
class EdgeTable {
 public:
  // The value stored for key, or null.
  Value* find(std::uint64_t key) {
    if (slots_.empty()) return nullptr;
    for (std::size_t i = home(key);; i = (i + 1) & mask()) {
      if (slots_[i].key == key) return &slots_[i].value;
      if (slots_[i].key == 0) return nullptr;
    }
  }

  // key's value set to v (added when absent).
  void put(std::uint64_t key, const Value& v) {
    if (2 * (count_ + 1) > slots_.size()) grow();
    std::size_t i = home(key);
    while (slots_[i].key != 0 && slots_[i].key != key) i = (i + 1) & mask();
    if (slots_[i].key == 0) ++count_;
    slots_[i] = Slot{key, v};
  }

  // Removes key (no tombstone: the entries after it in its run are moved back to where a search
  // from their home finds them).
  void erase(std::uint64_t key) {
    if (slots_.empty()) return;
    std::size_t i = home(key);
    while (slots_[i].key != key) {
      if (slots_[i].key == 0) return;
      i = (i + 1) & mask();
    }
    for (std::size_t j = (i + 1) & mask(); slots_[j].key != 0; j = (j + 1) & mask()) {
      const std::size_t h = home(slots_[j].key);
      // j's entry may fill the gap at i when its home is not in (i, j] (cyclically)
      if (((j - h) & mask()) >= ((j - i) & mask())) {
        slots_[i] = slots_[j];
        i = j;
      }
    }
    slots_[i].key = 0;
    --count_;
  }

  void clear() {
    slots_.clear();
    count_ = 0;
  }

  std::size_t size() const { return count_; }

 private:
  struct Slot {
    std::uint64_t key = 0;  // 0: empty
    Value value{};
  };
  std::vector<Slot> slots_;  // a power of two, at most half full
  std::size_t count_ = 0;

  std::size_t mask() const { return slots_.size() - 1; }
  std::size_t home(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 32) & mask();  // Fibonacci hashing
  }
  void grow() {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(old.empty() ? 1024 : 2 * old.size(), Slot{});
    count_ = 0;
    for (const Slot& s : old)
      if (s.key != 0) put(s.key, s.value);
  }
};

}  // namespace bisect::tet
