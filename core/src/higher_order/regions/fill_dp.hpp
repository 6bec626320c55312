// The best k-OD triangulation of a region for each signature (region_terms.hpp),
// by dynamic programming over partial fills instead of listing them all.
//
// A fill grows triangle by triangle from its frontier: the directed edges with
// the uncovered part on their left (at first the region's boundary). Which
// triangles can still be placed depends on the frontier alone, and what the
// terms will still read of the covered part is little: the neighbours (or fan)
// of each vertex on the frontier, the apex behind each frontier edge, and the
// signature entries of the shared vertices and edges already complete. Partial
// fills that agree on these are interchangeable for every completion, so each
// layer (fills of t triangles) keeps only the best of each; every vertex and edge
// adds its term the moment it completes. A region of millions of triangulations
// usually has a few thousand such states.
#pragma once
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "higher_order/fills/fill_enumerator.hpp"
#include "higher_order/regions/region_terms.hpp"

namespace hodt {

struct BestFill {
  std::vector<Tri> triangles;  // counterclockwise, canonical, sorted
  double value;                // the terms region r alone decides
};

// One best fill per signature, or nothing when more than max_states partial
// fills would be kept in all (*states_used counts them either way).
// keep_items (sorted RegionTerms items): signatures keep only the entries about
// these, the others' terms count as 0 (region_views.hpp); all when null.
// *swept (when given): the share of the region's triangles that the kept
// partial fills had placed when the budget ran out (1 when it did not).
std::optional<std::vector<BestFill>> best_fills(const Mesh& delaunay, const Candidates& candidates,
                                                const RegionTerms& terms, uint32_t region, uint64_t max_states,
                                                const Progress& progress = {}, uint64_t* states_used = nullptr,
                                                const std::vector<Tri>* keep_items = nullptr, double* swept = nullptr);

}  // namespace hodt
