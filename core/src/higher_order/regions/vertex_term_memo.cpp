#include "higher_order/regions/vertex_term_memo.hpp"

#include <algorithm>
#include <cstring>

namespace hodt {

uint64_t VertexTermMemo::hash(uint32_t v, const uint32_t* neighbors, size_t degree) {
  uint64_t h = 0x9e3779b97f4a7c15ull ^ v;
  for (const uint32_t* w = neighbors; w != neighbors + degree; ++w) h = (h ^ *w) * 0xff51afd7ed558ccdull, h ^= h >> 29;
  return h ^ (h >> 32);
}

bool VertexTermMemo::find(uint32_t v, const std::vector<uint32_t>& neighbors, uint64_t h, double& value) const {
  if (slots_.empty()) return false;
  const size_t mask = slots_.size() - 1;
  const uint64_t tag = h >> 32 << 32;
  for (size_t i = h & mask; slots_[i]; i = (i + 1) & mask) {
    if ((slots_[i] >> 32 << 32) != tag) continue;
    const uint32_t* r = records_.data() + (slots_[i] & 0xffffffffu) - 1;
    if (r[0] == v && r[1] == neighbors.size() && std::equal(neighbors.begin(), neighbors.end(), r + 4)) {
      std::memcpy(&value, r + 2, sizeof value);
      return true;
    }
  }
  return false;
}

void VertexTermMemo::insert(uint32_t v, const std::vector<uint32_t>& neighbors, uint64_t h, double value) {
  if (stars_ >= max_stars_ || records_.size() + 4 + neighbors.size() >= UINT32_MAX) return;
  if (2 * (stars_ + 1) > slots_.size()) {  // (at most half full)
    std::vector<uint64_t> slots(std::max<size_t>(1024, 2 * slots_.size()), 0);
    const size_t mask = slots.size() - 1;
    for (size_t at = 0; at < records_.size(); at += 4 + records_[at + 1]) {
      const uint32_t* r = records_.data() + at;
      const uint64_t g = hash(r[0], r + 4, r[1]);
      size_t i = g & mask;
      while (slots[i]) i = (i + 1) & mask;
      slots[i] = (g >> 32 << 32) | (at + 1);
    }
    slots_.swap(slots);
  }
  const size_t mask = slots_.size() - 1;
  size_t i = h & mask;
  while (slots_[i]) i = (i + 1) & mask;
  slots_[i] = (h >> 32 << 32) | (records_.size() + 1);
  uint32_t word[2];
  std::memcpy(word, &value, sizeof value);
  records_.insert(records_.end(), {v, static_cast<uint32_t>(neighbors.size()), word[0], word[1]});
  records_.insert(records_.end(), neighbors.begin(), neighbors.end());
  ++stars_;
}

}  // namespace hodt
