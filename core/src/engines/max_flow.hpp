// Maximum flow with integer capacities by Boykov and Kolmogorov's algorithm (two
// search trees, grown from the terminals and repaired rather than rebuilt after
// each augmentation): fast on the grid-like graphs of the roof dual, where
// shortest-path methods need a phase per few hundred augmentations. Arcs are kept
// in pairs (arc ^ 1 is the reverse), adjacency in compressed rows; everything is
// iterative (wasm's stack is small).
#pragma once
#include <cstdint>
#include <vector>

#include "hodt/progress.hpp"

namespace hodt {

class MaxFlow {
 public:
  explicit MaxFlow(uint32_t num_nodes) : n_(num_nodes), tr_(num_nodes, 0) {}
  // Capacities from the source to v and from v to the sink (the terminals are
  // not nodes), before solve().
  void add_terminal(uint32_t v, int64_t from_source, int64_t to_sink);
  // An edge u -> v of capacity cap >= 0 (its reverse has none), before solve();
  // edges are numbered from 0 in the order added.
  uint32_t add_edge(uint32_t u, uint32_t v, int64_t cap) {
    edges_.push_back({u, v, cap});
    return static_cast<uint32_t>(edges_.size() - 1);
  }
  int64_t solve(const Progress& progress = {});
  // After solve(): the flow on an edge, and the net flow from the source into a
  // node through its terminal arcs (negative: from the node into the sink).
  int64_t edge_flow(uint32_t e) const { return residual_[2 * size_t(e) + 1]; }
  int64_t terminal_flow(uint32_t v) const { return tr0_[v] - tr_[v]; }

 private:
  struct Edge { uint32_t u, v; int64_t cap; };
  bool grow(uint32_t p, uint32_t& bridge);
  void augment(uint32_t bridge);
  void adopt(uint32_t i);
  void make_orphan(uint32_t i) { parent_[i] = kOrphan, orphans_.push_back(i); }
  void activate(uint32_t i) {
    if (!queued_[i]) queued_[i] = 1, active_.push_back(i);
  }
  // The tree distance of i to its terminal, or kInfinite if i's path ends at an orphan.
  uint32_t origin_distance(uint32_t i);

  static constexpr uint32_t kNone = UINT32_MAX, kTerminal = UINT32_MAX - 1, kOrphan = UINT32_MAX - 2,
                            kInfinite = UINT32_MAX;
  uint32_t n_;
  std::vector<Edge> edges_;
  std::vector<int64_t> tr_, tr0_;  // per node: residual source capacity minus sink capacity
  std::vector<uint32_t> first_, list_, head_;  // arcs of v: list_[first_[v] .. first_[v + 1])
  std::vector<int64_t> residual_;
  std::vector<uint32_t> parent_;   // arc to the parent, kTerminal, kOrphan or kNone (free)
  std::vector<uint8_t> sink_, queued_;
  std::vector<uint32_t> stamp_, dist_;  // memo of origin checks: valid when stamp_ == time_
  uint32_t time_ = 0;
  std::vector<uint32_t> active_, orphans_;
  size_t active_head_ = 0, orphan_head_ = 0;
  int64_t flow_ = 0;
};

}  // namespace hodt
