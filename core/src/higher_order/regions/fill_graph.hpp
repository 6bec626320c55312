// Every k-OD triangulation of a region as a path in one graph: the fill DP
// (fill_dp.hpp) without signatures, its merged partial fills the nodes and its
// steps (one triangle each) the arcs. An arc carries the terms the region alone
// decides that complete at that step, and the signature entries (what the
// regions beside see: a fan at a shared vertex, an apex on a shared edge) that
// complete there. Every complete fill takes each item's entry exactly once.
//
// A region far too large to list by signature often has a small such graph
// (it forgets what the neighbours see): with a cost per (item, entry), the best
// fill and every entry's min-marginal are one pass each way. That makes the
// region one factor of a Lagrangian dual (dual_bound.hpp) over its entries.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "higher_order/fills/fill_enumerator.hpp"
#include "higher_order/regions/region_terms.hpp"

namespace hodt {

struct FillGraph {
  struct Arc {
    uint32_t parent, child;  // nodes; arcs are sorted by parent
    double cost;             // the region's own terms completing here, combined (summed, or their max)
    Tri triangle;            // placed here
    uint32_t first_take, takes;  // its (item, entry) pairs in `taken`
  };
  uint32_t region = 0;
  uint32_t nodes = 0;                           // node 0: the empty fill
  std::vector<Arc> arcs;                        // every one on a path to a complete fill
  std::vector<std::pair<uint32_t, uint32_t>> taken;  // (item, entry)
  std::vector<uint32_t> complete;               // the complete fills' nodes
  std::vector<Tri> items;                       // sorted
  std::vector<std::vector<SignatureEntry>> entries;  // per item, those some complete fill takes

  // With costs[item][entry] added where an arc takes it: the least total of a
  // complete fill (own terms plus costs). marginals (when not null): per item
  // and entry, the least total of a fill that takes it. best (when not null):
  // the triangles of a least fill (canonical, sorted); best_entries (when not
  // null): per item, the entry that fill takes.
  double least(const std::vector<std::vector<double>>& costs, std::vector<std::vector<double>>* marginals = nullptr,
               std::vector<Tri>* best = nullptr, std::vector<uint32_t>* best_entries = nullptr) const;
  // Per arc, the least total of a complete fill through it; nothing if a
  // partial total reaches 2^31 (below that, sums of grid values are exact).
  std::optional<std::vector<double>> through(const std::vector<std::vector<double>>& costs) const;
  // The complete fills that use only the arcs kept (canonical, sorted), or
  // nothing if there are more than max_fills.
  std::optional<std::vector<std::vector<Tri>>> fills(const std::vector<uint8_t>& kept, uint64_t max_fills) const;
  // Per combination of entries (one per item) that a complete fill over kept
  // arcs takes, the least such fill (least own terms: arc costs are read as a
  // minimised sum), canonical and sorted: the fills the regions beside can
  // tell apart, each at its best (far fewer than the fills, as a region's
  // listing by signature is). Nothing if more than max_labels partial
  // combinations or more than max_fills fills.
  std::optional<std::vector<std::vector<Tri>>> best_by_entries(const std::vector<uint8_t>& kept, uint64_t max_fills,
                                                               uint64_t max_labels) const;
  // Per item and entry, a complete fill that takes it (canonical, sorted).
  std::vector<std::vector<std::vector<Tri>>> representatives() const;
};

// Region r's fill graph, or nothing when more than max_states partial fills
// would be kept (*states_used adds them either way).
std::optional<FillGraph> fill_graph(const Mesh& delaunay, const Candidates& candidates, const RegionTerms& terms,
                                    uint32_t region, uint64_t max_states, const Progress& progress = {},
                                    uint64_t* states_used = nullptr);

}  // namespace hodt
