#include "engines/factor_graph.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <utility>

#include "hodt/error.hpp"
#include "engines/elimination_queue.hpp"
#include "hodt/progress.hpp"
#include "tuning/budgets.hpp"

namespace hodt {

double FactorGraph::evaluate(const Choice& x) const {
  double v = constant;
  for (const Factor& f : factors) {
    size_t idx = 0;
    for (size_t k = 0; k < f.scope.size(); ++k) idx |= size_t(x[f.scope[k]] & 1) << k;
    v = combine == Combine::Sum ? v + f.table[idx] : std::max(v, f.table[idx]);
  }
  return v;
}

void FactorGraph::simplify(const Progress& progress) {
  std::vector<Factor> kept;
  kept.reserve(factors.size());
  WorkCounter work;
  const double total = static_cast<double>(factors.size());
  for (size_t i = 0; i < factors.size(); ++i) {
    Factor& f = factors[i];
    for (size_t k = f.scope.size(); k-- > 0;) {
      if (work.tick(static_cast<double>(f.table.size()))) report(progress, static_cast<double>(i), total);
      const size_t bit = size_t(1) << k;
      bool depends = false;
      for (size_t idx = 0; idx < f.table.size() && !depends; ++idx)
        depends = (idx & bit) == 0 && f.table[idx] != f.table[idx | bit];
      if (depends) continue;
      // Keep the entries with bit k clear, closing the gap.
      std::vector<double> t;
      t.reserve(f.table.size() / 2);
      for (size_t idx = 0; idx < f.table.size(); ++idx)
        if ((idx & bit) == 0) t.push_back(f.table[idx]);
      f.table.swap(t);
      f.scope.erase(f.scope.begin() + static_cast<std::ptrdiff_t>(k));
    }
    if (f.scope.empty()) {
      constant = combine == Combine::Sum ? constant + f.table[0] : std::max(constant, f.table[0]);
    } else {
      kept.push_back(std::move(f));
    }
  }
  factors.swap(kept);
}

namespace {

using Adjacency = std::vector<std::vector<uint32_t>>;

// Eliminates variables in the order pick() gives (UINT32_MAX: done), making the
// remaining neighbours of each a clique (fill-in), into d's order and bags;
// changed(neighbours) is told of the variables whose neighbourhoods changed.
// Stops (d.complete = false) once a bag is wider than max_width: the fill-in of
// a wide component would cost far more memory and time than the answer needs.
template <class Pick, class Changed>
void eliminate(Adjacency& adj, Decomposition& d, uint32_t max_width, const Progress& progress, Pick pick,
               Changed changed) {
  const uint32_t n = static_cast<uint32_t>(adj.size());
  d.order.reserve(n);
  d.bags.reserve(n);
  WorkCounter work;
  for (uint32_t v; (v = pick()) != UINT32_MAX;) {
    std::vector<uint32_t> bag = {v};
    bag.insert(bag.end(), adj[v].begin(), adj[v].end());
    const uint32_t width = static_cast<uint32_t>(bag.size() - 1);
    d.width = std::max(d.width, width);
    d.component_width[d.component[v]] = std::max(d.component_width[d.component[v]], width);
    if (d.width > max_width) {  // the answer is "too wide" already
      d.complete = false;
      return;
    }
    double merged_size = 0;
    for (uint32_t a : adj[v]) {
      auto& na = adj[a];
      na.erase(std::lower_bound(na.begin(), na.end(), v));
      std::vector<uint32_t> merged;
      merged.reserve(na.size() + adj[v].size());
      std::set_union(na.begin(), na.end(), adj[v].begin(), adj[v].end(), std::back_inserter(merged));
      merged.erase(std::remove(merged.begin(), merged.end(), a), merged.end());
      na.swap(merged);
      merged_size += static_cast<double>(na.size());
    }
    changed(adj[v]);
    if (work.tick(merged_size + 32 * bag.size())) report(progress, static_cast<double>(d.order.size()), n);
    adj[v].clear();
    d.order.push_back(v);
    d.bags.push_back(std::move(bag));
  }
}

// Min-degree order: the variable with the fewest neighbours first.
void eliminate_min_degree(Adjacency adj, Decomposition& d, uint32_t max_width, const Progress& progress) {
  const uint32_t n = static_cast<uint32_t>(adj.size());
  EliminationQueue<uint32_t> queue(n);
  for (uint32_t v = 0; v < n; ++v) queue.offer(v, static_cast<uint32_t>(adj[v].size()));
  auto changed = [&](const std::vector<uint32_t>& nb) {
    for (uint32_t a : nb) queue.offer(a, static_cast<uint32_t>(adj[a].size()));
  };
  eliminate(adj, d, max_width, progress, [&] { return queue.next(); }, changed);
}

// Min-fill order (fewest edges added; ties by degree, then index): narrower than
// min-degree on grid-like graphs (such as a raster's frustrated quads), but
// each step recounts the fill of the variables within two steps of the
// eliminated one. Gives up (false) past `budget` pair tests.
bool eliminate_min_fill(Adjacency adj, Decomposition& d, uint32_t max_width, const Progress& progress,
                        double budget) {
  const uint32_t n = static_cast<uint32_t>(adj.size());
  double spent = 0;
  auto fill_of = [&](uint32_t v) {
    uint64_t f = 0;
    const auto& a = adj[v];
    for (size_t i = 0; i < a.size(); ++i)
      for (size_t j = i + 1; j < a.size(); ++j) f += !std::binary_search(adj[a[i]].begin(), adj[a[i]].end(), a[j]);
    spent += static_cast<double>(a.size() * a.size()) / 2 + 1;
    return f;
  };
  // Fewest fill-in edges, then fewest neighbours.
  EliminationQueue<std::pair<uint64_t, uint32_t>> queue(n);
  std::vector<uint32_t> seen(n, 0);
  uint32_t round = 0;
  for (uint32_t v = 0; v < n; ++v) queue.offer(v, {fill_of(v), static_cast<uint32_t>(adj[v].size())});
  bool over = false;
  auto pick = [&] { return over ? UINT32_MAX : queue.next(); };
  WorkCounter work;  // (a step near the end recounts thousands of fills)
  auto changed = [&](const std::vector<uint32_t>& nb) {
    ++round;
    auto recount = [&](uint32_t w) {
      if (queue.eliminated(w) || seen[w] == round) return;
      seen[w] = round;
      const double before = spent;
      queue.offer(w, {fill_of(w), static_cast<uint32_t>(adj[w].size())});
      if (work.tick(spent - before)) report(progress, round, n);
    };
    for (uint32_t a : nb) {
      recount(a);
      for (uint32_t w : adj[a]) recount(w);
    }
    over = spent > budget;
  };
  eliminate(adj, d, max_width, progress, pick, changed);
  return !over;
}

}  // namespace

Decomposition decompose(const FactorGraph& g, uint32_t max_width, const Progress& progress, Elimination elimination) {
  const uint32_t n = g.num_vars;
  Decomposition d;
  WorkCounter work;
  // Interaction graph: variables sharing a factor are neighbours.
  Adjacency adj(n);
  for (const Factor& f : g.factors) {
    for (uint32_t a : f.scope)
      for (uint32_t b : f.scope)
        if (a != b) adj[a].push_back(b);
    if (work.tick(static_cast<double>(f.scope.size() * f.scope.size()))) report(progress, 0, n);
  }
  for (auto& a : adj) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    if (work.tick(static_cast<double>(a.size()) + 1)) report(progress, 0, n);
  }
  // Connected components (for reporting widths per component).
  d.component.assign(n, UINT32_MAX);
  for (uint32_t s = 0; s < n; ++s) {
    if (d.component[s] != UINT32_MAX) continue;
    std::vector<uint32_t> stack = {s};
    d.component[s] = d.num_components;
    while (!stack.empty()) {
      const uint32_t v = stack.back();
      stack.pop_back();
      for (uint32_t w : adj[v])
        if (d.component[w] == UINT32_MAX) d.component[w] = d.num_components, stack.push_back(w);
    }
    ++d.num_components;
  }
  d.component_width.assign(d.num_components, 0);
  if (elimination == Elimination::MinFill) {
    eliminate_min_fill(std::move(adj), d, max_width, progress, INFINITY);
    return d;
  }
  // Too wide, min-degree may leave min-fill to try, on graphs small enough to
  // count fill-ins (within kBudgets.min_fill_work pair tests): only then is the graph
  // kept for it (a copy per solve of a million quads would cost more than the
  // elimination).
  const bool fallback = elimination == Elimination::Auto && n <= kBudgets.min_fill_variables;
  const Decomposition start = fallback ? d : Decomposition{};
  eliminate_min_degree(fallback ? adj : std::move(adj), d, max_width, progress);
  if (!fallback || d.complete) return d;
  Decomposition fill = start;
  if (eliminate_min_fill(std::move(adj), fill, max_width, progress, kBudgets.min_fill_work) && fill.complete) return fill;
  return d;
}

namespace {

// A table over a set of variables (sorted by elimination position).
struct Table {
  std::vector<uint32_t> vars;
  std::vector<double> values;
};

}  // namespace

namespace {

// Bytes the DP would hold at its peak, at most: every message and back-pointer
// table (one entry per assignment of a bag without its variable), the copies of
// the factors, and the largest combined table.
double table_bytes(const FactorGraph& g, const Decomposition& d) {
  double bytes = 0, widest = 0;
  for (const auto& bag : d.bags) {
    const double entries = std::ldexp(1.0, static_cast<int>(bag.size()));
    bytes += entries / 2 * (sizeof(double) + 1);
    widest = std::max(widest, entries);
  }
  for (const Factor& f : g.factors) bytes += static_cast<double>(f.table.size()) * sizeof(double);
  return bytes + widest * sizeof(double);
}

std::string mebibytes(double bytes) { return std::to_string(static_cast<uint64_t>(std::ceil(bytes / 1048576))) + " MiB"; }

}  // namespace

DpResult solve_exact(const FactorGraph& g, const DpLimits& limits) {
  DpResult r;
  r.decomposition = decompose(g, limits.max_width, limits.progress);
  const Decomposition& d = r.decomposition;
  if (d.width > limits.max_width) {
    uint32_t worst = 0;
    for (uint32_t c = 0; c < d.num_components; ++c)
      if (d.component_width[c] > d.component_width[worst]) worst = c;
    uint32_t size = 0;
    for (uint32_t v = 0; v < g.num_vars; ++v) size += d.component[v] == worst;
    throw LimitError("exact: a component of " + std::to_string(size) + " quads has a tree decomposition of width " +
                     (d.complete ? "" : "at least ") + std::to_string(d.width) + " (tables of 2^" +
                     std::to_string(d.width + 1) + " entries); the memory cap allows width " +
                     std::to_string(limits.max_width) + "; use --method approx");
  }
  if (const double bytes = table_bytes(g, d); bytes > limits.max_table_bytes)
    throw LimitError("exact: the tables of the tree decomposition (width " + std::to_string(d.width) + ", " +
                     std::to_string(g.num_vars) + " quads) would need " + mebibytes(bytes) +
                     "; the memory cap is " + mebibytes(limits.max_table_bytes) + "; use --method approx");
  const uint32_t n = g.num_vars;
  std::vector<uint32_t> position(n);
  for (uint32_t i = 0; i < n; ++i) position[d.order[i]] = i;
  const bool maximise = g.sense == Sense::Max;
  const bool sum = g.combine == Combine::Sum;
  auto better = [&](double a, double b) { return maximise ? a > b : a < b; };

  // Buckets: each factor goes to its earliest-eliminated variable.
  std::vector<std::vector<Table>> bucket(n);
  double constant = g.constant;
  WorkCounter work;
  for (const Factor& f : g.factors) {
    if (work.tick(static_cast<double>(64 + f.table.size()))) report(limits.progress, 0, n);
    if (f.scope.empty()) {
      constant = sum ? constant + f.table[0] : std::max(constant, f.table[0]);
      continue;
    }
    uint32_t first = f.scope[0];
    for (uint32_t v : f.scope)
      if (position[v] < position[first]) first = v;
    bucket[first].push_back(Table{f.scope, f.table});
  }

  // Eliminate in order; keep for each variable its later neighbours and the best
  // value of it for each of their assignments (the back-pointers).
  std::vector<std::vector<uint32_t>> later(n);
  std::vector<std::vector<uint8_t>> best_value(n);
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t v = d.order[i];
    if ((i & 255) == 0 || work.tick(64)) report(limits.progress, i, n);  // a bag's own cost: its vectors
    std::vector<uint32_t> bag = d.bags[i];  // v first, then its later neighbours
    std::sort(bag.begin() + 1, bag.end(), [&](uint32_t a, uint32_t b) { return position[a] < position[b]; });
    const uint32_t k = static_cast<uint32_t>(bag.size());
    std::vector<double> combined(size_t(1) << k, sum ? 0.0 : -INFINITY);
    // A table's index from a bag assignment: the bits of its variables, read as
    // two lookups (the bag's low 8 bits and the rest) instead of bit by bit.
    const uint32_t low_bits = std::min<uint32_t>(k, 8);
    std::vector<uint32_t> part(k), low(size_t(1) << low_bits), high(size_t(1) << (k - low_bits));
    for (const Table& t : bucket[v]) {
      std::fill(part.begin(), part.end(), 0);
      for (size_t j = 0; j < t.vars.size(); ++j)
        part[std::find(bag.begin(), bag.end(), t.vars[j]) - bag.begin()] = uint32_t(1) << j;
      for (size_t x = 1; x < low.size(); ++x) low[x] = low[x & (x - 1)] | part[std::countr_zero(x)];
      for (size_t x = 1; x < high.size(); ++x) high[x] = high[x & (x - 1)] | part[low_bits + std::countr_zero(x)];
      for (size_t idx = 0; idx < combined.size(); ++idx) {
        const double value = t.values[low[idx & (low.size() - 1)] | high[idx >> low_bits]];
        combined[idx] = sum ? combined[idx] + value : std::max(combined[idx], value);
        if ((idx & 4095) == 4095 && work.tick(4096)) report(limits.progress, i, n);
      }
    }
    bucket[v].clear();
    bucket[v].shrink_to_fit();
    // Optimise v (bit 0) out.
    Table message{std::vector<uint32_t>(bag.begin() + 1, bag.end()), std::vector<double>(size_t(1) << (k - 1))};
    best_value[v].resize(message.values.size());
    for (size_t rest = 0; rest < message.values.size(); ++rest) {
      const double v0 = combined[rest << 1], v1 = combined[(rest << 1) | 1];
      const bool one = better(v1, v0);
      best_value[v][rest] = one;
      message.values[rest] = one ? v1 : v0;
      if (work.tick()) report(limits.progress, i, n);
    }
    later[v] = message.vars;
    if (message.vars.empty()) {
      constant = sum ? constant + message.values[0] : std::max(constant, message.values[0]);
    } else {
      bucket[message.vars[0]].push_back(std::move(message));
    }
  }
  // Rebuild the optimal choice in reverse order.
  r.choice.assign(n, 0);
  for (uint32_t i = n; i-- > 0;) {
    const uint32_t v = d.order[i];
    size_t idx = 0;
    for (size_t j = 0; j < later[v].size(); ++j) idx |= size_t(r.choice[later[v][j]]) << j;
    r.choice[v] = best_value[v][idx];
    if ((i & 255) == 0 || work.tick(static_cast<double>(later[v].size() + 64))) report(limits.progress, n, n);
    // Freed here, between progress points, rather than all at once on return.
    std::vector<uint8_t>().swap(best_value[v]);
    std::vector<uint32_t>().swap(later[v]);
  }
  r.value = constant;
  return r;
}

}  // namespace hodt
