// A map from 64-bit keys to 32-bit indices in one array (open addressing,
// linear probing): the builders' hot lookups (a quad pair's kept term) were
// dominated by the node chasing and allocation of std::unordered_map.
#pragma once
#include <cstdint>
#include <vector>

namespace hodt {

class FlatIndex {
 public:
  static constexpr uint32_t kNone = UINT32_MAX;

  void reserve(size_t n) {
    size_t want = 64;
    while (want < 2 * n) want *= 2;
    if (want > slots_.size()) rehash(want);
  }
  uint32_t find(uint64_t key) const {
    if (slots_.empty()) return kNone;
    for (size_t i = slot_of(key);; i = (i + 1) & (slots_.size() - 1)) {
      if (slots_[i].value == kNone) return kNone;
      if (slots_[i].key == key) return slots_[i].value;
    }
  }
  // Stores value for key (not already stored; value != kNone).
  void insert(uint64_t key, uint32_t value) {
    if (2 * (size_ + 1) > slots_.size()) rehash(slots_.empty() ? 64 : 2 * slots_.size());
    place(key, value);
    ++size_;
  }
  // Stores value for key, in place of the one stored if any (value != kNone).
  void assign(uint64_t key, uint32_t value) {
    if (!slots_.empty())
      for (size_t i = slot_of(key); slots_[i].value != kNone; i = (i + 1) & (slots_.size() - 1))
        if (slots_[i].key == key) {
          slots_[i].value = value;
          return;
        }
    insert(key, value);
  }
  void clear() {
    slots_ = {};
    size_ = 0;
  }

 private:
  struct Slot {
    uint64_t key = 0;
    uint32_t value = kNone;  // kNone: empty
  };
  std::vector<Slot> slots_;  // a power of two, at most half full
  size_t size_ = 0;

  size_t slot_of(uint64_t key) const {
    key *= 0x9E3779B97F4A7C15ull;  // (Fibonacci hashing: the high bits are the mixed ones)
    return static_cast<size_t>(key >> 32) & (slots_.size() - 1);
  }
  void place(uint64_t key, uint32_t value) {
    size_t i = slot_of(key);
    while (slots_[i].value != kNone) i = (i + 1) & (slots_.size() - 1);
    slots_[i] = {key, value};
  }
  void rehash(size_t n) {
    std::vector<Slot> old(n);
    old.swap(slots_);
    for (const Slot& s : old)
      if (s.value != kNone) place(s.key, s.value);
  }
};

}  // namespace hodt
