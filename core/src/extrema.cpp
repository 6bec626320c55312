#include "hodt/extrema.hpp"

#include <algorithm>
#include <array>

#include "hodt/format.hpp"
#include "hodt/measures.hpp"
#include "hodt/term_budget.hpp"

namespace hodt {

namespace {

double z(const Mesh& m, uint32_t v) { return m.point(v)[2]; }

// Per vertex: +1 potential minimum, -1 potential maximum, 0 neither (or on the hull).
std::vector<int8_t> potential_extrema(const FirstOrder& fo, const Progress& progress) {
  WorkCounter work;
  const Mesh& m = fo.base;
  const std::vector<uint8_t> diagonal = fo.diagonal_mask();
  const uint32_t n = m.num_vertices();
  std::vector<uint8_t> higher(n, 1), lower(n, 1);  // all fixed neighbours strictly higher / lower
  for (uint32_t e = 0; e < m.triangles.size(); ++e) {
    if (work.tick(8)) report(progress, e, m.triangles.size());
    if (diagonal[e]) continue;
    const uint32_t u = m.origin(e), v = m.target(e);
    // Every edge appears as a halfedge from both ends, or once on the hull: visit both ways.
    for (auto [a, b] : {std::pair{u, v}, std::pair{v, u}}) {
      if (!(z(m, b) > z(m, a))) higher[a] = 0;
      if (!(z(m, b) < z(m, a))) lower[a] = 0;
    }
  }
  std::vector<int8_t> kind(n, 0);
  for (uint32_t v : m.hull) higher[v] = lower[v] = 0;
  for (uint32_t v = 0; v < n; ++v) kind[v] = higher[v] ? 1 : lower[v] ? -1 : 0;
  return kind;
}

// The vertices side s of quad q helps (at most 2).
uint32_t helped(const FirstOrder& fo, const std::vector<int8_t>& kind, uint32_t q, bool s, uint32_t out[2], bool minima_only) {
  const Mesh& m = fo.base;
  const Quad& k = fo.quads[q];
  const uint32_t u = s ? k.c : k.a, w = s ? k.d : k.b;
  uint32_t count = 0;
  for (auto [v, p] : {std::pair{u, w}, std::pair{w, u}}) {
    if (kind[v] > 0 && z(m, p) <= z(m, v)) out[count++] = v;
    else if (!minima_only && kind[v] < 0 && z(m, p) >= z(m, v)) out[count++] = v;
  }
  return count;
}

}  // namespace

Choice fewest_local_minima(const FirstOrder& fo, const Progress& progress) {
  // Only the diagonal through a lowest vertex can help; take the flipped one only
  // when it helps some potential minimum (fewer flips, the same value).
  const std::vector<int8_t> kind = potential_extrema(fo, progress);
  Choice c(fo.num_quads(), 0);
  WorkCounter work;
  for (uint32_t q = 0; q < fo.num_quads(); ++q) {
    if (work.tick(16)) report(progress, q, fo.num_quads());
    uint32_t h[2];
    c[q] = helped(fo, kind, q, true, h, true) > 0 && helped(fo, kind, q, false, h, true) == 0;
  }
  return c;
}

Choice fewest_local_extrema(const FirstOrder& fo, const DpLimits& limits) {
  const uint32_t nq = fo.num_quads(), n = fo.base.num_vertices();
  const std::vector<int8_t> kind = potential_extrema(fo, limits.progress);
  std::vector<std::array<uint32_t, 2>> h[2];
  std::vector<uint32_t> hn[2];
  bool ties = false;
  for (int s = 0; s < 2; ++s) {
    h[s].resize(nq);
    hn[s].resize(nq);
    for (uint32_t q = 0; q < nq; ++q) {
      hn[s][q] = helped(fo, kind, q, s, h[s][q].data(), false);
      ties = ties || hn[s][q] == 2;
    }
  }
  Choice c(nq, 0);
  if (ties) {
    // Exact through the factor graph: a term per potential extremum, 1 if no
    // chosen side helps it, over the quads that could.
    std::vector<std::vector<std::pair<uint32_t, bool>>> helpers(n);
    for (int s = 0; s < 2; ++s)
      for (uint32_t q = 0; q < nq; ++q)
        for (uint32_t i = 0; i < hn[s][q]; ++i) helpers[h[s][q][i]].push_back({q, s == 1});
    std::vector<std::vector<uint32_t>> scope(n);
    std::vector<TermSize> sizes(n, TermSize{0, 0});
    for (uint32_t v = 0; v < n; ++v) {
      for (auto [q, s] : helpers[v])
        if (std::find(scope[v].begin(), scope[v].end(), q) == scope[v].end()) scope[v].push_back(q);
      sizes[v] = TermSize{static_cast<uint32_t>(scope[v].size()), static_cast<double>(helpers[v].size())};
    }
    plan_terms(sizes, limits, OverBudget::Refuse, [&](size_t v) {  // before any table is allocated
      const double* p = fo.base.point(static_cast<uint32_t>(v));
      return "min-local-extrema with equal heights: the vertex at (" + format_number(p[0]) + ", " +
             format_number(p[1]) + ") has " + std::to_string(sizes[v].scope) + " flippable quads that could help it";
    });
    FactorGraph g;
    g.num_vars = nq;
    g.sense = Sense::Min;
    WorkCounter work;
    for (uint32_t v = 0; v < n; ++v) {
      if (helpers[v].empty()) continue;
      Factor f;
      f.scope = std::move(scope[v]);
      f.table.resize(size_t(1) << f.scope.size());
      for (size_t idx = 0; idx < f.table.size(); ++idx) {
        bool help = false;
        for (auto [q, s] : helpers[v]) {
          const size_t bit = std::find(f.scope.begin(), f.scope.end(), q) - f.scope.begin();
          help = help || (((idx >> bit) & 1) == (s ? 1u : 0u));
        }
        f.table[idx] = help ? 0 : 1;
        if (work.tick(sizes[v].work_per_entry + 1)) report(limits.progress, v, n);
      }
      g.factors.push_back(std::move(f));
    }
    g.simplify(limits.progress);
    return solve_exact(g, limits).choice;
  }
  // Claim graph: candidates are vertices; a quad helping one candidate on each
  // side is an edge, a quad helping on one side only is a loop (always taken).
  std::vector<std::vector<std::pair<uint32_t, uint32_t>>> adj(n);  // (neighbour, quad)
  std::vector<uint8_t> loop_at(n, 0);
  for (uint32_t q = 0; q < nq; ++q) {
    if (hn[0][q] && hn[1][q]) {
      adj[h[0][q][0]].push_back({h[1][q][0], q});
      adj[h[1][q][0]].push_back({h[0][q][0], q});
    } else if (hn[0][q] || hn[1][q]) {
      c[q] = hn[1][q] > 0;
      loop_at[h[c[q]][q][0]] = 1;
    }
  }
  // Per component: root at a looped vertex, else at an end of a cycle edge (which
  // then claims the root), else anywhere; every BFS tree edge claims its child.
  std::vector<uint8_t> seen(n, 0), reached(n, 0);
  std::vector<uint32_t> members, order;
  std::vector<int32_t> via(n, -2);  // tree quad into each vertex (-1 at the start), reset after use
  WorkCounter work;
  for (uint32_t s = 0; s < n; ++s) {
    if (work.tick(8)) report(limits.progress, s, n);
    if (seen[s] || adj[s].empty()) continue;
    members.assign({s});
    seen[s] = 1;
    size_t degree_sum = 0;
    for (size_t i = 0; i < members.size(); ++i) {
      degree_sum += adj[members[i]].size();
      for (auto [w, q] : adj[members[i]])
        if (!seen[w]) seen[w] = 1, members.push_back(w);
    }
    uint32_t root = members[0];
    int32_t cycle_quad = -1;
    const auto looped = std::find_if(members.begin(), members.end(), [&](uint32_t v) { return loop_at[v] != 0; });
    if (looped != members.end()) {
      root = *looped;
    } else if (degree_sum / 2 >= members.size()) {  // a cycle: find a non-tree edge
      order.assign({members[0]});
      via[members[0]] = -1;
      for (size_t i = 0; i < order.size() && cycle_quad < 0; ++i)
        for (auto [w, q] : adj[order[i]]) {
          if (via[w] == -2) {
            via[w] = static_cast<int32_t>(q), order.push_back(w);
          } else if (static_cast<int32_t>(q) != via[order[i]]) {
            cycle_quad = static_cast<int32_t>(q), root = w;
            break;
          }
        }
      for (uint32_t v : order) via[v] = -2;  // a vector of n per component would be quadratic
    }
    order.assign({root});
    reached[root] = 1;
    for (size_t i = 0; i < order.size(); ++i)
      for (auto [w, q] : adj[order[i]]) {
        if (reached[w] || static_cast<int32_t>(q) == cycle_quad) continue;
        reached[w] = 1;
        c[q] = h[1][q][0] == w;  // the side whose candidate is the child
        order.push_back(w);
        if (work.tick(8)) report(limits.progress, s, n);
      }
    if (cycle_quad >= 0) c[cycle_quad] = h[1][cycle_quad][0] == root;
  }
  return c;
}

}  // namespace hodt
