#include "engines/two_sat.hpp"

#include <algorithm>

namespace hodt {

std::optional<std::vector<uint8_t>> TwoSat::solve(const Progress& progress, double done, double total,
                                                  std::vector<int32_t>* components) const {
  WorkCounter work;
  work.every = 65536;  // a unit: one literal or edge visited (a few nanoseconds)
  // Only variables in some clause, renumbered in order: a free variable's literals
  // are isolated, Tarjan gives them their own components in between the others',
  // which keeps the others' order, and false (its first literal) stays false.
  // (Marks, not a sort: the bottleneck search solves one instance per threshold.)
  uint32_t vars = n_;
  for (const Clause& c : clauses_) vars = std::max({vars, (c.a >> 1) + 1, (c.b >> 1) + 1});
  std::vector<uint32_t> local_var(vars, 0);
  for (const Clause& c : clauses_) local_var[c.a >> 1] = local_var[c.b >> 1] = 1;
  report(progress, done, total);
  std::vector<uint32_t> used;  // the variables in some clause, in order
  for (uint32_t v = 0; v < vars; ++v)
    if (local_var[v]) local_var[v] = static_cast<uint32_t>(used.size()), used.push_back(v);
  report(progress, done, total);
  auto local = [&](uint32_t l) { return 2 * local_var[l >> 1] + (l & 1); };
  const uint32_t nl = 2 * static_cast<uint32_t>(used.size());
  // Implication graph in compressed rows: (a or b) gives !a -> b and !b -> a.
  std::vector<Clause> cl(clauses_.size());
  for (size_t k = 0; k < clauses_.size(); ++k) {
    cl[k] = {local(clauses_[k].a), local(clauses_[k].b)};
    if (work.tick(32)) report(progress, done, total);
  }
  std::vector<uint32_t> start(nl + 1, 0), adj(2 * cl.size());
  for (const Clause& c : cl) ++start[(c.a ^ 1) + 1], ++start[(c.b ^ 1) + 1];
  for (uint32_t i = 0; i < nl; ++i) start[i + 1] += start[i];
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (const Clause& c : cl) adj[fill[c.a ^ 1]++] = c.b, adj[fill[c.b ^ 1]++] = c.a;

  // Iterative Tarjan: components are numbered in reverse topological order.
  constexpr uint32_t kNone = UINT32_MAX;
  std::vector<uint32_t> index(nl, kNone), low(nl), comp(nl, kNone), stack, call, edge;
  uint32_t next_index = 0, next_comp = 0;
  for (uint32_t root = 0; root < nl; ++root) {
    if (work.tick()) report(progress, done, total);
    if (index[root] != kNone) continue;
    call.push_back(root);
    edge.push_back(start[root]);
    index[root] = low[root] = next_index++;
    stack.push_back(root);
    while (!call.empty()) {
      if (work.tick()) report(progress, done, total);
      const uint32_t v = call.back();
      uint32_t& e = edge.back();
      if (e < start[v + 1]) {
        const uint32_t w = adj[e++];
        if (index[w] == kNone) {
          index[w] = low[w] = next_index++;
          stack.push_back(w);
          call.push_back(w);
          edge.push_back(start[w]);
        } else if (comp[w] == kNone && index[w] < low[v]) {
          low[v] = index[w];
        }
        continue;
      }
      if (low[v] == index[v]) {
        uint32_t w;
        do {
          w = stack.back();
          stack.pop_back();
          comp[w] = next_comp;
        } while (w != v);
        ++next_comp;
      }
      call.pop_back();
      edge.pop_back();
      if (!call.empty()) low[call.back()] = std::min(low[call.back()], low[v]);
    }
  }
  if (components) {
    components->assign(2 * static_cast<size_t>(n_), -1);
    for (uint32_t i = 0; i < nl; ++i) (*components)[2 * used[i >> 1] + (i & 1)] = static_cast<int32_t>(comp[i]);
  }
  std::vector<uint8_t> value(n_, 0);
  for (uint32_t i = 0; i < used.size(); ++i) {
    const uint32_t f = comp[2 * i], t = comp[2 * i + 1];
    if (f == t) return std::nullopt;
    value[used[i]] = t < f;  // the literal later in topological order is true
  }
  return value;
}

}  // namespace hodt
