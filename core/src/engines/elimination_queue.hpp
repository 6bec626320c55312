// The one greedy elimination planner of the engines. Variable elimination's cost
// is set by its order; both elimination engines (the factor graph over binary
// variables, the state graph over classes of states) build that order greedily:
// eliminate the variable whose criterion is least, recompute the criterion of
// the variables the step touched, repeat. The criteria differ (the factor graph:
// fewest neighbours, or fewest fill-in edges; the state graph: the smallest
// table), the loop does not, and this queue is the loop.
//
// The queue is a binary heap with lazy deletion: offering a variable again
// pushes a new entry instead of updating the old one, and an entry older than
// its variable's latest offer is skipped when it reaches the top. The heap's
// top is therefore always the least current (criterion, index) of the live
// variables, ties going to the lower index, so every plan is deterministic.
#pragma once
#include <cstdint>
#include <queue>
#include <utility>
#include <vector>

namespace hodt {

template <class Criterion>
class EliminationQueue {
 public:
  explicit EliminationQueue(uint32_t n) : offers_(n, 0), eliminated_(n, 0) {}

  // v's criterion is now c (v not yet eliminated: an eliminated variable's
  // offer is ignored).
  void offer(uint32_t v, Criterion c) {
    if (!eliminated_[v]) heap_.push({std::move(c), v, ++offers_[v]});
  }

  // The live variable of least criterion (ties: lowest index), now marked
  // eliminated; UINT32_MAX once every offered variable is.
  uint32_t next() {
    while (!heap_.empty()) {
      const Entry e = heap_.top();
      heap_.pop();
      if (eliminated_[e.v] || e.offer != offers_[e.v]) continue;  // superseded
      eliminated_[e.v] = 1;
      return e.v;
    }
    return UINT32_MAX;
  }

  bool eliminated(uint32_t v) const { return eliminated_[v] != 0; }

 private:
  struct Entry {
    Criterion c;
    uint32_t v, offer;
    // The heap's order: criterion, then index (the offer count only tells a
    // current entry from a superseded one).
    bool operator>(const Entry& o) const { return o.c < c || (!(c < o.c) && v > o.v); }
  };
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap_;
  std::vector<uint32_t> offers_;
  std::vector<uint8_t> eliminated_;
};

}  // namespace hodt
