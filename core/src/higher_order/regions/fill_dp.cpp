#include "higher_order/regions/fill_dp.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <span>

#include "hodt/error.hpp"
#include "containers/flat_index.hpp"
#include "containers/words_hash.hpp"
#include "higher_order/regions/fill_graph.hpp"
#include "tuning/budgets.hpp"

namespace hodt {

namespace {

// A partial fill, reduced to what its completions can tell apart.
struct Partial {
  std::vector<uint64_t> open;     // the frontier, sorted
  std::vector<uint32_t> behind;   // per open edge, the kind of apex of the covered triangle on its right (apex terms)
  std::vector<uint32_t> around;   // per frontier vertex, by v: v, n, then its fan in n words (RegionTerms::extend_fan)
  std::vector<uint32_t> signature;  // entries in SignatureEntry order: each its count of triangles, then theirs
  double value = 0;
  uint32_t node = UINT32_MAX;  // how it was reached (Node)
};

// A kept partial fill as it is expanded: its frontier unpacked, the rest read
// where its layer holds it (its children copy what they change).
struct Kept {
  std::vector<uint64_t> open;
  std::span<const uint32_t> behind, around, signature;
  double value = 0;
  uint32_t node = UINT32_MAX;
};

// The partial fills of one layer, one per key, as words in one array (a layer
// holds up to hundreds of thousands: one allocation each would dominate).
class Layer {
 public:
  struct Stored {
    size_t at;           // its key's first word
    uint32_t sizes[4];   // of open (words), behind, around, signature
    double value;
    uint32_t node;
    size_t hash;
  };
  std::vector<Stored> states;

  // Keeps c if no state has its key, or in place of that state if c is better;
  // returns the index of the state with its key (hashed and compared in its
  // pieces: most children merge, and need no copy).
  template <class Better>
  uint32_t offer(const Partial& c, Better&& better) {
    const uint32_t sizes[4] = {static_cast<uint32_t>(2 * c.open.size()), static_cast<uint32_t>(c.behind.size()),
                               static_cast<uint32_t>(c.around.size()), static_cast<uint32_t>(c.signature.size())};
    WordsHasher hasher;
    key_words(c, [&](uint32_t x) { return hasher.add(x), true; });
    size_t hash = hasher.done();
    for (uint32_t n : sizes) hash = hash * 31 + n;
    if (2 * (states.size() + 1) > slots_.size()) grow();
    const size_t mask = slots_.size() - 1;
    for (size_t i = hash & mask;; i = (i + 1) & mask) {
      const uint32_t s = slots_[i];
      if (s == kEmpty) {
        slots_[i] = static_cast<uint32_t>(states.size());
        states.push_back({words_.size(), {sizes[0], sizes[1], sizes[2], sizes[3]}, c.value, c.node, hash});
        key_words(c, [&](uint32_t x) { return words_.push_back(x), true; });
        return slots_[i];
      }
      Stored& t = states[s];
      if (t.hash == hash && std::equal(t.sizes, t.sizes + 4, sizes) && same_key(t, c)) {
        if (better(c.value, t.value)) t.value = c.value, t.node = c.node;  // (the same key: only these differ)
        return s;
      }
    }
  }

  // State i, its frontier unpacked into p (the rest valid while this layer is
  // not changed).
  void load(size_t i, Kept& p) const {
    const Stored& t = states[i];
    const uint32_t* w = words_.data() + t.at;
    p.open.clear();
    for (uint32_t j = 0; j < t.sizes[0]; j += 2) p.open.push_back(uint64_t{w[j]} << 32 | w[j + 1]);
    w += t.sizes[0];
    for (auto [part, n] : {std::pair{&p.behind, t.sizes[1]}, {&p.around, t.sizes[2]}, {&p.signature, t.sizes[3]}}) {
      *part = {w, n};
      w += n;
    }
    p.value = t.value;
    p.node = t.node;
  }

  // Empty, its memory kept for the next layer (a fresh one per layer pays
  // its page faults and regrowth again at every layer).
  void clear() {
    const size_t mask = slots_.size() - 1;
    for (uint32_t s = 0; s < states.size(); ++s) {
      size_t i = states[s].hash & mask;
      while (slots_[i] != s) i = (i + 1) & mask;
      slots_[i] = kEmpty;
    }
    states.clear();
    words_.clear();
  }

 private:
  static constexpr uint32_t kEmpty = UINT32_MAX;
  std::vector<uint32_t> words_, slots_;
  // c's key word by word, as stored (each open edge: its ends), while
  // visit(word) returns true; returns whether it did to the end.
  template <class Visit>
  static bool key_words(const Partial& c, Visit&& visit) {
    for (uint64_t e : c.open)
      if (!visit(static_cast<uint32_t>(e >> 32)) || !visit(static_cast<uint32_t>(e))) return false;
    for (const auto* part : {&c.behind, &c.around, &c.signature})
      for (uint32_t x : *part)
        if (!visit(x)) return false;
    return true;
  }
  // Whether t's key is c's (their sizes equal).
  bool same_key(const Stored& t, const Partial& c) const {
    const uint32_t* w = words_.data() + t.at;
    return key_words(c, [&](uint32_t x) { return *w++ == x; });
  }
  void grow() {
    slots_.assign(std::max<size_t>(64, 2 * slots_.size()), kEmpty);
    const size_t mask = slots_.size() - 1;
    for (uint32_t s = 0; s < states.size(); ++s) {
      size_t i = states[s].hash & mask;
      while (slots_[i] != kEmpty) i = (i + 1) & mask;
      slots_[i] = s;
    }
  }
};

struct Node {
  uint32_t parent;
  Tri triangle;
};


uint32_t from(uint64_t e) { return static_cast<uint32_t>(e >> 32); }
uint32_t to(uint64_t e) { return static_cast<uint32_t>(e); }

// The fill graph (fill_graph.hpp) as the DP runs: every step, merged or not,
// as an arc between numbered kept states; entries interned as they come.
struct Recorder {
  FillGraph graph;
  std::map<Tri, uint32_t> item_id;
  std::vector<std::map<SignatureEntry, uint32_t>> entry_id;
  std::vector<std::pair<uint32_t, uint32_t>> pending;  // the child being built: its (item, entry)
  double step = 0;                                      // ... and its terms, combined
  void take(const SignatureEntry& entry) {
    const auto [it, fresh] = item_id.try_emplace(RegionTerms::item_of(entry), static_cast<uint32_t>(entry_id.size()));
    if (fresh) entry_id.emplace_back();
    auto& ids = entry_id[it->second];
    pending.push_back({it->second, ids.try_emplace(entry, static_cast<uint32_t>(ids.size())).first->second});
  }
};

class FillDp {
 public:
  FillDp(const Mesh& dt, const Candidates& cand, const RegionTerms& terms, uint32_t r, const std::vector<Tri>* keep,
         Recorder* record = nullptr)
      : dt_(dt), cand_(cand), T_(terms), r_(r), keep_(keep), record_(record) {}

  std::optional<std::vector<BestFill>> run(uint64_t max_states, const Progress& progress, uint64_t* used) {
    Partial start;
    for (auto [a, b] : T_.regions().regions[r_].boundary) start.open.push_back(edge_key(a, b));
    std::sort(start.open.begin(), start.open.end());
    set_axis(start.open);
    if (T_.reads_apexes()) start.behind.assign(start.open.size(), kNoApex);  // (the outside: never read)
    Layer layers[2];
    Layer *layer = &layers[0], *next = &layers[1];
    layer->offer(start, [](double, double) { return false; });
    std::vector<BestFill> out;
    uint64_t states = 1, generated = 0, work = 0;
    uint32_t base = 0;  // the layer's first node (when recording)
    Kept& p = parent_;
    while (!layer->states.empty()) {
      next->clear();
      const uint32_t next_base = base + static_cast<uint32_t>(layer->states.size());
      for (size_t i = 0; i < layer->states.size(); ++i) {
        layer->load(i, p);
        if (p.open.empty()) {
          if (record_) record_->graph.complete.push_back(base + static_cast<uint32_t>(i));
          else out.push_back({triangles_of(p.node), p.value});
          continue;
        }
        // (Children cost their keys even when merged: they count too, a quarter
        // each. An expansion costs its frontier's length: a region of thousands
        // of triangles must not take the time of millions of states.)
        work += p.open.size();
        if ((states + generated / 4) > max_states || work > kBudgets.fill_dp_work_per_state * max_states) return std::nullopt;
        expand(p, [&](const Partial& child) {
          ++generated;
          const uint32_t at = next->offer(child, [&](double a, double b) { return T_.better(a, b); });
          if (!record_) return;
          FillGraph& g = record_->graph;
          const Node& step = pending_[child.node];
          g.arcs.push_back({base + static_cast<uint32_t>(i), next_base + at, record_->step, step.triangle,
                            static_cast<uint32_t>(g.taken.size()), static_cast<uint32_t>(record_->pending.size())});
          g.taken.insert(g.taken.end(), record_->pending.begin(), record_->pending.end());
        });
      }
      base = next_base;
      ++layers_;
      if (record_) record_->graph.nodes = base + static_cast<uint32_t>(next->states.size());
      states += next->states.size();
      if (used) *used += next->states.size();
      if (states > max_states) return std::nullopt;
      if (progress && !progress(static_cast<double>(states), static_cast<double>(max_states))) throw Cancelled();
      // Record how each kept state was reached.
      for (Layer::Stored& t : next->states) {
        nodes_.push_back(pending_[t.node]);
        t.node = static_cast<uint32_t>(nodes_.size() - 1);
      }
      pending_.clear();
      std::swap(layer, next);
    }
    return out;
  }

  uint32_t layers() const { return layers_; }

 private:
  const Mesh& dt_;
  const Candidates& cand_;
  const RegionTerms& T_;
  uint32_t r_;
  const std::vector<Tri>* keep_;  // sorted items whose entries are kept (all if null)
  Recorder* record_;              // records the fill graph (with keep_ empty)
  uint32_t layers_ = 0;            // layers done: every kept partial fill has that many triangles
  std::vector<Node> nodes_;    // kept states' (parent, last triangle)
  std::vector<Node> pending_;  // this layer's children, before merging
  SignatureEntry entry_;
  std::vector<uint32_t> fan_;  // the fan being extended
  Kept parent_;                // the state being expanded
  Partial child_;              // the child being built
  mutable FlatIndex counts_;  // open edge -> its candidate triangles
  double origin_[2] = {0, 0}, axis_[2] = {1, 0};  // the sweep (see expand)

  // The boundary's centroid and principal axis (the eigenvector of the larger
  // eigenvalue of its covariance; + - * / and sqrt only, so that native and wasm
  // sweep alike).
  void set_axis(const std::vector<uint64_t>& boundary) {
    double n = 0, sxx = 0, sxy = 0, syy = 0;
    for (uint64_t e : boundary) origin_[0] += dt_.point(from(e))[0], origin_[1] += dt_.point(from(e))[1], n += 1;
    if (n == 0) return;
    origin_[0] /= n, origin_[1] /= n;
    for (uint64_t e : boundary) {
      const double x = dt_.point(from(e))[0] - origin_[0], y = dt_.point(from(e))[1] - origin_[1];
      sxx += x * x, sxy += x * y, syy += y * y;
    }
    const double half = (sxx - syy) / 2, root = std::sqrt(half * half + sxy * sxy);
    if (root == 0) return;  // no principal axis: sweep along x
    if (half >= 0) axis_[0] = half + root, axis_[1] = sxy;
    else axis_[0] = sxy, axis_[1] = root - half;
  }
  double along(uint32_t v) const {
    return (dt_.point(v)[0] - origin_[0]) * axis_[0] + (dt_.point(v)[1] - origin_[1]) * axis_[1];
  }

  std::vector<Tri> triangles_of(uint32_t node) const {
    std::vector<Tri> tris;
    for (; node != UINT32_MAX; node = nodes_[node].parent) tris.push_back(canonical_triangle(nodes_[node].triangle));
    std::sort(tris.begin(), tris.end());
    return tris;
  }

  // (Every expansion reads the count of every open edge: memoised in a flat
  // table, as a long region's frontier has hundreds.)
  size_t candidates(uint64_t e) const {
    uint32_t n = counts_.find(e);
    if (n == FlatIndex::kNone) {
      const auto it = cand_.find(e);
      n = it == cand_.end() ? 0 : static_cast<uint32_t>(it->second.size());
      counts_.insert(e, n);
    }
    return n;
  }

  static bool on_frontier(const Partial& p, uint32_t v) {
    for (uint64_t e : p.open)
      if (from(e) == v || to(e) == v) return true;
    return false;
  }

  void take(Partial& p, double term) {
    p.value = T_.add(p.value, term);
    if (record_) record_->step = T_.add(record_->step, term);
    if (entry_.empty()) return;
    if (record_) record_->take(entry_);
    if (keep_ && !std::binary_search(keep_->begin(), keep_->end(), RegionTerms::item_of(entry_))) return;
    // After the entries that are not greater (SignatureEntry order: triangle by
    // triangle, then by length, which is word by word).
    const uint32_t* words = entry_.front().data();
    const size_t n = 3 * entry_.size();
    size_t pos = 0;
    while (pos < p.signature.size()) {
      const uint32_t* at = p.signature.data() + pos + 1;
      const size_t m = 3 * size_t{p.signature[pos]};
      if (std::lexicographical_compare(words, words + n, at, at + m)) break;
      pos += 1 + m;
    }
    const auto where = p.signature.begin() + static_cast<std::ptrdiff_t>(pos);
    p.signature.insert(p.signature.insert(where, static_cast<uint32_t>(entry_.size())) + 1, words, words + n);
  }

  // Edge a -> b gets its triangle on the left (apex c); `behind` is the apex on
  // its right (inside the region; kNoApex when the terms read none).
  void edge_complete(Partial& p, uint32_t a, uint32_t b, uint32_t c, uint32_t behind) {
    if (T_.on_boundary(r_, a, b)) take(p, T_.boundary_edge(r_, a, b, c, entry_));
    else entry_.clear(), take(p, T_.inside_edge(a, b, c, behind));
  }

  // Adds triangle t to the fans of its corners; completes the corners that left
  // the frontier. fresh: per corner, how many of its sides t draws first.
  void add_to_fans(Partial& p, const Tri& t, const std::array<uint32_t, 3>& fresh) {
    for (int i = 0; i < 3; ++i) {
      const uint32_t v = t[i];
      // v's block (blocks sorted by vertex): v, n, then its fan in n words.
      size_t pos = 0;
      while (pos < p.around.size() && p.around[pos] < v) pos += 2 + p.around[pos + 1];
      const bool had = pos < p.around.size() && p.around[pos] == v;
      const size_t words = had ? p.around[pos + 1] : 0;
      const auto first = p.around.begin() + static_cast<std::ptrdiff_t>(pos);
      fan_.assign(first + (had ? 2 : 0), first + (had ? 2 + static_cast<std::ptrdiff_t>(words) : 0));
      T_.extend_fan(v, t, fresh[i], fan_);
      if (had) p.around.erase(first, first + 2 + static_cast<std::ptrdiff_t>(words));
      if (!on_frontier(p, v)) {  // complete: its term, or its signature entry
        take(p, T_.fan_done(r_, v, fan_, entry_));
        continue;
      }
      const auto at = p.around.insert(p.around.begin() + static_cast<std::ptrdiff_t>(pos), fan_.begin(), fan_.end());
      p.around.insert(at, {v, static_cast<uint32_t>(fan_.size())});
    }
  }

  template <class Emit>
  void expand(const Kept& p, Emit&& emit) {
    // The open edge to grow from, a function of the frontier so that equal
    // frontiers expand alike: a forced one (a single candidate) first, else the
    // one furthest back along the region's principal axis (ties: the fewest
    // candidate triangles, then the smallest key). The fill then sweeps the
    // region lengthwise and its frontier stays as short as the region is wide:
    // on regions glued from strips, or DEM regions of tens of triangles, this
    // keeps far fewer partial fills than growing at the edge with the fewest
    // candidates, whose frontier wanders across the region.
    size_t at = 0;
    double back = 0;
    size_t fewest = 0;
    for (size_t i = 0; i < p.open.size(); ++i) {
      const size_t c = candidates(p.open[i]);
      if (c == 0) return;  // a dead end
      if (c == 1) {
        at = i, fewest = 1;
        break;
      }
      const double pos = std::min(along(from(p.open[i])), along(to(p.open[i])));
      if (fewest == 0 || pos < back || (pos == back && c < fewest)) at = i, back = pos, fewest = c;
    }
    for (size_t i = at + 1; fewest == 1 && i < p.open.size(); ++i)
      if (candidates(p.open[i]) == 0) return;  // (a dead end after the forced edge)
    const uint32_t u = from(p.open[at]), v = to(p.open[at]);
    for (uint32_t w : cand_.find(p.open[at])->second) {
      // Sides v -> w and w -> u: each closes an open edge in the same direction,
      // or opens its reverse, if it crosses no frontier edge.
      const uint32_t side[2][2] = {{v, w}, {w, u}};
      int close[2] = {-1, -1};
      bool ok = true;
      for (int s = 0; s < 2 && ok; ++s) {
        const uint32_t a = side[s][0], b = side[s][1];
        const auto it = std::lower_bound(p.open.begin(), p.open.end(), edge_key(a, b));
        if (it != p.open.end() && *it == edge_key(a, b)) {
          close[s] = static_cast<int>(it - p.open.begin());
          continue;
        }
        if (std::binary_search(p.open.begin(), p.open.end(), edge_key(b, a))) ok = false;  // its far side is covered
        for (size_t j = 0; j < p.open.size() && ok; ++j)
          if (segments_cross(dt_, a, b, from(p.open[j]), to(p.open[j]))) ok = false;
      }
      if (!ok) continue;
      Partial& c = child_;
      if (record_) record_->pending.clear(), record_->step = 0;
      c.value = p.value;
      c.signature.assign(p.signature.begin(), p.signature.end());
      const bool edges = T_.reads_apexes();
      // The new frontier: without u -> v and the closed edges, with the opened
      // ones merged in (keys are distinct: an opened edge's reverse was not open).
      std::pair<uint64_t, uint32_t> opened[2];
      size_t n_opened = 0;
      for (int s = 0; s < 2; ++s)
        if (close[s] < 0) {
          const uint32_t a = side[s][1], b = side[s][0], behind = s == 0 ? u : v;
          opened[n_opened++] = {edge_key(a, b), edges ? T_.apex_kind(a, b, behind) : 0};
        }
      if (n_opened == 2 && opened[1].first < opened[0].first) std::swap(opened[0], opened[1]);
      c.open.clear();
      c.behind.clear();
      size_t next = 0;
      auto push = [&](uint64_t e, uint32_t b) {
        c.open.push_back(e);
        if (edges) c.behind.push_back(b);
      };
      for (size_t j = 0; j < p.open.size(); ++j) {
        if (j == at || static_cast<int>(j) == close[0] || static_cast<int>(j) == close[1]) continue;
        for (; next < n_opened && opened[next].first < p.open[j]; ++next) push(opened[next].first, opened[next].second);
        push(p.open[j], edges ? p.behind[j] : 0);
      }
      for (; next < n_opened; ++next) push(opened[next].first, opened[next].second);
      c.around.assign(p.around.begin(), p.around.end());
      if (T_.reads_edges()) {  // the edges this triangle completes: u -> v and the sides it closes
        auto behind = [&](int j) { return edges ? p.behind[static_cast<size_t>(j)] : kNoApex; };
        edge_complete(c, u, v, w, behind(static_cast<int>(at)));
        if (close[0] >= 0) edge_complete(c, v, w, u, behind(close[0]));
        if (close[1] >= 0) edge_complete(c, w, u, v, behind(close[1]));
      }
      if (T_.reads_triangles()) entry_.clear(), take(c, T_.triangle({u, v, w}));
      if (T_.reads_vertices()) {  // (the sides v -> w and w -> u are new unless they closed an open edge)
        const uint32_t vw = close[0] < 0, wu = close[1] < 0;
        add_to_fans(c, {u, v, w}, {wu, vw, vw + wu});
      }
      pending_.push_back({p.node, {u, v, w}});
      c.node = static_cast<uint32_t>(pending_.size() - 1);
      emit(c);
    }
  }
};

}  // namespace

std::optional<std::vector<BestFill>> best_fills(const Mesh& dt, const Candidates& candidates, const RegionTerms& terms,
                                                uint32_t region, uint64_t max_states, const Progress& progress,
                                                uint64_t* states_used, const std::vector<Tri>* keep_items,
                                                double* swept) {
  FillDp dp(dt, candidates, terms, region, keep_items);
  auto fills = dp.run(max_states, progress, states_used);
  if (swept)
    *swept = fills ? 1.0
                   : dp.layers() / static_cast<double>(terms.regions().regions[region].delaunay_triangles.size());
  return fills;
}

}  // namespace hodt

namespace hodt {

std::optional<FillGraph> fill_graph(const Mesh& dt, const Candidates& candidates, const RegionTerms& terms,
                                    uint32_t region, uint64_t max_states, const Progress& progress,
                                    uint64_t* states_used) {
  const std::vector<Tri> no_items;
  Recorder rec;
  FillDp dp(dt, candidates, terms, region, &no_items, &rec);
  if (!dp.run(max_states, progress, states_used)) return std::nullopt;
  FillGraph& g = rec.graph;
  g.region = region;
  // Only arcs on a path to a complete fill (arcs come layer by layer: backwards
  // once is enough), and only the entries those take.
  std::vector<uint8_t> alive(g.nodes, 0);
  for (uint32_t n : g.complete) alive[n] = 1;
  for (size_t a = g.arcs.size(); a-- > 0;) alive[g.arcs[a].parent] |= alive[g.arcs[a].child];
  std::vector<std::vector<uint32_t>> renumber(rec.entry_id.size());
  for (size_t i = 0; i < renumber.size(); ++i) renumber[i].assign(rec.entry_id[i].size(), UINT32_MAX);
  std::vector<uint32_t> count(renumber.size(), 0);
  std::vector<FillGraph::Arc> arcs;
  std::vector<std::pair<uint32_t, uint32_t>> taken;
  for (FillGraph::Arc arc : g.arcs) {
    if (!alive[arc.child]) continue;
    const uint32_t first = static_cast<uint32_t>(taken.size());
    for (uint32_t t = arc.first_take; t < arc.first_take + arc.takes; ++t) {
      auto [item, entry] = g.taken[t];
      uint32_t& id = renumber[item][entry];
      if (id == UINT32_MAX) id = count[item]++;
      taken.push_back({item, id});
    }
    arc.first_take = first;
    arcs.push_back(arc);
  }
  // Items in sorted order (their map's), entries by their new numbers.
  std::vector<uint32_t> item_index(renumber.size(), UINT32_MAX);
  for (const auto& [item, i] : rec.item_id) {
    if (!count[i]) continue;
    item_index[i] = static_cast<uint32_t>(g.items.size());
    g.items.push_back(item);
    g.entries.emplace_back(count[i]);
    for (const auto& [entry, id] : rec.entry_id[i])
      if (renumber[i][id] != UINT32_MAX) g.entries.back()[renumber[i][id]] = entry;
  }
  for (auto& [item, entry] : taken) item = item_index[item];
  g.arcs = std::move(arcs);
  g.taken = std::move(taken);
  return std::move(g);
}

}  // namespace hodt
