#include "engines/state_graph.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <string>
#include <unordered_map>

#include "engines/elimination_queue.hpp"
#include "hodt/error.hpp"

namespace hodt {

namespace {

struct Ops {
  Combine combine;
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

// Factor f's classes at position j whose slices of the table are equal made
// one class, the classes no state projects to dropped, and the position
// dropped when one class is left (the table does not depend on it). Returns
// whether anything changed.
bool merge_alike_classes(StateFactor& f, size_t j) {
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
  if (first_of.size() == dj && dj > 1) return false;
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
  return true;
}

}  // namespace

void simplify(StateGraph& g, const Progress& progress) {
  const Ops ops{g.combine, g.sense};
  std::vector<StateFactor> kept;
  kept.reserve(g.factors.size());
  double work = 0;
  for (StateFactor& f : g.factors) {
    work += static_cast<double>(f.table.size() * f.scope.size());
    if (progress && !progress(work, 0)) throw Cancelled();
    // Per scope position; again if anything changed: the first pass leaves no
    // unused class at any position, whose entries could keep apart slices that
    // differ nowhere else (in one pass, the order of the positions changed what
    // was merged, and so the dual's ascent).
    bool changed = false;
    for (size_t j = f.scope.size(); j-- > 0;) changed = merge_alike_classes(f, j) || changed;
    if (changed)
      for (size_t j = f.scope.size(); j-- > 0;) merge_alike_classes(f, j);
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

// The classes of a variable's states that a set of maps cannot tell apart
// (state -> class in `cls`); returns their number.
uint32_t joint_classes(const std::vector<std::pair<const std::vector<uint32_t>*, uint32_t>>& maps, uint32_t dom,
                       std::vector<uint32_t>& cls) {
  cls.assign(dom, 0);
  uint32_t count = 1;
  std::vector<uint32_t> dense;
  std::unordered_map<uint64_t, uint32_t> sparse;
  for (const auto& [map, digits] : maps) {
    uint32_t next = 0;
    if (static_cast<uint64_t>(count) * digits <= 4 * static_cast<uint64_t>(dom) + 64) {
      dense.assign(static_cast<size_t>(count) * digits, UINT32_MAX);
      for (uint32_t s = 0; s < dom; ++s) {
        uint32_t& id = dense[static_cast<size_t>(cls[s]) * digits + (*map)[s]];
        if (id == UINT32_MAX) id = next++;
        cls[s] = id;
      }
    } else {
      sparse.clear();
      for (uint32_t s = 0; s < dom; ++s) {
        const auto [it, fresh] = sparse.try_emplace(static_cast<uint64_t>(cls[s]) << 32 | (*map)[s], next);
        next += fresh;
        cls[s] = it->second;
      }
    }
    count = next;
  }
  return count;
}

// A table's shape: its variables, each read through a map from its states to
// the table's digits (first variable fastest).
struct Shape {
  std::vector<uint32_t> vars;
  std::vector<const std::vector<uint32_t>*> map;  // per variable: state -> digit
  std::vector<uint32_t> dims;
  bool live = true;
};

// Eliminating a variable: its bag is the variables of the live tables that read
// it, each read through the joint classes of those tables' maps (states the bag
// cannot tell apart are one digit), so its table is the product of the class
// counts rather than of the domains.
struct Bag {
  std::vector<uint32_t> tables;
  std::vector<uint32_t> vars;              // the eliminated variable first
  std::vector<std::vector<uint32_t>> cls;  // per variable: state -> class
  std::vector<uint32_t> count;             // classes per variable
  double size = 1;
};

// An elimination order with its bags; table i < factors is factor i, the others
// the messages, one per step that leaves variables (message[step]).
struct Order {
  std::vector<Shape> tables;
  std::deque<Bag> steps;          // (a deque: messages point into the steps' classes)
  std::vector<uint32_t> message;  // per step: the table it makes (UINT32_MAX: none)
  double largest = 0, work = 0;
  uint32_t width = 0;
  bool mini_buckets = false;
};

// The bag of eliminating v from the given tables (all of which read it).
Bag bag_over(const StateGraph& g, const Order& o, uint32_t v, std::vector<uint32_t> tables) {
  Bag b;
  b.tables = std::move(tables);
  b.vars = {v};
  std::vector<std::vector<std::pair<const std::vector<uint32_t>*, uint32_t>>> maps(1);
  for (uint32_t t : b.tables) {
    const Shape& tab = o.tables[t];
    for (size_t j = 0; j < tab.vars.size(); ++j) {
      const size_t p = static_cast<size_t>(std::find(b.vars.begin(), b.vars.end(), tab.vars[j]) - b.vars.begin());
      if (p == b.vars.size()) b.vars.push_back(tab.vars[j]), maps.emplace_back();
      maps[p].push_back({tab.map[j], tab.dims[j]});
    }
  }
  b.cls.resize(b.vars.size());
  for (size_t p = 0; p < b.vars.size(); ++p) {
    b.count.push_back(joint_classes(maps[p], g.domain[b.vars[p]], b.cls[p]));
    b.size *= b.count.back();
  }
  return b;
}

Bag bag_of(const StateGraph& g, const Order& o, const std::vector<std::vector<uint32_t>>& tables_of, uint32_t v) {
  std::vector<uint32_t> live;
  for (uint32_t t : tables_of[v])
    if (o.tables[t].live) live.push_back(t);
  return bag_over(g, o, v, std::move(live));
}

// Mini-buckets: the bag's tables split into groups whose bags fit under `cap`
// (first fit; a table alone always fits: its bag is at most its size), each
// eliminating v on its own. Optimising v separately per group can only do
// better than one v for all, so the result bounds the optimum.
std::vector<Bag> mini_buckets(const StateGraph& g, const Order& o, const Bag& bag, double cap) {
  std::vector<Bag> groups;
  for (uint32_t t : bag.tables) {
    bool placed = false;
    for (Bag& group : groups) {
      std::vector<uint32_t> tables = group.tables;
      tables.push_back(t);
      Bag wider = bag_over(g, o, bag.vars[0], std::move(tables));
      if (wider.size <= cap) {
        group = std::move(wider);
        placed = true;
        break;
      }
    }
    if (!placed) groups.push_back(bag_over(g, o, bag.vars[0], {t}));
  }
  return groups;
}

// A greedy order: the variable whose bag is smallest first. A bag over `cap`
// stops the plan early (largest over the cap), or with `mini`, is split into
// mini-buckets (the plan then bounds the optimum).
Order plan_order(const StateGraph& g, double cap, bool mini, const Progress& progress) {
  const uint32_t n = static_cast<uint32_t>(g.domain.size());
  Order o;
  std::vector<std::vector<uint32_t>> tables_of(n);
  for (const StateFactor& f : g.factors) {
    for (uint32_t x : f.scope) tables_of[x].push_back(static_cast<uint32_t>(o.tables.size()));
    Shape s{f.scope, {}, f.dims};
    for (const auto& p : f.project) s.map.push_back(&p);
    o.tables.push_back(std::move(s));
  }
  // The smallest table first; each variable's bag as last offered.
  EliminationQueue<double> queue(n);
  std::vector<Bag> current(n);
  auto offer = [&](uint32_t v) {
    current[v] = bag_of(g, o, tables_of, v);
    queue.offer(v, current[v].size);
  };
  for (uint32_t v = 0; v < n; ++v) offer(v);
  for (uint32_t v; (v = queue.next()) != UINT32_MAX;) {
    if (progress && (o.steps.size() & 255) == 0 && !progress(0, 1)) throw Cancelled();
    Bag bag = std::move(current[v]);
    if (bag.size > cap && !mini) {
      o.largest = bag.size;
      return o;
    }
    for (uint32_t t : bag.tables) o.tables[t].live = false;
    std::vector<Bag> groups;
    if (bag.size > cap) groups = mini_buckets(g, o, bag, cap), o.mini_buckets = true;
    else groups.push_back(std::move(bag));
    for (Bag& group : groups) {
      o.largest = std::max(o.largest, group.size);
      o.width = std::max(o.width, static_cast<uint32_t>(group.vars.size() - 1));
      o.work += group.size * static_cast<double>(group.tables.size() + 2);
      o.steps.push_back(std::move(group));
      const Bag& b = o.steps.back();
      o.message.push_back(UINT32_MAX);
      if (b.vars.size() == 1) continue;
      Shape m{{b.vars.begin() + 1, b.vars.end()}, {}, {b.count.begin() + 1, b.count.end()}};
      for (size_t p = 1; p < b.cls.size(); ++p) m.map.push_back(&b.cls[p]);
      o.message.back() = static_cast<uint32_t>(o.tables.size());
      for (uint32_t w : m.vars) tables_of[w].push_back(o.message.back());
      o.tables.push_back(std::move(m));
      for (uint32_t w : o.tables.back().vars)
        if (!queue.eliminated(w)) offer(w);
    }
  }
  return o;
}

// Variable elimination over a greedy order. (States that no table tells apart
// need no merging first: each bag reads its variables through their classes.)
StateDpResult eliminate(const StateGraph& input, const StateDpLimits& limits) {
  StateGraph g = input;
  simplify(g, limits.progress);
  const Ops ops{g.combine, g.sense};
  const uint32_t n = static_cast<uint32_t>(g.domain.size());
  Order order = plan_order(g, limits.max_table, limits.mini_buckets, limits.progress);
  if (order.largest > limits.max_table && !limits.mini_buckets)  // (mini-buckets: only single tables, already built)
    throw LimitError("exact: eliminating a region needs a table of " + std::to_string(static_cast<uint64_t>(order.largest)) +
                     " joint states; the memory cap is " + std::to_string(static_cast<uint64_t>(limits.max_table)));
  StateDpResult r;
  r.bound_only = order.mini_buckets;
  r.width = order.width;
  r.largest_table = order.largest;

  // Fill the tables in that order; per step, the best class of the eliminated
  // variable for each joint class of the others, and per class its best state.
  std::vector<std::vector<double>> values(order.tables.size());
  auto values_of = [&](uint32_t t) -> const std::vector<double>& { return t < g.factors.size() ? g.factors[t].table : values[t]; };
  double constant = g.constant, work = 0;
  std::vector<std::vector<uint32_t>> best_class(order.steps.size()), best_state(order.steps.size());
  std::vector<uint32_t> digit;
  std::vector<uint8_t> unary_read(n, 0);
  for (size_t step = 0; step < order.steps.size(); ++step) {
    const Bag& bag = order.steps[step];
    const uint32_t v = bag.vars[0];
    const size_t k = bag.vars.size(), c0 = bag.count[0];
    size_t total = 1;
    for (uint32_t c : bag.count) total *= c;
    // A representative state per class, and v's best unary per class.
    std::vector<std::vector<uint32_t>> rep(k);
    for (size_t p = 0; p < k; ++p) {
      rep[p].assign(bag.count[p], UINT32_MAX);
      for (uint32_t s = 0; s < bag.cls[p].size(); ++s)
        if (rep[p][bag.cls[p][s]] == UINT32_MAX) rep[p][bag.cls[p][s]] = s;
    }
    auto& arg = best_state[step];
    arg = rep[0];
    for (uint32_t s = 0; s < g.domain[v]; ++s)
      if (ops.better(g.unary[v][s], g.unary[v][arg[bag.cls[0][s]]])) arg[bag.cls[0][s]] = s;
    // (v's unary once: in its first mini-bucket)
    std::vector<double> combined(total, ops.zero());
    if (!unary_read[v]) {
      unary_read[v] = 1;
      for (size_t idx = 0; idx < total; ++idx) combined[idx] = g.unary[v][arg[idx % c0]];
    }
    for (uint32_t t : bag.tables) {
      const Shape& tab = order.tables[t];
      const std::vector<double>& tv = values_of(t);
      // Per bag position: the table's stride times the digit of each class (none if absent).
      std::vector<std::vector<size_t>> contrib(k);
      size_t stride = 1;
      for (size_t j = 0; j < tab.vars.size(); ++j) {
        const size_t p = static_cast<size_t>(std::find(bag.vars.begin(), bag.vars.end(), tab.vars[j]) - bag.vars.begin());
        contrib[p].resize(bag.count[p]);
        for (size_t c = 0; c < bag.count[p]; ++c) contrib[p][c] = stride * (*tab.map[j])[rep[p][c]];
        stride *= tab.dims[j];
      }
      // Row by row of the first digit (the fastest), the others carried per row;
      // the sum or max chosen once, outside the loop.
      std::vector<size_t> first = contrib[0];
      if (first.empty()) first.assign(c0, 0);
      digit.assign(k, 0);
      size_t ti = 0;  // the table index of the row's other digits
      for (size_t p = 1; p < k; ++p)
        if (!contrib[p].empty()) ti += contrib[p][0];
      const auto rows = [&](auto add) {
        for (size_t row = 0; row < total; row += c0) {
          if (limits.progress && (row & 0xFFFF) < c0 && row && !limits.progress(work + row, order.work)) throw Cancelled();
          double* out = combined.data() + row;
          const double* in = tv.data() + ti;
          for (size_t d = 0; d < c0; ++d) out[d] = add(out[d], in[first[d]]);
          for (size_t p = 1; p < k; ++p) {  // next row
            const bool has = !contrib[p].empty();
            if (has) ti -= contrib[p][digit[p]];
            if (++digit[p] < bag.count[p]) {
              if (has) ti += contrib[p][digit[p]];
              break;
            }
            digit[p] = 0;
            if (has) ti += contrib[p][0];
          }
        }
      };
      if (g.combine == Combine::Sum) rows([](double a, double b) { return a + b; });
      else rows([&](double a, double b) { return ops.add(a, b); });
      work += static_cast<double>(total);
      if (limits.progress && !limits.progress(work, order.work)) throw Cancelled();
      if (t >= g.factors.size()) std::vector<double>().swap(values[t]);  // (read once)
    }
    // Optimise v (the fastest digit) out.
    const size_t rest = total / c0;
    std::vector<double> out(rest);
    best_class[step].resize(rest);
    for (size_t j = 0; j < rest; ++j) {
      uint32_t a = 0;
      for (uint32_t c = 1; c < c0; ++c)
        if (ops.better(combined[j * c0 + c], combined[j * c0 + a])) a = c;
      best_class[step][j] = a;
      out[j] = combined[j * c0 + a];
    }
    work += static_cast<double>(total);
    if (order.message[step] == UINT32_MAX) constant = ops.add(constant, out[0]);
    else values[order.message[step]] = std::move(out);
  }
  // Rebuild in reverse elimination order: each step's message reads only
  // variables eliminated after it.
  r.state.assign(n, 0);
  for (size_t i = order.steps.size(); i-- > 0;) {
    const Bag& bag = order.steps[i];
    size_t idx = 0, stride = 1;
    for (size_t p = 1; p < bag.vars.size(); ++p) {
      idx += stride * bag.cls[p][r.state[bag.vars[p]]];
      stride *= bag.count[p];
    }
    r.state[bag.vars[0]] = best_state[i][best_class[i][idx]];
  }
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

// top: per factor, its largest entry (a factor at most t everywhere is left out:
// every assignment meets it).
Threshold threshold_graph(const StateGraph& g, double t, const std::vector<double>& top) {
  Threshold th;
  StateGraph& h = th.graph;
  h.combine = Combine::Max;
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
  for (size_t fi = 0; fi < g.factors.size(); ++fi) {
    const StateFactor& f = g.factors[fi];
    if (top[fi] <= t) continue;
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
  std::vector<double> top;
  for (const StateFactor& f : g.factors) top.push_back(*std::max_element(f.table.begin(), f.table.end()));
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
  // Galloping up from the bottom, then bisecting: the optimum is most often
  // the worst term every assignment has, or a few values above it, which
  // galloping reaches in fewer probes than bisecting the whole range.
  size_t a = 0, b = values.size() - 1, step = 1;
  StateDpResult best;
  best.state.assign(g.domain.size(), 0);
  while (a < b) {
    const size_t mid = std::min(a + step - 1, (a + b) / 2);
    const Threshold th = threshold_graph(g, values[mid], top);
    bool feasible = false;
    if (!th.empty) {
      const StateDpResult r = eliminate(th.graph, limits);
      best.width = std::max(best.width, r.width);
      best.bound_only = best.bound_only || r.bound_only;
      best.largest_table = std::max(best.largest_table, r.largest_table);
      if (r.value == 0) {
        feasible = true;
        for (size_t x = 0; x < g.domain.size(); ++x) best.state[x] = th.state[x][r.state[x]];
      }
    }
    if (feasible) b = mid, step = b - a;  // (from now on bisecting)
    else a = mid + 1, step *= 2;
  }
  // (with mini-buckets, an infeasible verdict is still a proof: the threshold
  // found bounds the optimum)
  best.value = best.bound_only ? values[b] : evaluate_states(g, best.state);
  return best;
}

}  // namespace

StateDpResult solve_states(const StateGraph& g, const StateDpLimits& limits) {
  if (g.combine == Combine::Max && g.sense == Sense::Min) return bottleneck(g, limits);
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

std::vector<uint32_t> improve_by_windows(const StateGraph& g, std::vector<uint32_t> x, const StateDpLimits& limits,
                                         uint32_t window) {
  const uint32_t n = static_cast<uint32_t>(g.domain.size());
  std::vector<std::vector<uint32_t>> factors_of(n), neighbours(n);
  for (uint32_t i = 0; i < g.factors.size(); ++i)
    for (uint32_t v : g.factors[i].scope) {
      factors_of[v].push_back(i);
      for (uint32_t w : g.factors[i].scope)
        if (w != v) neighbours[v].push_back(w);
    }
  std::vector<uint32_t> local(n, UINT32_MAX);
  std::vector<uint32_t> in_window(g.factors.size(), 0);  // per factor: the last window that took it
  uint32_t window_id = 0;
  // Min-max: a window whose worst term is below the whole's cannot lower the
  // whole's (its search would only rearrange terms that do not count).
  const Ops ops{g.combine, g.sense};
  const bool max_only = g.combine == Combine::Max;
  double whole = max_only ? evaluate_states(g, x) : 0.0;
  for (int pass = 0;; ++pass) {
    bool improved = false;
    const double whole_before = whole;
    std::vector<uint8_t> covered(n, 0);
    for (uint32_t seed = 0; seed < n; ++seed) {
      if (covered[seed] || g.domain[seed] < 2) continue;
      if (limits.progress && !limits.progress(std::min(pass, 1) * double(n) + seed, 2.0 * n)) throw Cancelled();
      // The window: a breadth-first ball of variables with a choice.
      std::vector<uint32_t> ball = {seed};
      local[seed] = 0;
      for (size_t head = 0; head < ball.size() && ball.size() < window; ++head)
        for (uint32_t w : neighbours[ball[head]])
          if (local[w] == UINT32_MAX && g.domain[w] > 1 && ball.size() < window) {
            local[w] = static_cast<uint32_t>(ball.size());
            ball.push_back(w);
          }
      // The factors that read the ball, and what the ball's terms come to now
      // (read off g: a window that is skipped builds nothing).
      ++window_id;
      std::vector<uint32_t> read;
      double now = ops.zero();
      for (uint32_t v : ball) {
        now = ops.add(now, g.unary[v][x[v]]);
        for (uint32_t i : factors_of[v])
          if (in_window[i] != window_id) {
            in_window[i] = window_id;
            read.push_back(i);
            now = ops.add(now, g.factors[i].table[factor_index(g.factors[i], x)]);
          }
      }
      if (max_only && ops.better(now, whole)) {
        for (uint32_t v : ball) covered[v] = 1, local[v] = UINT32_MAX;
        continue;
      }
      // Its graph: the ball's variables, and those factors with every other
      // variable fixed at x (a variable of one state).
      StateGraph h;
      h.combine = g.combine, h.sense = g.sense, h.term_max = g.term_max;
      for (uint32_t v : ball) {
        h.domain.push_back(g.domain[v]);
        h.unary.push_back(g.unary[v]);
      }
      std::vector<uint32_t> fixed;
      for (uint32_t i : read) {
        StateFactor f = g.factors[i];
        for (size_t j = 0; j < f.scope.size(); ++j) {
          uint32_t& w = f.scope[j];
          if (local[w] == UINT32_MAX) {
            f.project[j] = {f.project[j][x[w]]};
            fixed.push_back(w);
            local[w] = static_cast<uint32_t>(h.domain.size());
            h.domain.push_back(1);
            h.unary.push_back({0.0});
          } else if (local[w] >= ball.size()) {
            f.project[j] = {f.project[j][x[w]]};
          }
          w = local[w];
        }
        h.factors.push_back(std::move(f));
      }
      h.unary_terms.assign(h.domain.size(), 0);
      h.partial.assign(h.domain.size(), 0);
      try {
        const StateDpResult r = solve_states(h, limits);
        if (ops.better(r.value, now)) {
          for (size_t i = 0; i < ball.size(); ++i) x[ball[i]] = r.state[i];
          improved = true;
          if (max_only) whole = evaluate_states(g, x);
        }
      } catch (const LimitError&) {
      }
      for (uint32_t v : ball) covered[v] = 1, local[v] = UINT32_MAX;
      for (uint32_t w : fixed) local[w] = UINT32_MAX;
    }
    // Two passes; min-max, more while a pass lowers the whole's worst term (the
    // windows it skipped before may hold it now; it takes finitely many values).
    if (!improved || (pass >= 1 && !(max_only && ops.better(whole, whole_before)))) break;
  }
  return x;
}

namespace {

// What a term we cannot read may contribute at best.
double unknown(const StateGraph& g, uint64_t terms) {
  if (g.sense == Sense::Min) return 0.0;  // every term is >= 0
  return g.combine == Combine::Sum ? g.term_max * static_cast<double>(terms) : g.term_max;
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
  StateGraph h;  // (g but its factors: those are copied once, below)
  h.combine = g.combine, h.sense = g.sense, h.term_max = g.term_max;
  h.domain = g.domain, h.unary = g.unary, h.unary_terms = g.unary_terms, h.partial = g.partial;
  h.factors.reserve(g.factors.size());
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

double relaxation_bound(const StateGraph& g, StateDpLimits limits) {
  limits.mini_buckets = true;
  const StateDpResult r = solve_states(relaxation(g), limits);
  return r.bound_only ? tighter(g.sense, r.value, independent_bound(g)) : r.value;
}

bool none_below(const StateGraph& g, double t, const Progress& progress) {
  if (g.combine != Combine::Max || g.sense != Sense::Min) return false;
  if (!(g.constant < t)) return true;
  const size_t n = g.domain.size();
  std::vector<std::vector<uint8_t>> alive(n);
  for (size_t x = 0; x < n; ++x) {
    alive[x].resize(g.domain[x]);
    bool any = false;
    for (uint32_t s = 0; s < g.domain[x]; ++s) any |= alive[x][s] = g.unary[x][s] < t;
    if (!any) return true;
  }
  std::vector<std::vector<uint32_t>> touching(n);
  for (uint32_t fi = 0; fi < g.factors.size(); ++fi)
    for (uint32_t x : g.factors[fi].scope) touching[x].push_back(fi);
  std::deque<uint32_t> work;
  std::vector<uint8_t> queued(g.factors.size(), 1);
  for (uint32_t fi = 0; fi < g.factors.size(); ++fi) work.push_back(fi);
  uint64_t visits = 0;
  std::vector<std::vector<uint8_t>> live, supported;
  std::vector<uint32_t> digit;
  while (!work.empty()) {
    if (progress && (++visits & 255) == 0 && !progress(static_cast<double>(visits), static_cast<double>(visits + work.size())))
      throw Cancelled();
    const uint32_t fi = work.front();
    work.pop_front();
    queued[fi] = 0;
    const StateFactor& f = g.factors[fi];
    const size_t m = f.scope.size();
    live.assign(m, {});
    supported.assign(m, {});
    for (size_t j = 0; j < m; ++j) {
      live[j].assign(f.dims[j], 0);
      supported[j].assign(f.dims[j], 0);
      for (uint32_t s = 0; s < g.domain[f.scope[j]]; ++s)
        if (alive[f.scope[j]][s]) live[j][f.project[j][s]] = 1;
    }
    // Every entry below t over live classes supports its classes (first variable fastest).
    bool some = false;
    digit.assign(m, 0);
    for (size_t e = 0; e < f.table.size(); ++e) {
      if (e)
        for (size_t j = 0; j < m && ++digit[j] == f.dims[j]; ++j) digit[j] = 0;
      if (!(f.table[e] < t)) continue;
      bool ok = true;
      for (size_t j = 0; j < m && ok; ++j) ok = live[j][digit[j]];
      if (!ok) continue;
      some = true;
      for (size_t j = 0; j < m; ++j) supported[j][digit[j]] = 1;
    }
    if (!some) return true;
    for (size_t j = 0; j < m; ++j) {
      const uint32_t x = f.scope[j];
      bool changed = false, any = false;
      for (uint32_t s = 0; s < g.domain[x]; ++s) {
        if (alive[x][s] && !supported[j][f.project[j][s]]) alive[x][s] = 0, changed = true;
        any |= alive[x][s];
      }
      if (!any) return true;
      if (changed)
        for (uint32_t other : touching[x])
          if (!queued[other]) queued[other] = 1, work.push_back(other);
    }
  }
  return false;
}

}  // namespace hodt
