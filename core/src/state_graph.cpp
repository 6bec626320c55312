#include "hodt/state_graph.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <string>

#include "hodt/error.hpp"

namespace hodt {

namespace {

struct Ops {
  TermCombine combine;
  Sense sense;
  double zero() const { return 0; }  // every term is >= 0
  double add(double a, double b) const { return hodt::combine(combine, a, b); }
  bool better(double a, double b) const { return sense == Sense::Min ? a < b : a > b; }
};

size_t factor_index(const StateFactor& f, const std::vector<uint32_t>& state) {
  size_t idx = 0, stride = 1;
  for (size_t j = 0; j < f.scope.size(); ++j) {
    idx += stride * f.project[j][state[f.scope[j]]];
    stride *= f.dims[j];
  }
  return idx;
}

// A table over variables (reduced states), read through per-variable maps.
struct Table {
  std::vector<uint32_t> vars;
  std::vector<const std::vector<uint32_t>*> map;  // reduced state -> index digit (nullptr: identity)
  std::vector<uint32_t> dims;
  std::vector<double> values;
};

}  // namespace

void simplify(StateGraph& g, const Progress& progress) {
  const Ops ops{g.combine, g.sense};
  std::vector<StateFactor> kept;
  kept.reserve(g.factors.size());
  double work = 0;
  for (StateFactor& f : g.factors) {
    work += static_cast<double>(f.table.size() * f.scope.size());
    if (progress && !progress(work, 0)) throw Cancelled();
    // Per scope position: classes whose slices of the table are equal are one class.
    for (size_t j = f.scope.size(); j-- > 0;) {
      size_t inner = 1;  // stride of position j
      for (size_t i = 0; i < j; ++i) inner *= f.dims[i];
      const size_t dj = f.dims[j], outer = f.table.size() / (inner * dj);
      std::map<std::vector<double>, uint32_t> ids;
      std::vector<uint32_t> id(dj);
      std::vector<double> slice(inner * outer);
      std::vector<uint32_t> first_of;  // new class -> an old class
      std::vector<uint8_t> used(dj, 0);  // classes no state projects to are dropped
      for (uint32_t c : f.project[j]) used[c] = 1;
      for (size_t c = 0; c < dj; ++c) {
        if (!used[c]) continue;
        for (size_t o = 0; o < outer; ++o)
          for (size_t i = 0; i < inner; ++i) slice[o * inner + i] = f.table[(o * dj + c) * inner + i];
        auto [it, fresh] = ids.try_emplace(slice, static_cast<uint32_t>(first_of.size()));
        if (fresh) first_of.push_back(static_cast<uint32_t>(c));
        id[c] = it->second;
      }
      if (first_of.size() == dj && dj > 1) continue;
      const size_t nd = first_of.size();
      std::vector<double> table(inner * nd * outer);
      for (size_t o = 0; o < outer; ++o)
        for (size_t c = 0; c < nd; ++c)
          for (size_t i = 0; i < inner; ++i) table[(o * nd + c) * inner + i] = f.table[(o * dj + first_of[c]) * inner + i];
      f.table.swap(table);
      for (uint32_t& c : f.project[j]) c = id[c];
      if (nd > 1) {
        f.dims[j] = static_cast<uint32_t>(nd);
      } else {  // the table does not depend on this variable
        f.scope.erase(f.scope.begin() + static_cast<std::ptrdiff_t>(j));
        f.project.erase(f.project.begin() + static_cast<std::ptrdiff_t>(j));
        f.dims.erase(f.dims.begin() + static_cast<std::ptrdiff_t>(j));
      }
    }
    if (f.scope.empty()) {
      g.constant = ops.add(g.constant, f.table[0]);
    } else if (f.scope.size() == 1) {
      auto& u = g.unary[f.scope[0]];
      for (size_t s = 0; s < u.size(); ++s) u[s] = ops.add(u[s], f.table[f.project[0][s]]);
    } else {
      kept.push_back(std::move(f));
    }
  }
  g.factors.swap(kept);
}

double evaluate_states(const StateGraph& g, const std::vector<uint32_t>& state) {
  const Ops ops{g.combine, g.sense};
  double v = g.constant;
  for (size_t x = 0; x < g.domain.size(); ++x) v = ops.add(v, g.unary[x][state[x]]);
  for (const StateFactor& f : g.factors) v = ops.add(v, f.table[factor_index(f, state)]);
  return v;
}

namespace {

// Merges the states of each variable that every factor sees alike, keeping the
// one of best unary value: returns the graph over the kept states (variables
// left with one state drop out of every factor: they would only widen the bags)
// and, per variable, which state each kept one is.
StateGraph merge_states(StateGraph g, std::vector<std::vector<uint32_t>>& kept, const Progress& progress) {
  simplify(g, progress);
  const Ops ops{g.combine, g.sense};
  const uint32_t n = static_cast<uint32_t>(g.domain.size());
  std::vector<std::vector<std::pair<uint32_t, uint32_t>>> seen_by(n);  // (factor, position)
  for (uint32_t i = 0; i < g.factors.size(); ++i)
    for (uint32_t j = 0; j < g.factors[i].scope.size(); ++j) seen_by[g.factors[i].scope[j]].push_back({i, j});
  kept.assign(n, {});
  for (uint32_t x = 0; x < n; ++x) {
    if (progress && (x & 255) == 0 && !progress(x, n)) throw Cancelled();
    std::map<std::vector<uint32_t>, uint32_t> by_signature;
    for (uint32_t s = 0; s < g.domain[x]; ++s) {
      std::vector<uint32_t> sig;
      sig.reserve(seen_by[x].size());
      for (auto [i, j] : seen_by[x]) sig.push_back(g.factors[i].project[j][s]);
      auto [it, fresh] = by_signature.try_emplace(std::move(sig), static_cast<uint32_t>(kept[x].size()));
      if (fresh) kept[x].push_back(s);
      else if (ops.better(g.unary[x][s], g.unary[x][kept[x][it->second]])) kept[x][it->second] = s;
    }
  }
  StateGraph h;
  h.combine = g.combine, h.sense = g.sense, h.constant = g.constant, h.term_max = g.term_max;
  h.unary_terms = g.unary_terms, h.partial = g.partial;
  for (uint32_t x = 0; x < n; ++x) {
    h.domain.push_back(static_cast<uint32_t>(kept[x].size()));
    h.unary.emplace_back();
    for (uint32_t s : kept[x]) h.unary[x].push_back(g.unary[x][s]);
  }
  for (StateFactor& f : g.factors) {
    for (size_t j = 0; j < f.scope.size(); ++j) {
      std::vector<uint32_t> p;
      for (uint32_t s : kept[f.scope[j]]) p.push_back(f.project[j][s]);
      f.project[j].swap(p);
    }
    h.factors.push_back(std::move(f));
  }
  simplify(h, progress);
  return h;
}

// Variable elimination over a min-degree-like order (fewest joint states first).
StateDpResult eliminate(const StateGraph& input, const StateDpLimits& limits) {
  std::vector<std::vector<uint32_t>> original;  // per variable: kept state -> state
  const StateGraph g = merge_states(input, original, limits.progress);
  const Ops ops{g.combine, g.sense};
  const uint32_t n = static_cast<uint32_t>(g.domain.size());
  std::vector<double> dom(n);
  for (uint32_t x = 0; x < n; ++x) dom[x] = g.domain[x];

  // Elimination order: greedily the variable whose bag has the fewest joint states.
  std::vector<std::vector<uint32_t>> adj(n);
  for (const StateFactor& f : g.factors)
    for (uint32_t a : f.scope)
      for (uint32_t b : f.scope)
        if (a != b) adj[a].push_back(b);
  for (auto& a : adj) std::sort(a.begin(), a.end()), a.erase(std::unique(a.begin(), a.end()), a.end());
  auto bag_size = [&](uint32_t v) {
    double s = dom[v];
    for (uint32_t w : adj[v]) s *= dom[w];
    return s;
  };
  using Entry = std::pair<double, uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  for (uint32_t v = 0; v < n; ++v) heap.push({bag_size(v), v});
  std::vector<uint8_t> gone(n, 0);
  std::vector<uint32_t> order;
  std::vector<std::vector<uint32_t>> bags;
  StateDpResult r;
  while (!heap.empty()) {
    const auto [size, v] = heap.top();
    heap.pop();
    if (gone[v] || size != bag_size(v)) continue;  // stale
    if (size > limits.max_table)
      throw LimitError("exact: eliminating a region needs a table of " + std::to_string(static_cast<uint64_t>(size)) +
                       " joint states over " + std::to_string(adj[v].size() + 1) +
                       " regions; the memory cap is " + std::to_string(static_cast<uint64_t>(limits.max_table)));
    gone[v] = 1;
    r.width = std::max(r.width, static_cast<uint32_t>(adj[v].size()));
    r.largest_table = std::max(r.largest_table, size);
    std::vector<uint32_t> bag = {v};
    bag.insert(bag.end(), adj[v].begin(), adj[v].end());
    for (uint32_t a : adj[v]) {
      auto& na = adj[a];
      na.erase(std::lower_bound(na.begin(), na.end(), v));
      std::vector<uint32_t> merged;
      std::set_union(na.begin(), na.end(), adj[v].begin(), adj[v].end(), std::back_inserter(merged));
      merged.erase(std::remove(merged.begin(), merged.end(), a), merged.end());
      na.swap(merged);
      heap.push({bag_size(a), a});
    }
    adj[v].clear();
    order.push_back(v);
    bags.push_back(std::move(bag));
  }
  std::vector<uint32_t> position(n);
  for (uint32_t i = 0; i < n; ++i) position[order[i]] = i;

  // Buckets: each table goes to its earliest-eliminated variable.
  std::vector<std::vector<Table>> bucket(n);
  double constant = g.constant;
  auto place = [&](Table t) {
    uint32_t first = t.vars[0];
    for (uint32_t v : t.vars)
      if (position[v] < position[first]) first = v;
    bucket[first].push_back(std::move(t));
  };
  for (uint32_t x = 0; x < n; ++x) {
    Table t{{x}, {nullptr}, {g.domain[x]}, g.unary[x]};
    place(std::move(t));
  }
  for (uint32_t i = 0; i < g.factors.size(); ++i) {
    Table t{g.factors[i].scope, {}, g.factors[i].dims, g.factors[i].table};
    for (auto& p : g.factors[i].project) t.map.push_back(&p);
    place(std::move(t));
  }

  std::vector<std::vector<uint32_t>> later(n);
  std::vector<std::vector<uint32_t>> best_state(n);
  double work = 0, total_work = 0;
  for (uint32_t i = 0; i < n; ++i) {
    double s = 1;
    for (uint32_t v : bags[i]) s *= dom[v];
    total_work += s;
  }
  std::vector<uint32_t> digit;
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t v = order[i];
    std::vector<uint32_t> bag = bags[i];
    std::sort(bag.begin() + 1, bag.end(), [&](uint32_t a, uint32_t b) { return position[a] < position[b]; });
    const size_t k = bag.size();
    size_t total = 1;
    for (uint32_t b : bag) total *= g.domain[b];
    std::vector<double> combined(total, ops.zero());
    for (const Table& t : bucket[v]) {
      // Per bag position: the table's stride times the digit's class (0 if absent).
      std::vector<std::vector<size_t>> contrib(k);
      size_t stride = 1;
      for (size_t j = 0; j < t.vars.size(); ++j) {
        const size_t pos = static_cast<size_t>(std::find(bag.begin(), bag.end(), t.vars[j]) - bag.begin());
        auto& c = contrib[pos];
        c.resize(g.domain[t.vars[j]]);
        for (size_t s = 0; s < c.size(); ++s) c[s] = stride * (t.map[j] ? (*t.map[j])[s] : s);
        stride *= t.dims[j];
      }
      digit.assign(k, 0);
      size_t ti = 0;
      for (size_t p = 0; p < k; ++p)
        if (!contrib[p].empty()) ti += contrib[p][0];
      for (size_t idx = 0; idx < total; ++idx) {
        if (limits.progress && (idx & 0xFFFF) == 0xFFFF && !limits.progress(work + idx, total_work)) throw Cancelled();
        combined[idx] = ops.add(combined[idx], t.values[ti]);
        // Next joint state: the first digit is the fastest.
        for (size_t p = 0; p < k; ++p) {
          const bool has = !contrib[p].empty();
          if (has) ti -= contrib[p][digit[p]];
          if (++digit[p] < g.domain[bag[p]]) {
            if (has) ti += contrib[p][digit[p]];
            break;
          }
          digit[p] = 0;
          if (has) ti += contrib[p][0];
        }
      }
      work += static_cast<double>(total);
      if (limits.progress && !limits.progress(work, total_work)) throw Cancelled();
    }
    bucket[v].clear();
    bucket[v].shrink_to_fit();
    // Optimise v (the fastest digit) out.
    const size_t dv = g.domain[v], rest = total / dv;
    Table message{std::vector<uint32_t>(bag.begin() + 1, bag.end()), {}, {}, std::vector<double>(rest)};
    for (uint32_t w : message.vars) message.map.push_back(nullptr), message.dims.push_back(g.domain[w]);
    best_state[v].resize(rest);
    for (size_t j = 0; j < rest; ++j) {
      if (limits.progress && (j & 0xFFFF) == 0xFFFF && !limits.progress(work, total_work)) throw Cancelled();
      uint32_t arg = 0;
      for (uint32_t s = 1; s < dv; ++s)
        if (ops.better(combined[j * dv + s], combined[j * dv + arg])) arg = s;
      best_state[v][j] = arg;
      message.values[j] = combined[j * dv + arg];
    }
    later[v] = message.vars;
    if (message.vars.empty()) constant = ops.add(constant, message.values[0]);
    else place(std::move(message));
  }
  // Rebuild in reverse elimination order.
  std::vector<uint32_t> reduced(n, 0);
  for (uint32_t i = n; i-- > 0;) {
    const uint32_t v = order[i];
    size_t idx = 0, stride = 1;
    for (uint32_t w : later[v]) idx += stride * reduced[w], stride *= g.domain[w];
    reduced[v] = best_state[v][idx];
  }
  r.state.resize(n);
  for (uint32_t x = 0; x < n; ++x) r.state[x] = original[x][reduced[x]];
  r.value = constant;
  return r;
}

// The threshold graph: states and table entries whose value is at most t cost 0,
// the others 1 (states over t on their own are dropped). Feasible iff its optimum is 0.
struct Threshold {
  StateGraph graph;
  std::vector<std::vector<uint32_t>> state;  // per variable: new state -> old
  bool empty = false;                         // a variable has no state left
};

Threshold threshold_graph(const StateGraph& g, double t) {
  Threshold th;
  StateGraph& h = th.graph;
  h.combine = TermCombine::Max;
  h.sense = Sense::Min;
  h.constant = g.constant <= t ? 0 : 1;
  const size_t n = g.domain.size();
  th.state.resize(n);
  std::vector<std::vector<uint32_t>> renumber(n);
  for (size_t x = 0; x < n; ++x) {
    renumber[x].assign(g.domain[x], UINT32_MAX);
    for (uint32_t s = 0; s < g.domain[x]; ++s)
      if (g.unary[x][s] <= t) renumber[x][s] = static_cast<uint32_t>(th.state[x].size()), th.state[x].push_back(s);
    if (th.state[x].empty()) th.empty = true;
    h.domain.push_back(static_cast<uint32_t>(th.state[x].size()));
    h.unary.emplace_back(th.state[x].size(), 0.0);
    h.unary_terms.push_back(0);
    h.partial.push_back(0);
  }
  for (const StateFactor& f : g.factors) {
    StateFactor c;
    c.scope = f.scope;
    c.dims = f.dims;
    c.table.resize(f.table.size());
    for (size_t i = 0; i < f.table.size(); ++i) c.table[i] = f.table[i] <= t ? 0 : 1;
    for (size_t j = 0; j < f.scope.size(); ++j) {
      std::vector<uint32_t> p;
      for (uint32_t s : th.state[f.scope[j]]) p.push_back(f.project[j][s]);
      c.project.push_back(std::move(p));
    }
    h.factors.push_back(std::move(c));
  }
  return th;
}

// Min-max: binary search over the values the tables hold, each threshold a
// feasibility DP over 0/1 tables (which merge far more classes than values do).
StateDpResult bottleneck(const StateGraph& g, const StateDpLimits& limits) {
  // Every assignment is at least each table's smallest entry.
  double lo = g.constant;
  auto min_of = [](const std::vector<double>& t) { return *std::min_element(t.begin(), t.end()); };
  for (const auto& u : g.unary) lo = std::max(lo, min_of(u));
  for (const StateFactor& f : g.factors) lo = std::max(lo, min_of(f.table));
  const double hi = evaluate_states(g, std::vector<uint32_t>(g.domain.size(), 0));
  std::vector<double> values = {hi};
  auto collect = [&](const std::vector<double>& t) {
    for (double v : t)
      if (v >= lo && v < hi) values.push_back(v);
  };
  for (const auto& u : g.unary) collect(u);
  for (const StateFactor& f : g.factors) collect(f.table);
  if (g.constant >= lo && g.constant < hi) values.push_back(g.constant);
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  // values.back() == hi is feasible (the assignment of states 0).
  size_t a = 0, b = values.size() - 1;
  StateDpResult best;
  best.state.assign(g.domain.size(), 0);
  while (a < b) {
    const size_t mid = (a + b) / 2;
    const Threshold th = threshold_graph(g, values[mid]);
    bool feasible = false;
    if (!th.empty) {
      const StateDpResult r = eliminate(th.graph, limits);
      best.width = std::max(best.width, r.width);
      best.largest_table = std::max(best.largest_table, r.largest_table);
      if (r.value == 0) {
        feasible = true;
        for (size_t x = 0; x < g.domain.size(); ++x) best.state[x] = th.state[x][r.state[x]];
      }
    }
    if (feasible) b = mid;
    else a = mid + 1;
  }
  best.value = evaluate_states(g, best.state);
  return best;
}

}  // namespace

StateDpResult solve_states(const StateGraph& g, const StateDpLimits& limits) {
  if (g.combine == TermCombine::Max && g.sense == Sense::Min) return bottleneck(g, limits);
  return eliminate(g, limits);
}

std::vector<uint32_t> improve_states(const StateGraph& g, std::vector<uint32_t> x, const Progress& progress) {
  const Ops ops{g.combine, g.sense};
  const uint32_t n = static_cast<uint32_t>(g.domain.size());
  std::vector<std::vector<uint32_t>> factors_of(n);
  for (uint32_t i = 0; i < g.factors.size(); ++i)
    for (uint32_t v : g.factors[i].scope) factors_of[v].push_back(i);
  auto local = [&](uint32_t v) {
    double s = g.unary[v][x[v]];
    for (uint32_t i : factors_of[v]) s = ops.add(s, g.factors[i].table[factor_index(g.factors[i], x)]);
    return s;
  };
  for (int pass = 0; pass < 100; ++pass) {
    bool changed = false;
    for (uint32_t v = 0; v < n; ++v) {
      if (progress && (v & 1023) == 0 && !progress(pass * double(n) + v, 100.0 * n)) throw Cancelled();
      const uint32_t current = x[v];
      double best = local(v);
      uint32_t arg = current;
      for (uint32_t s = 0; s < g.domain[v]; ++s) {
        if (s == current) continue;
        x[v] = s;
        const double val = local(v);
        if (ops.better(val, best)) best = val, arg = s;
      }
      x[v] = arg;
      changed = changed || arg != current;
    }
    if (!changed) break;
  }
  return x;
}

namespace {

// What a term we cannot read may contribute at best.
double unknown(const StateGraph& g, uint64_t terms) {
  if (g.sense == Sense::Min) return 0.0;  // every term is >= 0
  return g.combine == TermCombine::Sum ? g.term_max * static_cast<double>(terms) : g.term_max;
}

// Each factor at its best on its own.
double independent_bound(const StateGraph& g) {
  const Ops ops{g.combine, g.sense};
  auto best_of = [&](const std::vector<double>& t) {
    double b = t[0];
    for (double v : t)
      if (ops.better(v, b)) b = v;
    return b;
  };
  double bound = ops.add(g.constant, unknown(g, g.relaxed_terms));
  for (size_t x = 0; x < g.domain.size(); ++x)
    bound = ops.add(bound, g.partial[x] ? unknown(g, g.unary_terms[x]) : best_of(g.unary[x]));
  for (const StateFactor& f : g.factors) {
    bool partial = false;
    for (uint32_t v : f.scope) partial = partial || g.partial[v];
    bound = ops.add(bound, partial ? unknown(g, f.num_terms) : best_of(f.table));
  }
  return bound;
}

}  // namespace

StateGraph relaxation(const StateGraph& g) {
  const Ops ops{g.combine, g.sense};
  StateGraph h = g;
  h.factors.clear();
  h.constant = ops.add(g.constant, unknown(g, g.relaxed_terms));
  h.relaxed_terms = 0;
  for (size_t x = 0; x < g.domain.size(); ++x) {
    if (!g.partial[x]) continue;
    h.constant = ops.add(h.constant, unknown(g, g.unary_terms[x]));
    h.domain[x] = 1;
    h.unary[x].assign(1, 0.0);
    h.partial[x] = 0;
  }
  for (const StateFactor& f : g.factors) {
    bool partial = false;
    for (uint32_t v : f.scope) partial = partial || g.partial[v];
    if (partial) h.constant = ops.add(h.constant, unknown(g, f.num_terms));
    else h.factors.push_back(f);
  }
  return h;
}

double relaxation_bound(const StateGraph& g, const StateDpLimits& limits) {
  try {
    return solve_states(relaxation(g), limits).value;
  } catch (const LimitError&) {
    return independent_bound(g);
  }
}

}  // namespace hodt
