#include "engines/dual_bound.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "hodt/error.hpp"

namespace hodt {

namespace {

// Messages are multiples of 2^-20 and every value (each message, unary,
// table entry and the bound's terms) stays below 2^31 in magnitude, so each
// sum of two of them is exact in a double (53 bits); a value outside ends the
// ascent without a bound.
constexpr int kGridBits = 20;
constexpr double kLargest = 0x1p31;

double on_grid(double x) { return std::ldexp(std::nearbyint(std::ldexp(x, kGridBits)), -kGridBits); }
bool small_integer(double v) { return std::isfinite(v) && v == std::nearbyint(v) && std::fabs(v) < 0x1p24; }

// Per table entry, its class at each scope position (first position fastest).
template <class Visit>
void for_entries(const StateFactor& f, Visit visit) {
  std::vector<uint32_t> c(f.scope.size(), 0);
  for (size_t e = 0; e < f.table.size(); ++e) {
    visit(e, c);
    for (size_t j = 0; j < c.size(); ++j) {
      if (++c[j] < f.dims[j]) break;
      c[j] = 0;
    }
  }
}

// A factor's table in rows along its first scope position (stride 1): per
// row, its first entry, its classes at the other positions, and the sum of
// w[j][class] over those (the ascent's inner loops then add one term per entry,
// where a pass per position would read the whole table m times). leave(j) is
// called as position j (from 1) is about to change class, and for each at the end.
template <class Row, class Leave>
void for_rows(const StateFactor& f, const std::vector<std::vector<double>>& w, Row row, Leave leave) {
  const size_t m = f.dims.size();
  const size_t d0 = m ? f.dims[0] : 1;
  std::vector<uint32_t> c(m, 0);
  // rest[j]: the sum over positions j.. (from 1) at their current classes,
  // recomputed only below the position that moved.
  std::vector<double> rest(m + 1, 0.0);
  for (size_t j = m; j-- > 1;) rest[j] = rest[j + 1] + w[j][0];
  for (size_t o = 0; o < f.table.size(); o += d0) {
    row(o, c, m > 1 ? rest[1] : 0.0);
    size_t j = 1;
    for (; j < m; ++j) {
      leave(j, c[j]);
      if (++c[j] < f.dims[j]) break;
      c[j] = 0;
    }
    if (j >= m) break;
    for (size_t i = j; i >= 1; --i) rest[i] = rest[i + 1] + w[i][c[i]];
  }
}

// A factor position's states grouped by class: class c's are
// state[start[c]] .. state[start[c + 1] - 1].
struct ClassStates {
  std::vector<uint32_t> start, state;
  explicit ClassStates(const std::vector<uint32_t>& project, uint32_t classes) : start(classes + 1, 0), state(project.size()) {
    for (uint32_t c : project) ++start[c + 1];
    for (uint32_t c = 0; c < classes; ++c) start[c + 1] += start[c];
    std::vector<uint32_t> at(start.begin(), start.end() - 1);
    for (uint32_t s = 0; s < project.size(); ++s) state[at[project[s]]++] = s;
  }
};

// The ascent on a simplified graph, in min form (every value times `sign`).
struct Ascent {
  const StateGraph& g;
  std::vector<const ImplicitFactor*> implicit;
  double sign;
  std::vector<std::vector<double>> unary;             // reparametrised, per variable and state
  // Per factor (the tables, then the implicit ones), scope position and class.
  std::vector<std::vector<std::vector<double>>> msg;
  // Per factor: its least reparametrised entry; 0 while stale (an MPLP
  // update leaves the least entry 0, but for the messages' rounding to the
  // grid: settle() makes them exact).
  std::vector<double> factor_least;
  std::vector<uint8_t> stale;
  // Updates are numbered: per variable the last that changed a message to it,
  // per factor its last.
  uint64_t clock = 1;
  std::vector<uint64_t> changed, updated;
  bool in_range = true;
  std::vector<std::vector<ClassStates>> classes;  // per table factor and scope position
  std::vector<std::vector<double>> u_, marginal_;  // (the update's scratch)

  Ascent(const StateGraph& graph, std::vector<const ImplicitFactor*> implicit_factors)
      : g(graph), implicit(std::move(implicit_factors)), sign(graph.sense == Sense::Min ? 1.0 : -1.0) {
    for (const auto& u : g.unary) {
      unary.emplace_back(u);
      for (double& v : unary.back()) v *= sign;
    }
    for (const StateFactor& f : g.factors) {
      msg.emplace_back();
      classes.emplace_back();
      for (size_t j = 0; j < f.dims.size(); ++j) {
        msg.back().emplace_back(f.dims[j], 0.0);
        classes.back().emplace_back(f.project[j], f.dims[j]);
      }
    }
    for (const ImplicitFactor* f : implicit) {
      msg.emplace_back();
      for (uint32_t x : f->scope) msg.back().emplace_back(g.domain[x], 0.0);
    }
    factor_least.resize(msg.size());
    stale.assign(msg.size(), 0);
    for (size_t fi = 0; fi < msg.size(); ++fi) set_least(fi);
    changed.assign(g.domain.size(), 1);
    updated.assign(msg.size(), 0);
  }

  // The same block update for an implicit factor (its classes are the states).
  void update_implicit(size_t fi) {
    const ImplicitFactor& f = *implicit[fi - g.factors.size()];
    const size_t m = f.scope.size();
    if (std::all_of(f.scope.begin(), f.scope.end(), [&](uint32_t x) { return changed[x] <= updated[fi]; })) return;
    updated[fi] = ++clock;
    std::vector<std::vector<double>> u(m), marginal;
    for (size_t j = 0; j < m; ++j) {
      u[j] = unary[f.scope[j]];
      for (size_t s = 0; s < u[j].size(); ++s) u[j][s] -= msg[fi][j][s];
    }
    f.least(u, &marginal);
    send(fi, f.scope, nullptr, marginal, u);
  }

  // MPLP's messages from factor fi to its scope (by_class: per position, its
  // states by class; null: the classes are the states): each variable gets its
  // equal share of the min-marginals, less what it holds besides.
  void send(size_t fi, const std::vector<uint32_t>& scope, const std::vector<ClassStates>* by_class,
            const std::vector<std::vector<double>>& marginal, const std::vector<std::vector<double>>& u) {
    const size_t m = scope.size();
    for (size_t j = 0; j < m; ++j) {
      std::vector<double>& old = msg[fi][j];
      std::vector<double>& ux = unary[scope[j]];
      bool any = false;
      for (size_t c = 0; c < old.size(); ++c) {
        const double next = on_grid(marginal[j][c] / static_cast<double>(m) - u[j][c]);
        // (so a table entry less all its m messages stays below 2^31 at every step)
        if (!(std::fabs(next) * static_cast<double>(2 * (m + 1)) < kLargest)) in_range = false;
        if (!in_range) return;
        if (next == old[c]) continue;
        const double delta = next - old[c];
        old[c] = next;
        any = true;
        auto add = [&](uint32_t s) {
          ux[s] += delta;
          if (!(std::fabs(ux[s]) < kLargest)) in_range = false;
        };
        if (!by_class) {
          add(static_cast<uint32_t>(c));
          continue;
        }
        const ClassStates& k = (*by_class)[j];
        for (uint32_t i = k.start[c]; i < k.start[c + 1]; ++i) add(k.state[i]);
      }
      if (any) changed[scope[j]] = clock;
    }
    factor_least[fi] = 0;
    stale[fi] = 1;
  }

  // Every factor's least entry exact again.
  void settle() {
    for (size_t fi = 0; fi < msg.size(); ++fi)
      if (stale[fi]) set_least(fi), stale[fi] = 0;
  }

  // Factor fi's table less its messages, entry by entry: visit(entry, value).
  // (Exact: dyadic values in range; one pass along rows, for_rows.)
  template <class Visit>
  void for_reparametrised(size_t fi, Visit visit) const {
    const StateFactor& f = g.factors[fi];
    if (f.dims.empty()) return visit(size_t(0), sign * f.table[0]);
    const size_t d0 = f.dims[0];
    const double* m0 = msg[fi][0].data();
    for_rows(
        f, msg[fi],
        [&](size_t o, const std::vector<uint32_t>&, double rest) {
          for (size_t i = 0; i < d0; ++i) visit(o + i, sign * f.table[o + i] - m0[i] - rest);
        },
        [](size_t, uint32_t) {});
  }
  std::vector<double> reparametrised(size_t fi) const {
    std::vector<double> t(g.factors[fi].table.size());
    for_reparametrised(fi, [&](size_t e, double v) { t[e] = v; });
    return t;
  }

  // MPLP's block update of one factor: everything its variables hold (their
  // best state per class, its own message taken back) joins the table, and the
  // table's min-marginals go back to the variables in equal shares. The bound
  // never falls (the minimum of a sum is at least the sum of the minima).
  // (Not inlined, nor set_least: inlined into raise, one long call for a whole
  // ascent, the sweeps are slower in wasm. V8 optimises a wasm function only
  // after calls to it, and huge functions less well.)
  [[gnu::noinline]] void update(size_t fi, WorkCounter& work, const Progress& progress, double sweep, double sweeps) {
    if (fi >= g.factors.size()) return update_implicit(fi);
    const StateFactor& f = g.factors[fi];
    const size_t m = f.scope.size();
    // The update reads only the other factors' messages at its variables: if
    // none changed since its last update, it would change nothing.
    if (std::all_of(f.scope.begin(), f.scope.end(), [&](uint32_t x) { return changed[x] <= updated[fi]; })) return;
    updated[fi] = ++clock;
    std::vector<std::vector<double>>& u = u_;
    std::vector<std::vector<double>>& marginal = marginal_;
    u.resize(std::max(u.size(), m)), marginal.resize(std::max(marginal.size(), m));
    double size = 0;
    for (size_t j = 0; j < m; ++j) {
      const std::vector<double>& ux = unary[f.scope[j]];
      const ClassStates& k = classes[fi][j];
      u[j].resize(f.dims[j]);
      for (uint32_t c = 0; c < f.dims[j]; ++c) {
        double least = INFINITY;
        for (uint32_t i = k.start[c]; i < k.start[c + 1]; ++i) least = std::min(least, ux[k.state[i]]);
        u[j][c] = least - msg[fi][j][c];
      }
      marginal[j].assign(f.dims[j], INFINITY);
      size += static_cast<double>(ux.size());
    }
    if (work.tick(size + static_cast<double>(m * f.table.size()))) report(progress, sweep, sweeps);
    // The table plus what its variables hold, and its least entry per class
    // of each position: position 0 along each row, the others from the least
    // of the rows since their class last changed. (Every value is dyadic and
    // in range, so sums are exact in any order.)
    if (m) {
      const size_t d0 = f.dims[0];
      const double* u0 = u[0].data();
      double* m0 = marginal[0].data();
      std::vector<double> low(m + 1, INFINITY);  // per position from 1: least since its class last changed
      for_rows(
          f, u,
          [&](size_t o, const std::vector<uint32_t>&, double rest) {
            const double* t = f.table.data() + o;
            double row = INFINITY;
            for (size_t i = 0; i < d0; ++i) {
              const double v = sign * t[i] + u0[i] + rest;
              m0[i] = std::min(m0[i], v);
              row = std::min(row, v);
            }
            low[1] = std::min(low[1], row);
          },
          [&](size_t j, uint32_t c) {
            marginal[j][c] = std::min(marginal[j][c], low[j]);
            low[j + 1] = std::min(low[j + 1], low[j]);
            low[j] = INFINITY;
          });
    }
    send(fi, f.scope, &classes[fi], marginal, u);
  }

  // Factor fi's least reparametrised entry (every entry checked in range).
  [[gnu::noinline]] void set_least(size_t fi) {
    if (fi >= g.factors.size()) {  // (exact: its paths add at most m messages, each below 2^31 / (2m + 2))
      std::vector<std::vector<double>> costs = msg[fi];
      for (auto& c : costs)
        for (double& v : c) v = -v;
      factor_least[fi] = implicit[fi - g.factors.size()]->least(costs, nullptr);
      if (!(std::fabs(factor_least[fi]) < kLargest)) in_range = false;
      return;
    }
    double least = INFINITY, most = -INFINITY;  // (the values are finite: tables and messages are)
    for_reparametrised(fi, [&](size_t, double v) { least = std::min(least, v), most = std::max(most, v); });
    if (!(least > -kLargest && most < kLargest)) in_range = false;
    factor_least[fi] = least;
  }

  // The bound: each piece at its best, summed exactly (nothing when a value
  // left the exact range); an estimate while a factor is stale.
  std::optional<double> bound() const {
    double total = sign * g.constant, magnitude = std::fabs(total);
    for (const auto& u : unary) {
      const double b = *std::min_element(u.begin(), u.end());
      total += b, magnitude += std::fabs(b);
    }
    for (double b : factor_least) total += b, magnitude += std::fabs(b);
    if (!in_range || !(magnitude < kLargest)) return std::nullopt;
    return total;
  }
};

// Factors that share variables, joined into one table while it stays within
// `max_entries`: the relaxation then holds each cluster's joint, not only its
// factors' (cycles inside a cluster are exact), and its bound is tighter.
StateGraph clustered(const StateGraph& g, double max_entries, const Progress& progress) {
  const size_t nf = g.factors.size();
  std::vector<std::vector<uint32_t>> factors_of(g.domain.size());
  for (uint32_t i = 0; i < nf; ++i)
    for (uint32_t x : g.factors[i].scope) factors_of[x].push_back(i);
  StateGraph h = g;
  h.factors.clear();
  std::vector<uint8_t> taken(nf, 0);
  std::vector<uint32_t> pair;  // joint class ids
  for (uint32_t seed = 0; seed < nf; ++seed) {
    if (taken[seed]) continue;
    report(progress, seed, static_cast<double>(nf));
    // The cluster: its factors, and per variable its joint classes.
    std::vector<uint32_t> members;
    StateFactor c;
    auto join = [&](const StateFactor& f, bool commit) {
      double size = 1;
      std::vector<std::pair<size_t, uint32_t>> counts;  // (cluster position or new, count)
      for (size_t j = 0; j < f.scope.size(); ++j) {
        const size_t p = static_cast<size_t>(std::find(c.scope.begin(), c.scope.end(), f.scope[j]) - c.scope.begin());
        if (p == c.scope.size()) {
          size *= f.dims[j];
          if (commit) c.scope.push_back(f.scope[j]), c.project.push_back(f.project[j]), c.dims.push_back(f.dims[j]);
          continue;
        }
        const uint32_t d = f.dims[j];
        pair.assign(static_cast<size_t>(c.dims[p]) * d, UINT32_MAX);
        uint32_t next = 0;
        std::vector<uint32_t> joint(c.project[p].size());
        for (size_t s = 0; s < joint.size(); ++s) {
          uint32_t& id = pair[static_cast<size_t>(c.project[p][s]) * d + f.project[j][s]];
          if (id == UINT32_MAX) id = next++;
          joint[s] = id;
        }
        counts.push_back({p, next});
        if (commit) c.project[p].swap(joint), c.dims[p] = next;
      }
      if (!commit)
        for (size_t p = 0; p < c.scope.size(); ++p) {
          const auto it = std::find_if(counts.begin(), counts.end(), [&](const auto& q) { return q.first == p; });
          size *= it == counts.end() ? c.dims[p] : it->second;
        }
      return size;
    };
    join(g.factors[seed], true);
    members.push_back(seed);
    taken[seed] = 1;
    for (size_t head = 0; head < members.size(); ++head)
      for (uint32_t x : g.factors[members[head]].scope)
        for (uint32_t f : factors_of[x]) {
          if (taken[f] || join(g.factors[f], false) > max_entries) continue;
          join(g.factors[f], true);
          members.push_back(f);
          taken[f] = 1;
        }
    // Its table: per entry, the members' values at a state of each class.
    std::vector<std::vector<uint32_t>> rep(c.scope.size());
    size_t entries = 1;
    for (size_t p = 0; p < c.scope.size(); ++p) {
      rep[p].assign(c.dims[p], 0);
      for (uint32_t s = 0; s < c.project[p].size(); ++s) rep[p][c.project[p][s]] = s;
      entries *= c.dims[p];
    }
    c.table.assign(entries, 0.0);
    c.num_terms = 0;
    std::vector<uint32_t> state(g.domain.size(), 0);
    for_entries(c, [&](size_t e, const std::vector<uint32_t>& cl) {
      for (size_t p = 0; p < cl.size(); ++p) state[c.scope[p]] = rep[p][cl[p]];
      for (uint32_t f : members) {
        const StateFactor& m = g.factors[f];
        size_t idx = 0, stride = 1;
        for (size_t j = 0; j < m.scope.size(); ++j) idx += stride * m.project[j][state[m.scope[j]]], stride *= m.dims[j];
        c.table[e] += m.table[idx];
      }
    });
    for (uint32_t f : members) c.num_terms += g.factors[f].num_terms;
    h.factors.push_back(std::move(c));
  }
  return h;
}

bool graph_applies(const StateGraph& g) {
  return integral_sum(g) && !g.relaxed_terms &&
         std::none_of(g.partial.begin(), g.partial.end(), [](uint8_t p) { return p != 0; });
}

struct Raised {
  Ascent ascent;
  double bound;  // min form
  uint32_t sweeps;
};

// The ascent until it stalls, the sweeps run out, or the bound (min form)
// reaches `enough`. (The sweeps read the bound's estimate, the stop its exact
// value: the exact least entries cost a second pass over every table.)
std::optional<Raised> raise(const StateGraph& g, const DualLimits& limits, double enough,
                            const std::vector<const ImplicitFactor*>& implicit = {}) {
  Raised r{Ascent(g, implicit), 0, 0};
  std::optional<double> b = r.ascent.bound();
  WorkCounter work;
  work.every = 1 << 16;
  for (bool stalled = false; b && !stalled && r.sweeps < limits.max_sweeps && *b < enough;) {
    while (!stalled && r.sweeps < limits.max_sweeps && *b < enough) {
      report(limits.progress, r.sweeps, limits.max_sweeps);
      const size_t n = r.ascent.msg.size();
      for (size_t i = 0; i < n; ++i) r.ascent.update(r.sweeps % 2 ? n - 1 - i : i, work, limits.progress, r.sweeps, limits.max_sweeps);
      ++r.sweeps;
      const std::optional<double> next = r.ascent.bound();
      if (!next) return std::nullopt;
      stalled = *next - *b < limits.min_gain;
      b = next;
    }
    r.ascent.settle();
    b = r.ascent.bound();
  }
  if (!b) return std::nullopt;
  r.bound = *b;
  return r;
}

// Each factor's positions from the most classes to the fewest (the same
// relaxation): the ascent's loops run along rows of the first position, and
// a first position of 2 classes, as joined tables often have, leaves rows
// whose bookkeeping costs more than their entries.
void widest_first(StateGraph& g) {
  std::vector<size_t> order, stride;
  for (StateFactor& f : g.factors) {
    const size_t m = f.dims.size();
    if (std::is_sorted(f.dims.begin(), f.dims.end(), std::greater<>())) continue;
    order.resize(m);
    for (size_t j = 0; j < m; ++j) order[j] = j;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return f.dims[a] > f.dims[b]; });
    StateFactor t;
    t.num_terms = f.num_terms;
    for (size_t j : order) t.scope.push_back(f.scope[j]), t.dims.push_back(f.dims[j]), t.project.push_back(std::move(f.project[j]));
    stride.assign(m, 1);  // (of each old position in the new table)
    for (size_t i = 1, s = t.dims[0]; i < m; s *= t.dims[i], ++i) stride[order[i]] = s;
    t.table.resize(f.table.size());
    for_entries(f, [&](size_t e, const std::vector<uint32_t>& c) {
      size_t at = 0;
      for (size_t j = 0; j < m; ++j) at += c[j] * stride[j];
      t.table[at] = f.table[e];
    });
    f = std::move(t);
  }
}

// The graph the ascent runs on: simplified, clustered, each table widest first.
StateGraph prepared(const StateGraph& input, const DualLimits& limits) {
  StateGraph g = input;
  simplify(g, limits.progress);
  if (limits.cluster_entries > 1) g = clustered(g, limits.cluster_entries, limits.progress);
  widest_first(g);
  return g;
}

// States that every factor reads alike differ only in their unary terms: the
// best of each such class stands for all of them (no assignment gets worse).
// Returns, per variable and new state, the original state.
// Variables an implicit factor reads (`kept`) keep every state.
std::vector<std::vector<uint32_t>> keep_best_of_alike(StateGraph& g, const std::vector<uint8_t>& kept = {}) {
  std::vector<std::vector<std::pair<size_t, size_t>>> reads(g.domain.size());  // (factor, position)
  for (size_t fi = 0; fi < g.factors.size(); ++fi)
    for (size_t j = 0; j < g.factors[fi].scope.size(); ++j) reads[g.factors[fi].scope[j]].push_back({fi, j});
  std::vector<std::vector<uint32_t>> original(g.domain.size());
  std::vector<uint32_t> cls, pair;
  for (size_t x = 0; x < g.domain.size(); ++x) {
    const uint32_t dom = g.domain[x];
    if (x < kept.size() && kept[x]) {
      for (uint32_t s = 0; s < dom; ++s) original[x].push_back(s);
      continue;
    }
    cls.assign(dom, 0);
    uint32_t count = 1;
    for (const auto& [fi, j] : reads[x]) {
      const std::vector<uint32_t>& p = g.factors[fi].project[j];
      const uint32_t d = g.factors[fi].dims[j];
      pair.assign(static_cast<size_t>(count) * d, UINT32_MAX);
      uint32_t next = 0;
      for (uint32_t s = 0; s < dom; ++s) {
        uint32_t& id = pair[static_cast<size_t>(cls[s]) * d + p[s]];
        if (id == UINT32_MAX) id = next++;
        cls[s] = id;
      }
      count = next;
    }
    std::vector<uint32_t>& best = original[x];
    best.assign(count, UINT32_MAX);
    for (uint32_t s = 0; s < dom; ++s)
      if (best[cls[s]] == UINT32_MAX || better(g.sense, g.unary[x][s], g.unary[x][best[cls[s]]])) best[cls[s]] = s;
    std::vector<double> unary;
    for (uint32_t s : best) unary.push_back(g.unary[x][s]);
    g.unary[x].swap(unary);
    g.domain[x] = count;
    for (const auto& [fi, j] : reads[x]) {
      std::vector<uint32_t> p;
      for (uint32_t s : best) p.push_back(g.factors[fi].project[j][s]);
      g.factors[fi].project[j].swap(p);
    }
  }
  return original;
}

// A piece held at one of its values: the bound over the assignments that read
// it, per variable state and per factor entry (each also lifts the other
// pieces it touches to their best over the states or entries it allows).
struct Reduced {
  std::vector<std::vector<double>> state;  // per variable and state
  std::vector<std::vector<double>> entry;  // per factor and entry
};

Reduced reduced_bounds(const StateGraph& g, const Ascent& a, double lb, const Progress& progress) {
  Reduced r;
  WorkCounter work;
  std::vector<double> least_unary;
  for (const auto& u : a.unary) least_unary.push_back(*std::min_element(u.begin(), u.end()));
  for (const auto& u : a.unary) r.state.emplace_back(u.size(), lb);
  for (size_t fi = 0; fi < g.factors.size(); ++fi) {
    const StateFactor& f = g.factors[fi];
    if (work.tick(static_cast<double>(f.table.size() * f.scope.size()))) report(progress, fi, g.factors.size());
    // Per scope position and class: the best state of the class (above the variable's best),
    // and the factor's best entry with that class (above its best).
    std::vector<std::vector<double>> class_state(f.scope.size()), class_entry(f.scope.size());
    for (size_t j = 0; j < f.scope.size(); ++j) {
      class_state[j].assign(f.dims[j], INFINITY);
      class_entry[j].assign(f.dims[j], INFINITY);
      const auto& u = a.unary[f.scope[j]];
      for (size_t s = 0; s < u.size(); ++s) {
        double& b = class_state[j][f.project[j][s]];
        b = std::min(b, u[s] - least_unary[f.scope[j]]);
      }
    }
    const std::vector<double> values = a.reparametrised(fi);
    const double least = *std::min_element(values.begin(), values.end());
    r.entry.emplace_back(f.table.size());
    for_entries(f, [&](size_t e, const std::vector<uint32_t>& c) {
      double b = lb + values[e] - least;
      for (size_t j = 0; j < c.size(); ++j) {
        b += class_state[j][c[j]];
        class_entry[j][c[j]] = std::min(class_entry[j][c[j]], values[e] - least);
      }
      r.entry.back()[e] = b;
    });
    for (size_t j = 0; j < f.scope.size(); ++j) {
      auto& sb = r.state[f.scope[j]];
      for (size_t s = 0; s < sb.size(); ++s) sb[s] += class_entry[j][f.project[j][s]];
    }
  }
  for (size_t x = 0; x < a.unary.size(); ++x)
    for (size_t s = 0; s < a.unary[x].size(); ++s) r.state[x][s] += a.unary[x][s] - least_unary[x];
  return r;
}

}  // namespace

bool integral_sum(const StateGraph& g) {
  if (g.combine != Combine::Sum || !small_integer(g.constant)) return false;
  for (const auto& u : g.unary)
    if (u.empty() || !std::all_of(u.begin(), u.end(), small_integer)) return false;
  for (const StateFactor& f : g.factors)
    if (!std::all_of(f.table.begin(), f.table.end(), small_integer)) return false;
  return true;
}

struct DualProof::Impl {
  DualLimits limits;
  std::vector<const ImplicitFactor*> implicit;
  StateGraph g;  // prepared, with the best of alike states only
  std::vector<std::vector<uint32_t>> original;  // per variable and state of g: the input's state
  std::optional<Raised> raised;
};

DualProof::DualProof(const StateGraph& input, const DualLimits& limits, std::optional<double> stop_at,
                     std::vector<const ImplicitFactor*> implicit)
    : impl_(std::make_unique<Impl>()) {
  impl_->limits = limits;
  impl_->implicit = std::move(implicit);
  if (!graph_applies(input)) return;
  impl_->g = prepared(input, limits);
  std::vector<uint8_t> kept(input.domain.size(), 0);
  for (const ImplicitFactor* f : impl_->implicit)
    for (uint32_t x : f->scope) kept[x] = 1;
  impl_->original = keep_best_of_alike(impl_->g, kept);
  const double sign = impl_->g.sense == Sense::Min ? 1.0 : -1.0;
  // (Integer values: a bound above incumbent - 1 proves the incumbent.)
  if (auto r = raise(impl_->g, limits, stop_at ? sign * *stop_at - 1 : INFINITY, impl_->implicit))
    impl_->raised.emplace(std::move(*r));
}

DualProof::~DualProof() = default;

bool DualProof::applies() const { return impl_->raised.has_value(); }

std::optional<double> DualProof::bound() const {
  if (!impl_->raised) return std::nullopt;
  const double sign = impl_->g.sense == Sense::Min ? 1.0 : -1.0;
  return sign * std::ceil(impl_->raised->bound);
}

std::vector<std::vector<double>> DualProof::implicit_costs(size_t i) const {
  std::vector<std::vector<double>> costs;
  if (impl_->raised)
    for (uint32_t x : impl_->implicit[i]->scope) costs.push_back(impl_->raised->ascent.unary[x]);
  return costs;
}

std::optional<DualProof::ImplicitReduced> DualProof::implicit_reduced(size_t i) const {
  if (!impl_->raised) return std::nullopt;
  const Ascent& a = impl_->raised->ascent;
  const size_t fi = impl_->g.factors.size() + i;
  // Every piece but this factor and its variables at its least: the bound less
  // theirs, plus what they take for the value held (exact: each below 2^31).
  ImplicitReduced r;
  r.offset = impl_->raised->bound - a.factor_least[fi];
  for (size_t j = 0; j < impl_->implicit[i]->scope.size(); ++j) {
    const std::vector<double>& u = a.unary[impl_->implicit[i]->scope[j]];
    r.offset -= *std::min_element(u.begin(), u.end());
    r.costs.push_back(u);
    for (size_t s = 0; s < u.size(); ++s) r.costs.back()[s] -= a.msg[fi][j][s];
  }
  if (!(std::fabs(r.offset) < kLargest)) return std::nullopt;
  return r;
}

uint32_t DualProof::sweeps() const { return impl_->raised ? impl_->raised->sweeps : 0; }

std::vector<uint32_t> DualProof::decoded() const {
  std::vector<uint32_t> x;
  if (impl_->raised)
    for (const auto& u : impl_->raised->ascent.unary)
      x.push_back(impl_->original[x.size()][static_cast<size_t>(std::min_element(u.begin(), u.end()) - u.begin())]);
  return x;
}

namespace {

// What is left of a graph for the assignments better than an incumbent: the
// states whose bound allows one, and the entries that do (the others become
// `forbidden` in the DP's graph, and `penalty` more in the ascent's: either way
// no assignment that reads them beats the incumbent).
struct Pruned {
  StateGraph dp, ascent;
  std::vector<std::vector<uint32_t>> kept;  // per variable: its kept states
  bool empty = false;                       // a variable kept no state
  bool any = false;                         // something was pruned
};

Pruned prune(const StateGraph& g, const Reduced& red, double ub, double penalty, DualProof::Proof& proof) {
  Pruned p;
  const double sign = g.sense == Sense::Min ? 1.0 : -1.0;
  StateGraph& h = p.dp;
  h.combine = g.combine, h.sense = g.sense, h.term_max = g.term_max, h.constant = g.constant;
  p.kept.resize(g.domain.size());
  for (size_t x = 0; x < g.domain.size(); ++x) {
    h.unary.emplace_back();
    for (uint32_t s = 0; s < g.domain[x]; ++s)
      if (red.state[x][s] <= ub - 1) p.kept[x].push_back(s), h.unary.back().push_back(g.unary[x][s]);
    if (p.kept[x].empty()) {
      p.empty = true;
      return p;
    }
    p.any = p.any || p.kept[x].size() < g.domain[x];
    proof.kept_states += p.kept[x].size();
    h.domain.push_back(static_cast<uint32_t>(p.kept[x].size()));
  }
  h.unary_terms.assign(h.domain.size(), 1);
  h.partial.assign(h.domain.size(), 0);
  p.ascent = h;
  for (size_t fi = 0; fi < g.factors.size(); ++fi) {
    StateFactor c = g.factors[fi], a = g.factors[fi];
    for (size_t e = 0; e < c.table.size(); ++e) {
      if (red.entry[fi][e] > ub - 1) {
        p.any = p.any || red.entry[fi][e] < INFINITY;
        c.table[e] = sign * INFINITY;
        a.table[e] += sign * penalty;
      } else {
        ++proof.kept_entries;
      }
    }
    proof.entries += c.table.size();
    for (size_t j = 0; j < c.scope.size(); ++j) {
      std::vector<uint32_t> q;
      for (uint32_t s : p.kept[c.scope[j]]) q.push_back(c.project[j][s]);
      c.project[j] = q;
      a.project[j].swap(q);
    }
    p.dp.factors.push_back(std::move(c));
    p.ascent.factors.push_back(std::move(a));
  }
  return p;
}

}  // namespace

DualProof::Proof DualProof::prove(double incumbent, const StateDpLimits& dp_limits) const {
  Proof proof;
  if (!impl_->raised || !small_integer(incumbent)) return proof;
  const double sign = impl_->g.sense == Sense::Min ? 1.0 : -1.0;
  const double ub = sign * incumbent;  // min form
  // Round by round: prune by the bound, try the DP over what is left, else
  // raise the bound again over what is left (it can only rise) and prune more.
  const StateGraph* g = &impl_->g;
  const Raised* raised = &*impl_->raised;
  std::vector<std::vector<uint32_t>> original = impl_->original;
  StateGraph next;
  std::optional<Raised> again;
  for (uint32_t round = 0;; ++round) {
    const double lb = raised->bound;
    proof.states = proof.kept_states = proof.entries = proof.kept_entries = 0;
    for (uint32_t d : g->domain) proof.states += d;
    // Every value is an integer: an assignment can beat the incumbent only if
    // the bound over the assignments that read each of its pieces is at most ub - 1.
    if (lb > ub - 1) {
      proof.proven = true;
      return proof;
    }
    if (!impl_->implicit.empty()) return proof;  // (the DP below would not see them)
    const double penalty = std::ceil(ub - lb) + 1;
    Pruned p = prune(*g, reduced_bounds(*g, raised->ascent, lb, impl_->limits.progress), ub, penalty, proof);
    if (p.empty) {  // no state of some variable is in a better assignment
      proof.proven = true;
      return proof;
    }
    try {
      StateDpLimits exact = dp_limits;
      exact.mini_buckets = false;  // (a mini-bucket value is no assignment's)
      const StateDpResult dp = solve_states(p.dp, exact);
      proof.proven = true;
      if (std::isfinite(dp.value) && better(g->sense, dp.value, incumbent)) {
        std::vector<uint32_t> state(g->domain.size());
        for (size_t x = 0; x < state.size(); ++x) state[x] = original[x][p.kept[x][dp.state[x]]];
        proof.better_value = dp.value;
        proof.better = std::move(state);
      }
      return proof;
    } catch (const LimitError&) {
    }
    if (!p.any || round + 1 >= impl_->limits.max_rounds) return proof;
    // The next round's graph: what is left, its alike states merged.
    simplify(p.ascent, impl_->limits.progress);
    widest_first(p.ascent);
    std::vector<std::vector<uint32_t>> alike = keep_best_of_alike(p.ascent);
    for (size_t x = 0; x < alike.size(); ++x)
      for (uint32_t& s : alike[x]) s = original[x][p.kept[x][s]];
    original.swap(alike);
    next = std::move(p.ascent);
    again.reset();
    std::optional<Raised> r = raise(next, impl_->limits, ub - 1);
    if (!r) return proof;
    again.emplace(std::move(*r));
    g = &next;
    raised = &*again;
  }
}

}  // namespace hodt
