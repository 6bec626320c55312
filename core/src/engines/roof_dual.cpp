#include "engines/roof_dual.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "engines/max_flow.hpp"
#include "engines/two_sat.hpp"

namespace hodt {

bool roof_dual_applies(const FactorGraph& g) {
  if (g.combine != Combine::Sum || g.relaxed) return false;
  for (const Factor& f : g.factors) {
    if (f.scope.size() > 2) return false;
    for (double v : f.table)
      if (!(std::fabs(v) <= 0x1p40) || v != std::floor(v)) return false;
  }
  return true;
}

namespace {

// The doubled energy E'(x, y) = E(x) + E(1 - y), every term split so that both
// halves are submodular (y stands for the complement of x), as a cut: a node's
// value is 0 on the source side. min E' <= 2 min E, and in a minimum the
// variables with x != y form an assignment some minimum of E extends.
// The graph is its own mirror (node p <-> its complement, s <-> t, arcs
// reversed); arcs are added in mirror pairs 2i, 2i + 1.
class QpboGraph {
 public:
  explicit QpboGraph(uint32_t n) : n_(n), one_(n, 0) {}

  // A term over variables p, q with values e = {e00, e10, e01, e11} (bit 0 is p).
  void term(uint32_t p, uint32_t q, const int64_t* e) {
    const int64_t a = e[0], c = e[1], b = e[2], d = e[3];
    if (b + c >= a + d) {  // submodular: x_p, x_q, and the mirror on the complements
      constant_ += a + d;
      one_[p] += c - a, one_[q] += d - c;
      arc_pair(p, q, n_ + q, n_ + p, b + c - a - d);
    } else {  // x_p with the complement of x_q, and the mirror
      constant_ += b + c;
      one_[p] += d - b, one_[q] += d - c;
      arc_pair(p, n_ + q, q, n_ + p, a + d - b - c);
    }
  }
  void term(uint32_t p, const int64_t* e) { constant_ += e[0] + e[1], one_[p] += e[1] - e[0]; }
  void term(const int64_t* e) { constant_ += 2 * e[0]; }

  struct Minimum {
    int64_t value;              // min E'
    std::vector<int8_t> fixed;  // per variable 0, 1 or -1 (free)
  };
  Minimum minimise(const Progress& progress) {
    // Node p is x_p, node n + p its complement. A node costing c more at 1 than
    // at 0 (the source side is 0): an arc s -> node of capacity c if c > 0, else
    // c in the constant and an arc node -> t of capacity -c. The complement of p
    // costs -one_[p], so the constant takes -|c| per variable.
    MaxFlow flow(2 * n_);
    int64_t constant = constant_;
    for (uint32_t p = 0; p < n_; ++p) {
      const int64_t c = one_[p];
      flow.add_terminal(p, std::max<int64_t>(c, 0), std::max<int64_t>(-c, 0));
      flow.add_terminal(n_ + p, std::max<int64_t>(-c, 0), std::max<int64_t>(c, 0));
      constant -= c < 0 ? -c : c;
    }
    for (const Arc& a : arcs_) flow.add_edge(a.u, a.v, a.cap);
    Minimum m{constant + flow.solve(progress), std::vector<int8_t>(n_, -1)};
    // The average of the flow and its mirror is a maximum flow too, and its
    // residual graph is symmetric. Its minimum cuts are the sets closed under
    // residual arcs (u on the source side => v too) that hold s: read as
    // implications between "p is on the source side" and its mirror "the
    // complement is", a 2-SAT whose strongly connected components label every
    // variable not in one component with its complement (Kolmogorov and Rother's
    // weak persistencies). Mirror arcs give the same clause: one of each pair.
    const uint32_t source = TwoSat::lit(n_, true);  // "s is on the source side"
    auto node = [&](uint32_t v) { return TwoSat::lit(v % n_, v < n_); };
    TwoSat sat(n_ + 1);
    sat.add_clause(source, source);
    for (uint32_t p = 0; p < n_; ++p) {
      if (one_[p] == 0) continue;
      const int64_t cap = one_[p] < 0 ? -one_[p] : one_[p];
      const int64_t doubled = std::abs(flow.terminal_flow(p)) + std::abs(flow.terminal_flow(n_ + p));
      const uint32_t u = one_[p] > 0 ? source : node(p), v = one_[p] > 0 ? node(p) : source ^ 1;  // s -> p or p -> t
      if (doubled < 2 * cap) sat.add_clause(u ^ 1, v);
      if (doubled > 0) sat.add_clause(v ^ 1, u);
    }
    for (uint32_t i = 0; i < arcs_.size(); i += 2) {
      const int64_t doubled = flow.edge_flow(i) + flow.edge_flow(i + 1);
      const Arc& a = arcs_[i];
      if (doubled < 2 * a.cap) sat.add_clause(node(a.u) ^ 1, node(a.v));  // residual u -> v
      if (doubled > 0) sat.add_clause(node(a.v) ^ 1, node(a.u));         // residual v -> u
    }
    report(progress, 1, 1);
    std::vector<int32_t> comp;
    sat.solve(progress, 1, 1, &comp);
    for (uint32_t p = 0; p < n_; ++p) {
      const int32_t src = comp[TwoSat::lit(p, true)], snk = comp[TwoSat::lit(p, false)];
      // A variable in no clause has no term: any value is optimal.
      if (src < 0) m.fixed[p] = 0;
      else if (src != snk) m.fixed[p] = src < snk ? 0 : 1;  // the later component holds
    }
    return m;
  }

 private:
  struct Arc { uint32_t u, v; int64_t cap; };
  void arc_pair(uint32_t u, uint32_t v, uint32_t mu, uint32_t mv, int64_t cap) {
    arcs_.push_back({u, v, cap});
    arcs_.push_back({mu, mv, cap});
  }
  uint32_t n_;
  std::vector<int64_t> one_;  // per variable: its node's cost at 1 minus at 0 (its complement's is the negation)
  std::vector<Arc> arcs_;
  int64_t constant_ = 0;      // of E'
};

// roof_dual() once roof_dual_applies(g) is known.
RoofDual checked_roof_dual(const FactorGraph& g, const Progress& progress) {
  const int64_t sign = g.sense == Sense::Max ? -1 : 1;  // minimise sign * value
  QpboGraph q(g.num_vars);
  for (const Factor& f : g.factors) {
    int64_t e[4] = {};
    for (size_t i = 0; i < f.table.size(); ++i) e[i] = sign * static_cast<int64_t>(f.table[i]);
    if (f.scope.size() == 1) q.term(f.scope[0], e);
    else if (f.scope.size() == 2) q.term(f.scope[0], f.scope[1], e);
    else q.term(e);
  }
  QpboGraph::Minimum m = q.minimise(progress);
  RoofDual r;
  // E is an integer, and min E >= min E' / 2.
  const int64_t low = m.value >= 0 ? (m.value + 1) / 2 : -((-m.value) / 2);
  r.bound = static_cast<double>(sign * low) + g.constant;
  r.fixed = std::move(m.fixed);
  r.num_fixed = static_cast<uint32_t>(std::count_if(r.fixed.begin(), r.fixed.end(), [](int8_t v) { return v >= 0; }));
  return r;
}

}  // namespace

RoofDual roof_dual(const FactorGraph& g, const Progress& progress) {
  if (!roof_dual_applies(g)) throw std::logic_error("roof_dual: not a sum of integer terms over at most two variables");
  return checked_roof_dual(g, progress);
}

FactorGraph condition(const FactorGraph& g, const std::vector<int8_t>& fixed) {
  FactorGraph c;
  c.num_vars = g.num_vars, c.sense = g.sense, c.combine = g.combine, c.constant = g.constant, c.relaxed = g.relaxed;
  for (const Factor& f : g.factors) {
    Factor r;
    size_t base = 0;
    std::vector<size_t> free_bit;
    for (size_t k = 0; k < f.scope.size(); ++k) {
      if (fixed[f.scope[k]] < 0) r.scope.push_back(f.scope[k]), free_bit.push_back(size_t(1) << k);
      else base |= size_t(fixed[f.scope[k]]) << k;
    }
    r.table.resize(size_t(1) << r.scope.size());
    for (size_t i = 0; i < r.table.size(); ++i) {
      size_t idx = base;
      for (size_t k = 0; k < free_bit.size(); ++k)
        if ((i >> k) & 1) idx |= free_bit[k];
      r.table[i] = f.table[idx];
    }
    if (r.scope.empty()) c.constant = c.combine == Combine::Sum ? c.constant + r.table[0] : std::max(c.constant, r.table[0]);
    else c.factors.push_back(std::move(r));
  }
  return c;
}

ReducedModel reduce_by_roof_dual(FactorGraph model, const Progress& progress) {
  ReducedModel r;
  if (!roof_dual_applies(model)) {
    r.model = std::move(model);
    return r;
  }
  r.roof = checked_roof_dual(model, progress);
  r.free = condition(model, r.roof->fixed);
  std::vector<uint32_t> renamed(model.num_vars, UINT32_MAX);
  for (uint32_t v = 0; v < model.num_vars; ++v)
    if (r.roof->fixed[v] < 0) renamed[v] = static_cast<uint32_t>(r.original.size()), r.original.push_back(v);
  r.free.num_vars = static_cast<uint32_t>(r.original.size());
  for (Factor& f : r.free.factors)
    for (uint32_t& v : f.scope) v = renamed[v];
  r.model = std::move(model);
  return r;
}

Choice ReducedModel::expand(const Choice& x) const {
  if (!roof) return x;
  Choice full(roof->fixed.size());
  for (size_t v = 0; v < full.size(); ++v) full[v] = static_cast<uint8_t>(std::max<int8_t>(roof->fixed[v], 0));
  for (size_t i = 0; i < original.size(); ++i) full[original[i]] = x[i];
  return full;
}

std::vector<uint32_t> ReducedModel::restrict(const std::vector<uint32_t>& per_variable) const {
  if (!roof) return per_variable;
  std::vector<uint32_t> r(original.size());
  for (size_t i = 0; i < original.size(); ++i) r[i] = per_variable[original[i]];
  return r;
}

}  // namespace hodt
