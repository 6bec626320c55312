#include "higher_order/fills/fill_search.hpp"

#include <algorithm>

#include "hodt/error.hpp"
#include "containers/flat_index.hpp"
#include "containers/words_memo.hpp"

namespace hodt {

namespace {

class FillSearch {
 public:
  FillSearch(const Mesh& dt, const Candidates& cand, const std::vector<std::pair<uint32_t, uint32_t>>& boundary,
             uint64_t max_nodes, FillPruning& pruning, const std::function<void(const std::vector<Tri>&)>& visit,
             const Progress& progress)
      : pruning_(pruning), visit_(visit), progress_(progress), budget_(max_nodes) {
    // (Each candidate is listed under each of its edges: the keys and the
    // boundary are every edge a fill can have.)
    for (const auto& entry : cand) index(static_cast<uint32_t>(entry.first >> 32), static_cast<uint32_t>(entry.first));
    for (const auto& [a, b] : boundary) index(a, b);
    for (const auto& [key, apexes] : cand) {
      const uint32_t a = static_cast<uint32_t>(key >> 32), b = static_cast<uint32_t>(key);
      edges_[id(a, b)].apexes[a < b ? 0 : 1] = &apexes;
    }
    for (uint32_t i = 0; i < edges_.size(); ++i)
      for (uint32_t j = i + 1; j < edges_.size(); ++j)
        if (segments_cross(dt, edges_[i].lo, edges_[i].hi, edges_[j].lo, edges_[j].hi))
          edges_[i].crossing.push_back(j), edges_[j].crossing.push_back(i);
    for (const auto& [a, b] : boundary) open(a, b);
    // A fill has fewer triangles than twice the points.
    words_ = (2 * dt.num_vertices() + 64) / 64;
    conflicts_.assign(words_ * (2 * dt.num_vertices() + 2), 0);
    // (Keys pack an edge's ends in one word.)
    memo_on_ = pruning.memo_words > 0 && dt.num_vertices() <= 0xFFFF;
  }

  bool run(uint64_t* nodes_used) {
    try {
      node();
    } catch (...) {
      if (nodes_used) *nodes_used += nodes_;
      throw;
    }
    if (nodes_used) *nodes_used += nodes_;
    return complete_;
  }

 private:
  struct Edge {
    uint32_t lo = 0, hi = 0;
    const std::vector<uint32_t>* apexes[2] = {nullptr, nullptr};  // of lo -> hi, of hi -> lo
    std::vector<uint32_t> crossing;
    uint32_t blocked = 0;  // placed edges that cross it or are it
    int32_t placed_by = -1, closed_by = -1;  // positions of the triangles that placed it and closed it
    uint8_t open = 0;  // 0, or 1 + the direction open (0: lo -> hi)
    uint32_t at = 0;   // while open, its place in open_
    uint64_t weight = 1;  // 1 + the dead ends met at it (nothing could cover it)
  };
  struct Option {
    uint32_t apex;
    uint8_t closes;  // bit s: side s closes an open edge
  };

  FillPruning& pruning_;
  const std::function<void(const std::vector<Tri>&)>& visit_;
  const Progress& progress_;
  uint64_t budget_, nodes_ = 0;
  bool complete_ = true;
  std::vector<Edge> edges_;
  FlatIndex ids_;
  std::vector<uint32_t> open_;  // the open edges' ids
  std::vector<Tri> tris_;
  // Per depth, the reason its branch failed: a bit per placed position.
  size_t words_ = 0;
  std::vector<uint64_t> conflicts_;
  WordsMemo memo_;
  bool memo_on_ = false;
  std::vector<uint64_t> sorted_;
  std::vector<uint32_t> positions_;

  static uint64_t undirected(uint32_t a, uint32_t b) { return a < b ? edge_key(a, b) : edge_key(b, a); }
  void index(uint32_t a, uint32_t b) {
    if (ids_.find(undirected(a, b)) != FlatIndex::kNone) return;
    ids_.insert(undirected(a, b), static_cast<uint32_t>(edges_.size()));
    Edge e;
    e.lo = std::min(a, b), e.hi = std::max(a, b);
    edges_.push_back(std::move(e));
  }
  uint32_t id(uint32_t a, uint32_t b) const { return ids_.find(undirected(a, b)); }
  static uint8_t direction(uint32_t a, uint32_t b) { return a < b ? 1 : 2; }
  bool is_open(uint32_t a, uint32_t b) const { return edges_[id(a, b)].open == direction(a, b); }
  const std::vector<uint32_t>* apexes(uint32_t a, uint32_t b) const { return edges_[id(a, b)].apexes[a < b ? 0 : 1]; }

  void open(uint32_t a, uint32_t b) {
    Edge& e = edges_[id(a, b)];
    e.open = direction(a, b), e.at = static_cast<uint32_t>(open_.size());
    open_.push_back(id(a, b));
  }
  void shut(uint32_t i) {
    Edge& e = edges_[i];
    e.open = 0;
    edges_[open_.back()].at = e.at;
    open_[e.at] = open_.back();
    open_.pop_back();
  }
  // A placed edge blocks itself and every edge it crosses (sign: +1 placed, -1 undone).
  void block(uint32_t i, int sign) {
    edges_[i].blocked += sign;
    for (uint32_t c : edges_[i].crossing) edges_[c].blocked += sign;
  }

  // Whether triangle u v w may cover the open edge u -> v: each of its other
  // sides either closes an open edge in the same direction (the region beyond
  // is this triangle) or opens its reverse, which must cross nothing placed.
  bool fits(uint32_t u, uint32_t v, uint32_t w, uint8_t& closes) const {
    const uint32_t side[2][2] = {{v, w}, {w, u}};
    closes = 0;
    for (int s = 0; s < 2; ++s) {
      const uint32_t a = side[s][0], b = side[s][1];
      const Edge& e = edges_[id(a, b)];
      if (e.open == direction(a, b)) {
        closes |= 1 << s;
        continue;
      }
      if (e.open || e.blocked) return false;  // its far side is covered already, or it meets a placed edge
    }
    return true;
  }

  // Adds to `out` why triangle u v w may not cover u -> v now: the placed
  // triangles it overlaps, or those the pruning names.
  void add_reasons(uint32_t u, uint32_t v, uint32_t w, uint64_t* out) {
    const uint32_t side[2][2] = {{v, w}, {w, u}};
    const uint32_t depth = static_cast<uint32_t>(tris_.size());
    for (int s = 0; s < 2; ++s) {
      const uint32_t a = side[s][0], b = side[s][1];
      const Edge& e = edges_[id(a, b)];
      if (e.open == direction(a, b)) continue;
      if (e.open) {  // the reverse is open: the triangle that placed it is on this side
        set(out, e.placed_by);
        return;
      }
      if (e.blocked) {  // a placed edge crosses it (its triangle overlaps this one), or it is placed
        set(out, e.placed_by), set(out, e.closed_by);
        for (uint32_t c : e.crossing) set(out, edges_[c].placed_by);
        return;
      }
    }
    positions_.clear();
    if (!pruning_.reasons(Tri{u, v, w}, positions_)) return prefix(out, depth);
    for (uint32_t p : positions_) set(out, static_cast<int32_t>(p));
  }

  uint64_t* slot(uint32_t depth) { return conflicts_.data() + words_ * depth; }
  void set(uint64_t* c, int32_t p) const {
    if (p >= 0) c[p / 64] |= uint64_t{1} << (p % 64);
  }
  static bool test(const uint64_t* c, uint32_t p) { return (c[p / 64] >> (p % 64)) & 1; }
  // The first n positions.
  void prefix(uint64_t* c, uint32_t n) const {
    std::fill(c, c + words_, 0);
    for (uint32_t w = 0; w < n / 64; ++w) c[w] = ~uint64_t{0};
    if (n % 64) c[n / 64] = (uint64_t{1} << (n % 64)) - 1;
  }

  // The open edge with the fewest triangles that fit and are accepted per unit
  // of its weight (ties: smallest key), and those triangles; false when some
  // edge has none (then `best` is that edge). An edge that was a dead end
  // before is likely one again, and choosing it early finds that at once.
  bool choose(uint64_t& best, std::vector<Option>& fewest) {
    std::vector<Option> here;
    bool first = true;
    uint64_t best_weight = 1;
    for (uint32_t i : open_) {
      const Edge& e = edges_[i];
      const uint32_t u = e.open == 1 ? e.lo : e.hi, v = e.open == 1 ? e.hi : e.lo;
      const uint64_t weight = e.weight;
      here.clear();
      if (const auto* o = e.apexes[e.open - 1])
        for (uint32_t w : *o) {
          if (!first && here.size() * best_weight > fewest.size() * weight) break;  // (then it is not chosen)
          uint8_t closes;
          if (fits(u, v, w, closes) && pruning_.accept(Tri{u, v, w})) here.push_back({w, closes});
        }
      const uint64_t key = edge_key(u, v);
      if (here.empty()) {
        fewest.clear(), best = key;
        return false;
      }
      const uint64_t a = here.size() * best_weight, b = fewest.size() * weight;
      if (first || a < b || (a == b && key < best))
        fewest.swap(here), best = key, best_weight = weight, first = false;
    }
    return true;
  }

  void place(uint32_t u, uint32_t v, uint32_t w, uint8_t closes) {
    const int32_t at = static_cast<int32_t>(tris_.size());
    const uint32_t side[2][2] = {{v, w}, {w, u}};
    shut(id(u, v)), edges_[id(u, v)].closed_by = at;
    for (int s = 0; s < 2; ++s) {
      const uint32_t a = side[s][0], b = side[s][1], i = id(a, b);
      if (closes >> s & 1) {
        shut(i), edges_[i].closed_by = at;
      } else {
        open(b, a), edges_[i].placed_by = at;
        block(i, +1);
      }
    }
    tris_.push_back({u, v, w});
    pruning_.place(tris_.back());
  }
  void remove(uint32_t u, uint32_t v, uint32_t w, uint8_t closes) {
    pruning_.remove(tris_.back());
    tris_.pop_back();
    const uint32_t side[2][2] = {{v, w}, {w, u}};
    for (int s = 1; s >= 0; --s) {
      const uint32_t a = side[s][0], b = side[s][1], i = id(a, b);
      if (closes >> s & 1) {
        open(a, b), edges_[i].closed_by = -1;
      } else {
        shut(i), edges_[i].placed_by = -1;
        block(i, -1);
      }
    }
    open(u, v), edges_[id(u, v)].closed_by = -1;
  }

  // One search node: its branch's reason for failing is left in slot(depth),
  // a set of positions below the depth.
  void node() {
    const uint32_t depth = static_cast<uint32_t>(tris_.size());
    uint64_t* out = slot(depth);
    std::fill(out, out + words_, 0);
    if (++nodes_ > budget_) {
      complete_ = false;
      return;
    }
    if (progress_ && (nodes_ & 4095) == 0 && !progress_(static_cast<double>(nodes_), static_cast<double>(budget_)))
      throw Cancelled();
    if (const uint32_t c = pruning_.dead()) return prefix(out, c);
    if (open_.empty()) {
      visit_(tris_);
      const uint32_t c = pruning_.dead();
      return prefix(out, c ? c : depth);
    }
    // The memo's key: the frontier, then the pruning's context.
    std::vector<uint32_t> key;
    if (memo_on_) {
      sorted_.clear();
      for (uint32_t i : open_) {
        const Edge& e = edges_[i];
        sorted_.push_back(e.open == 1 ? edge_key(e.lo, e.hi) : edge_key(e.hi, e.lo));
      }
      std::sort(sorted_.begin(), sorted_.end());
      for (uint64_t e : sorted_) key.push_back(static_cast<uint32_t>(e >> 32) << 16 | static_cast<uint32_t>(e));
      pruning_.context(sorted_, key);
      bool found = false;
      memo_.find(key, found);
      if (found) return prefix(out, depth);  // a twin failed: so does this (fill_search.hpp)
    }
    uint64_t edge = 0;
    std::vector<Option> options;
    const bool any = choose(edge, options);
    const uint32_t u = static_cast<uint32_t>(edge >> 32), v = static_cast<uint32_t>(edge);
    if (any)
      for (const Option& o : options) {
        place(u, v, o.apex, o.closes);
        node();
        remove(u, v, o.apex, o.closes);
        if (!complete_) return;
        if (const uint32_t c = pruning_.dead()) return prefix(out, c);
        const uint64_t* below = slot(depth + 1);
        if (!test(below, depth)) {  // it failed without this triangle: so does every other
          std::copy(below, below + words_, out);
          return remember(key);
        }
        for (size_t w = 0; w < words_; ++w) out[w] |= below[w];
        out[depth / 64] &= ~(uint64_t{1} << (depth % 64));
      }
    if (!any) edges_[id(u, v)].weight++;
    // Every triangle of the edge failed or was refused, and the edge is there
    // because its triangle placed it.
    set(out, edges_[id(u, v)].placed_by);
    if (const auto* all = apexes(u, v))
      for (uint32_t w : *all)
        if (std::none_of(options.begin(), options.end(), [&](const Option& o) { return o.apex == w; }))
          add_reasons(u, v, w, out);
    remember(key);
  }

  // Keeps a failed partial fill's key, when the pruning says its failure is
  // its completions' (explored) and the memo has room. (A key found here was
  // not in the memo at the node's start, where it was looked up, and partial
  // fills below have smaller uncovered parts: it is new.)
  void remember(const std::vector<uint32_t>& key) {
    if (!memo_on_ || !pruning_.explored()) return;
    if (memo_.words() + key.size() + 2 > pruning_.memo_words) return;
    memo_.insert(key, {});
  }
};

}  // namespace

bool search_fills(const Mesh& dt, const Candidates& candidates, const std::vector<std::pair<uint32_t, uint32_t>>& boundary,
                  uint64_t max_nodes, FillPruning& pruning, const std::function<void(const std::vector<Tri>&)>& visit,
                  const Progress& progress, uint64_t* nodes_used) {
  FillSearch search(dt, candidates, boundary, max_nodes, pruning, visit, progress);
  return search.run(nodes_used);
}

}  // namespace hodt
