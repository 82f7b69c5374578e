#include "fusion/flat_hash_map.h"

#include <gtest/gtest.h>

#include <random>
#include <unordered_map>

namespace slamkit {
namespace {

struct Sum {
  uint64_t total = 0;
  int count = 0;
};

// Keys drawn from a small range, so that most repeat, plus voxel-like runs of adjacent keys.
std::vector<uint64_t> test_keys(size_t count, uint64_t range, uint32_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<uint64_t> pick(0, range - 1);
  std::vector<uint64_t> keys;
  while (keys.size() < count) {
    const uint64_t key = pick(rng);
    for (uint64_t k = key; k < key + 4 && keys.size() < count; ++k) keys.push_back(k << 21);
  }
  return keys;
}

TEST(FlatHashMap, AgreesWithUnorderedMapThroughGrowth) {
  // About 13, 1000 and 95000 distinct keys: none, a few and many doublings of the index.
  for (const uint64_t range : {uint64_t(10), uint64_t(1000), uint64_t(100000)}) {
    FlatHashMap<Sum> map;
    std::unordered_map<uint64_t, Sum> reference;
    const std::vector<uint64_t> keys = test_keys(300000, range, uint32_t(range));
    for (size_t i = 0; i < keys.size(); ++i) {
      Sum& s = map[keys[i]];
      s.total += i;
      ++s.count;
      Sum& r = reference[keys[i]];
      r.total += i;
      ++r.count;
    }
    ASSERT_EQ(map.size(), reference.size()) << range;
    for (const auto& [key, r] : reference) {
      const Sum* s = map.find(key);
      ASSERT_NE(s, nullptr) << key;
      EXPECT_EQ(s->total, r.total) << key;
      EXPECT_EQ(s->count, r.count) << key;
    }
    size_t visited = 0;
    map.for_each([&](uint64_t key, const Sum& s) {
      ++visited;
      EXPECT_EQ(s.total, reference.at(key).total) << key;
    });
    EXPECT_EQ(visited, reference.size());
  }
}

TEST(FlatHashMap, FindsNothingOfAbsentKeys) {
  FlatHashMap<int> map;
  EXPECT_EQ(map.find(5), nullptr);  // empty
  for (uint64_t k = 0; k < 5000; k += 2) map[k] = int(k);
  for (uint64_t k = 1; k < 5000; k += 2) EXPECT_EQ(map.find(k), nullptr) << k;
  EXPECT_EQ(map.find(~uint64_t(0)), nullptr);
  ASSERT_NE(map.find(4000), nullptr);
  EXPECT_EQ(*map.find(4000), 4000);
}

TEST(FlatHashMap, ValuesStayInPlaceAndInInsertionOrder) {
  FlatHashMap<int> map;
  int& first = map[77];
  first = 1;
  std::vector<uint64_t> inserted = {77};
  std::mt19937_64 rng(3);
  while (map.size() < 100000) {  // the index grows 11 times, the values never move
    const uint64_t key = rng();
    if (map.find(key)) continue;
    map[key] = 0;
    inserted.push_back(key);
  }
  EXPECT_EQ(&first, map.find(77));
  EXPECT_EQ(map[77], 1);
  std::vector<uint64_t> order;
  map.for_each([&](uint64_t key, int) { order.push_back(key); });
  EXPECT_EQ(order, inserted);
}

TEST(FlatHashMap, KeysSharingTheirLowBitsAreKeptApart) {
  // Keys that differ only above bit 40: a table indexed by the key's low bits would put them
  // all in one slot.
  FlatHashMap<uint64_t> map;
  for (uint64_t i = 0; i < 4096; ++i) map[i << 40] = i;
  ASSERT_EQ(map.size(), 4096u);
  for (uint64_t i = 0; i < 4096; ++i) EXPECT_EQ(*map.find(i << 40), i);
}

}  // namespace
}  // namespace slamkit
