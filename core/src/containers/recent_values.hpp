// Values of a pure function of a few doubles, remembered for the keys seen last
// (a direct-mapped table): where a computation recurs with the same inputs, as
// a grid's shapes or a star's triangles do. A value depends on its key alone,
// so an entry is never stale and every value is the same, bit for bit.
#pragma once
#include <array>
#include <cstdint>
#include <cstring>

namespace hodt {

template <size_t N, class Value, size_t Slots = 256>
class RecentValues {
 public:
  template <class Compute>
  const Value& get(const std::array<double, N>& key, Compute compute) {
    uint64_t h = 0x9E3779B97F4A7C15ull;
    for (double k : key) {
      uint64_t bits;  // (std::bit_cast: not in Emscripten's libc++)
      std::memcpy(&bits, &k, sizeof bits);
      h = (h ^ bits) * 0xFF51AFD7ED558CCDull;
    }
    Slot& slot = slots_[(h >> 40) % Slots];
    if (!slot.used || std::memcmp(slot.key.data(), key.data(), sizeof key) != 0)
      slot.key = key, slot.value = compute(), slot.used = true;
    return slot.value;
  }

 private:
  struct Slot {
    std::array<double, N> key;
    Value value;
    bool used = false;
  };
  std::array<Slot, Slots> slots_;
};

}  // namespace hodt
