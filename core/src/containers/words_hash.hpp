// A hash for keys made of 32-bit words (vectors or arrays of vertex ids and
// the like), for the engines' memo and merge tables: FNV-1a over the words,
// then the high bits folded down (tables index by the low ones).
#pragma once
#include <cstddef>
#include <cstdint>

namespace hodt {

// The same hash fed word by word (a key held in pieces).
struct WordsHasher {
  uint64_t h = 1469598103934665603ull;
  void add(uint32_t x) { h = (h ^ x) * 1099511628211ull; }
  size_t done() const { return static_cast<size_t>(h ^ (h >> 29)); }
};

struct WordsHash {
  template <class Words>
  size_t operator()(const Words& k) const {
    WordsHasher h;
    for (uint32_t x : k) h.add(x);
    return h.done();
  }
};

}  // namespace hodt
