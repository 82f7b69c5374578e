#pragma once
// A hash map from 64-bit keys to values: the entries in insertion order, in blocks of 16384 that
// never move, and an open-addressing index over them (linear probing, power-of-two capacity).
// Hand-written: std::unordered_map allocates a node per key and divides by a prime on every
// look-up, and no library of the stack (Eigen, OpenCV, Ceres, PCL, OpenMP) offers a flat table.
//
// A key costs its entry and 1.4-2.9 slots of 8 bytes (the index is 35-70 % full), about what
// std::unordered_map's node and bucket cost; entries stored in the slots themselves would cost
// 1.4-2.9 entries. Holds up to 2^32 - 1 keys (a slot numbers its entry in 32 bits).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace slamkit {

template <typename Value>
class FlatHashMap {
 public:
  FlatHashMap() : slots_(kFirstCapacity, kEmpty) {}

  // The value of `key`, inserted as Value{} if absent. References to values stay valid until
  // the map is destroyed.
  Value& operator[](uint64_t key) {
    const uint64_t hash = mix(key);
    size_t slot = find_slot(key, hash);
    if (slots_[slot] != kEmpty) return entry(index_in(slots_[slot])).value;
    if ((size_ + 1) * 10 > slots_.size() * kMaxLoadTenths) {
      grow();
      slot = find_slot(key, hash);
    }
    if (size_ % kBlockSize == 0) blocks_.emplace_back(new Entry[kBlockSize]);
    Entry& e = entry(size_);
    e.key = key;
    slots_[slot] = tag_of(hash) | (size_ + 1);
    ++size_;
    return e.value;
  }

  // Null when absent.
  const Value* find(uint64_t key) const {
    const size_t slot = find_slot(key, mix(key));
    return slots_[slot] == kEmpty ? nullptr : &entry(index_in(slots_[slot])).value;
  }

  size_t size() const { return size_; }

  // Calls f(key, value) for every entry, in insertion order.
  template <typename F>
  void for_each(F&& f) const {
    for (size_t i = 0; i < size_; ++i) f(entry(i).key, entry(i).value);
  }

 private:
  struct Entry {
    uint64_t key = 0;
    Value value{};
  };
  static constexpr size_t kBlockSize = size_t(1) << 14;  // entries
  // The index doubles past 70 % full: linear probing's runs stay short below that.
  static constexpr size_t kMaxLoadTenths = 7;
  static constexpr size_t kFirstCapacity = 64;
  // A slot is 0 (empty) or the high 32 bits of its key's hash, then the entry's index + 1: most
  // probes of other keys are told apart by the hash bits without reading their entries.
  static constexpr uint64_t kEmpty = 0;
  static constexpr uint64_t kTagMask = ~uint64_t(0) << 32;

  // MurmurHash3's finaliser: voxel keys differ in few bits (neighbours by 1 or 2^21), and every
  // bit of the key must reach the low bits that pick the slot.
  static uint64_t mix(uint64_t k) {
    k ^= k >> 33;
    k *= 0xff51afd7ed558ccdull;
    k ^= k >> 33;
    k *= 0xc4ceb9fe1a85ec53ull;
    k ^= k >> 33;
    return k;
  }
  static uint64_t tag_of(uint64_t hash) { return hash & kTagMask; }
  static size_t index_in(uint64_t slot) { return size_t(slot & ~kTagMask) - 1; }

  Entry& entry(size_t i) { return blocks_[i / kBlockSize][i % kBlockSize]; }
  const Entry& entry(size_t i) const { return blocks_[i / kBlockSize][i % kBlockSize]; }

  // The slot holding `key`, or the empty slot where it belongs. The index is never full.
  size_t find_slot(uint64_t key, uint64_t hash) const {
    const size_t mask = slots_.size() - 1;
    for (size_t i = hash & mask;; i = (i + 1) & mask) {
      const uint64_t slot = slots_[i];
      if (slot == kEmpty || (tag_of(slot) == tag_of(hash) && entry(index_in(slot)).key == key))
        return i;
    }
  }

  void grow() {
    slots_.assign(2 * slots_.size(), kEmpty);
    const size_t mask = slots_.size() - 1;
    for (size_t i = 0; i < size_; ++i) {
      const uint64_t hash = mix(entry(i).key);
      size_t slot = hash & mask;
      while (slots_[slot] != kEmpty) slot = (slot + 1) & mask;
      slots_[slot] = tag_of(hash) | (i + 1);
    }
  }

  std::vector<std::unique_ptr<Entry[]>> blocks_;
  std::vector<uint64_t> slots_;
  size_t size_ = 0;
};

}  // namespace slamkit
