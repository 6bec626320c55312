#include "engines/max_flow.hpp"

#include <algorithm>
#include <limits>

namespace hodt {

void MaxFlow::add_terminal(uint32_t v, int64_t from_source, int64_t to_sink) {
  // Flow through s -> v -> t needs no search.
  const int64_t through = std::min(from_source, to_sink);
  flow_ += through;
  tr_[v] += from_source - to_sink;
}

// Grows p's tree by one layer of free neighbours; true, with the arc from the
// source tree to the sink tree, when it meets the other tree.
bool MaxFlow::grow(uint32_t p, uint32_t& bridge) {
  const bool sink = sink_[p];
  for (uint32_t k = first_[p]; k < first_[p + 1]; ++k) {
    const uint32_t a = list_[k], q = head_[a];
    if (residual_[sink ? a ^ 1 : a] == 0) continue;  // p -> q in the source tree, q -> p in the sink tree
    if (parent_[q] == kNone) {
      parent_[q] = a ^ 1, sink_[q] = sink, stamp_[q] = stamp_[p], dist_[q] = dist_[p] + 1;
      activate(q);
    } else if (sink_[q] != sink) {
      bridge = sink ? a ^ 1 : a;
      return true;
    } else if (stamp_[q] <= stamp_[p] && dist_[q] > dist_[p]) {
      // A shorter path to the terminal through p (Boykov and Kolmogorov's heuristic).
      parent_[q] = a ^ 1, stamp_[q] = stamp_[p], dist_[q] = dist_[p] + 1;
    }
  }
  return false;
}

void MaxFlow::augment(uint32_t bridge) {
  int64_t push = residual_[bridge];
  const uint32_t tail = head_[bridge ^ 1], tip = head_[bridge];
  uint32_t i = tail;
  for (; parent_[i] != kTerminal; i = head_[parent_[i]]) push = std::min(push, residual_[parent_[i] ^ 1]);
  push = std::min(push, tr_[i]);
  for (i = tip; parent_[i] != kTerminal; i = head_[parent_[i]]) push = std::min(push, residual_[parent_[i]]);
  push = std::min(push, -tr_[i]);
  residual_[bridge] -= push, residual_[bridge ^ 1] += push;
  for (i = tail; parent_[i] != kTerminal;) {
    const uint32_t a = parent_[i];  // i -> its parent; the flow runs parent -> i
    residual_[a] += push, residual_[a ^ 1] -= push;
    const uint32_t up = head_[a];
    if (residual_[a ^ 1] == 0) make_orphan(i);
    i = up;
  }
  if ((tr_[i] -= push) == 0) make_orphan(i);
  for (i = tip; parent_[i] != kTerminal;) {
    const uint32_t a = parent_[i];  // the flow runs i -> its parent
    residual_[a ^ 1] += push, residual_[a] -= push;
    const uint32_t up = head_[a];
    if (residual_[a] == 0) make_orphan(i);
    i = up;
  }
  if ((tr_[i] += push) == 0) make_orphan(i);
  flow_ += push;
}

uint32_t MaxFlow::origin_distance(uint32_t j) {
  uint32_t d = 0;
  for (;;) {
    if (stamp_[j] == time_) return d + dist_[j];
    const uint32_t a = parent_[j];
    ++d;
    if (a == kTerminal) {
      stamp_[j] = time_, dist_[j] = 1;
      return d;
    }
    if (a == kOrphan) return kInfinite;
    j = head_[a];
  }
}

// A new parent for orphan i in its own tree, one whose path reaches the terminal
// (the nearest); else i becomes free, its children orphans, and the tree nodes
// that could reach it active again.
void MaxFlow::adopt(uint32_t i) {
  const bool sink = sink_[i];
  uint32_t best = kNone, best_d = kInfinite;
  for (uint32_t k = first_[i]; k < first_[i + 1]; ++k) {
    const uint32_t a = list_[k], j = head_[a];
    if (residual_[sink ? a : a ^ 1] == 0 || sink_[j] != sink || parent_[j] == kNone) continue;
    const uint32_t d = origin_distance(j);
    if (d == kInfinite) continue;
    if (d < best_d) best = a, best_d = d;
    // Remember the distances along the path just checked.
    uint32_t dd = d;
    for (uint32_t x = j; stamp_[x] != time_; x = head_[parent_[x]]) stamp_[x] = time_, dist_[x] = dd--;
  }
  if (best != kNone) {
    parent_[i] = best, stamp_[i] = time_, dist_[i] = best_d + 1;
    return;
  }
  for (uint32_t k = first_[i]; k < first_[i + 1]; ++k) {
    const uint32_t a = list_[k], j = head_[a];
    if (sink_[j] != sink || parent_[j] == kNone) continue;
    if (residual_[sink ? a : a ^ 1] > 0) activate(j);
    const uint32_t pa = parent_[j];
    if (pa != kTerminal && pa != kOrphan && head_[pa] == i) make_orphan(j);
  }
  parent_[i] = kNone;
}

int64_t MaxFlow::solve(const Progress& progress) {
  const size_t m = edges_.size();
  first_.assign(n_ + 1, 0);
  for (const Edge& e : edges_) ++first_[e.u + 1], ++first_[e.v + 1];
  for (uint32_t v = 0; v < n_; ++v) first_[v + 1] += first_[v];
  std::vector<uint32_t> fill(first_.begin(), first_.end() - 1);
  list_.resize(2 * m), head_.resize(2 * m), residual_.resize(2 * m);
  for (size_t k = 0; k < m; ++k) {
    const Edge& e = edges_[k];
    const uint32_t a = static_cast<uint32_t>(2 * k);
    head_[a] = e.v, residual_[a] = e.cap, head_[a + 1] = e.u, residual_[a + 1] = 0;
    list_[fill[e.u]++] = a, list_[fill[e.v]++] = a + 1;
  }
  std::vector<Edge>().swap(edges_);
  tr0_ = tr_;
  parent_.assign(n_, kNone), sink_.assign(n_, 0), queued_.assign(n_, 0);
  stamp_.assign(n_, 0), dist_.assign(n_, 0);
  for (uint32_t v = 0; v < n_; ++v)
    if (tr_[v] != 0) parent_[v] = kTerminal, sink_[v] = tr_[v] < 0, dist_[v] = 1, activate(v);

  WorkCounter work;
  uint32_t current = kNone;  // the active node being grown: kept while it finds paths
  for (;;) {
    if (work.tick(static_cast<double>(orphans_.size() - orphan_head_ + 1))) report(progress, 0, 1);
    uint32_t p = current;
    if (p == kNone || parent_[p] == kNone) {
      p = kNone;
      while (active_head_ < active_.size()) {
        const uint32_t q = active_[active_head_++];
        queued_[q] = 0;
        if (parent_[q] != kNone) {
          p = q;
          break;
        }
      }
      if (active_head_ == active_.size()) active_.clear(), active_head_ = 0;
      if (p == kNone) break;
    }
    uint32_t bridge;
    if (!grow(p, bridge)) {
      current = kNone;
      continue;
    }
    current = p;
    ++time_;
    augment(bridge);
    while (orphan_head_ < orphans_.size()) adopt(orphans_[orphan_head_++]);
    orphans_.clear(), orphan_head_ = 0;
  }
  return flow_;
}

}  // namespace hodt
