// The flat edge table of edge removal's failures, against std::unordered_map under random
// puts, overwrites and erases: many keys of one home run (their probe runs wrap round the
// array's end, where the erase moves entries back) and keys as edge removal packs them.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <unordered_map>

#include "tet/edge_table.hpp"

namespace bisect::tet {
namespace {

std::uint64_t edge(std::uint32_t a, std::uint32_t b) { return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b); }

void expect_same(EdgeTable<int>& t, const std::unordered_map<std::uint64_t, int>& ref, const std::vector<std::uint64_t>& keys) {
  ASSERT_EQ(t.size(), ref.size());
  for (std::uint64_t k : keys) {
    const auto it = ref.find(k);
    const int* got = t.find(k);
    if (it == ref.end()) {
      EXPECT_EQ(got, nullptr) << k;
    } else {
      ASSERT_NE(got, nullptr) << k;
      EXPECT_EQ(*got, it->second) << k;
    }
  }
}

TEST(EdgeTable, AgreesWithAMapUnderPutsOverwritesAndErases) {
  std::mt19937 rng(11);
  // few nodes: many edges collide and the runs are long; the table grows through several sizes
  std::vector<std::uint64_t> keys;
  for (std::uint32_t a = 0; a < 120; ++a)
    for (std::uint32_t b = a + 1; b < 120; b += 1 + a % 3) keys.push_back(edge(a, b));
  EdgeTable<int> t;
  std::unordered_map<std::uint64_t, int> ref;
  std::uniform_int_distribution<std::size_t> pick(0, keys.size() - 1);
  for (int step = 0; step < 60000; ++step) {
    const std::uint64_t k = keys[pick(rng)];
    if (rng() % 3 == 0) {
      t.erase(k);
      ref.erase(k);
    } else {
      t.put(k, step);
      ref[k] = step;
    }
    if (step % 5000 == 0) expect_same(t, ref, keys);
  }
  expect_same(t, ref, keys);
  EXPECT_GT(ref.size(), 1000u);
  // emptied one by one, then cleared and used again
  for (std::uint64_t k : keys) t.erase(k), ref.erase(k);
  expect_same(t, ref, keys);
  t.put(edge(3, 9), 7);
  t.clear();
  EXPECT_EQ(t.find(edge(3, 9)), nullptr);
  t.put(edge(3, 9), 8);
  ASSERT_NE(t.find(edge(3, 9)), nullptr);
  EXPECT_EQ(*t.find(edge(3, 9)), 8);
}

TEST(EdgeTable, ErasesWithinRunsThatWrapRoundTheEnd) {
  // keys chosen to share the last home slots of the first array (1024 slots): their run wraps
  EdgeTable<int> t;
  t.put(edge(0, 1), 0);  // the array exists
  std::vector<std::uint64_t> wrap;
  for (std::uint64_t k = 1; wrap.size() < 40; ++k) {
    const std::size_t home = static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> 32) & 1023;
    if (home >= 1015) wrap.push_back(k);
  }
  std::unordered_map<std::uint64_t, int> ref{{edge(0, 1), 0}};
  for (std::size_t i = 0; i < wrap.size(); ++i) t.put(wrap[i], static_cast<int>(i)), ref[wrap[i]] = static_cast<int>(i);
  std::vector<std::uint64_t> all = wrap;
  all.push_back(edge(0, 1));
  expect_same(t, ref, all);
  for (std::size_t i = 0; i < wrap.size(); i += 3) t.erase(wrap[i]), ref.erase(wrap[i]);
  expect_same(t, ref, all);
  t.erase(12345678);  // absent: nothing changes
  expect_same(t, ref, all);
}

}  // namespace
}  // namespace bisect::tet
