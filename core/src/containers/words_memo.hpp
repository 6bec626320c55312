// A memo from word sequences to word sequences (an answer computed once per
// key): keys and answers live in one arena and the table holds offsets into it,
// so an entry costs no allocation of its own. Lookups on many small keys (a
// vertex and its neighbours) were slower through a map of vectors than the
// computation they saved.
#pragma once
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "containers/words_hash.hpp"

namespace hodt {

class WordsMemo {
 public:
  // The answer stored for key (empty span, found false: none).
  std::span<const uint32_t> find(std::span<const uint32_t> key, bool& found) const {
    found = false;
    if (slots_.empty()) return {};
    const size_t mask = slots_.size() - 1;
    for (size_t i = WordsHash{}(key) & mask;; i = (i + 1) & mask) {
      const uint32_t at = slots_[i];
      if (!at) return {};
      const uint32_t* e = arena_.data() + (at - 1);
      if (e[0] == key.size() && std::equal(key.begin(), key.end(), e + 1)) {
        found = true;
        return {e + 2 + e[0], e[1 + e[0]]};
      }
    }
  }
  // The words held: keys, answers and their sizes.
  size_t words() const { return arena_.size(); }
  // Stores value for key (not already stored).
  void insert(std::span<const uint32_t> key, std::span<const uint32_t> value) {
    if (2 * (used_ + 1) > slots_.size()) grow();
    const uint32_t at = static_cast<uint32_t>(arena_.size()) + 1;
    arena_.push_back(static_cast<uint32_t>(key.size()));
    arena_.insert(arena_.end(), key.begin(), key.end());
    arena_.push_back(static_cast<uint32_t>(value.size()));
    arena_.insert(arena_.end(), value.begin(), value.end());
    place(at);
    ++used_;
  }

 private:
  std::vector<uint32_t> arena_;  // per entry: key size, key, value size, value
  std::vector<uint32_t> slots_;  // open addressing, a power of two: arena offset + 1, 0 empty
  size_t used_ = 0;

  std::span<const uint32_t> key_at(uint32_t at) const { return {arena_.data() + at, arena_[at - 1]}; }
  void place(uint32_t at) {
    const size_t mask = slots_.size() - 1;
    size_t i = WordsHash{}(key_at(at)) & mask;
    while (slots_[i]) i = (i + 1) & mask;
    slots_[i] = at;
  }
  void grow() {
    std::vector<uint32_t> old(slots_.empty() ? 64 : 2 * slots_.size(), 0);
    old.swap(slots_);
    for (uint32_t at : old)
      if (at) place(at);
  }
};

}  // namespace hodt
