// A small memo of a per-triangle value (area, normal) for the min-max models:
// they evaluate every pair of nearby triangles, so each triangle comes up in many
// pairs, in a spatially coherent order, and its accurate area or normal
// (accurate_det.hpp) is worth computing once. Direct-mapped: a slot holds the
// last triangle that hashed to it. Values are exactly those of `compute` (which
// must not depend on the rotation of the triangle's corners): only time changes.
#pragma once
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "hodt/skeleton.hpp"

namespace hodt {

template <class Value, class Compute>
class TriangleMemo {
 public:
  // triangles: about how many distinct triangles will come (a small mesh gets a
  // small table).
  TriangleMemo(Compute compute, size_t triangles) : compute_(compute) {
    while (bits_ < kMaxBits && (size_t(1) << bits_) < triangles) ++bits_;
    slots_.resize(size_t(1) << bits_);
  }

  Value operator()(const Tri& t) {
    // The rotation that starts at the smallest index: one key per triangle.
    const int r = t[1] < t[0] ? (t[2] < t[1] ? 2 : 1) : (t[2] < t[0] ? 2 : 0);
    const Tri key = {t[r], t[(r + 1) % 3], t[(r + 2) % 3]};
    Slot& s = slots_[(key[0] * 0x9E3779B1u ^ key[1] * 0x85EBCA77u ^ key[2] * 0xC2B2AE3Du) >> (32 - bits_)];
    if (s.key[0] != key[0] || s.key[1] != key[1] || s.key[2] != key[2]) s.key = key, s.value = compute_(key);
    return s.value;  // by value: the next call may reuse the slot
  }

 private:
  static constexpr int kMaxBits = 12;  // 4096 slots: more would leave the L1/L2 caches
  struct Slot {
    Tri key = {UINT32_MAX, UINT32_MAX, UINT32_MAX};
    Value value{};
  };
  Compute compute_;
  int bits_ = 4;
  std::vector<Slot> slots_;
};
template <class Compute>
TriangleMemo(Compute, size_t) -> TriangleMemo<std::invoke_result_t<Compute&, const Tri&>, Compute>;

}  // namespace hodt
