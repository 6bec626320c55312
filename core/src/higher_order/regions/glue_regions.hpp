// Regions glued in pairs: a coarser cut of the same k-OD triangulations.
//
// A union of neighbouring regions is triangulated exactly as the regions are,
// one by one: the fixed edges between them are in every triangulation of the
// union too. Gluing changes nothing of what is feasible, only what a relaxation
// that reads each region whole (region_dual.hpp) can see: the terms on the
// glued edges and vertices become the union's own, and the cycles of coupled
// terms between the two (strips side by side share whole boundaries) are
// inside one region.
#pragma once
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>
#include "higher_order/regions/regions.hpp"

namespace hodt {

// Neighbouring regions a and b that `may_glue(a, b)` are paired, greedily the
// pairs sharing the most fixed edges first (ties by index), each region in one
// pair at most. The edges between a pair are no longer fixed; a pair becomes one
// region holding only its Delaunay fill, incomplete. Other regions stay as they
// are. pairs: the pairs glued (their indices in `regions`).
Regions glue_pairs(const Mesh& delaunay, const Regions& regions, const std::function<bool(uint32_t, uint32_t)>& may_glue,
                   std::vector<std::pair<uint32_t, uint32_t>>* pairs = nullptr);

}  // namespace hodt
