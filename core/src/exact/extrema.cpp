#include "exact/extrema.hpp"

#include <algorithm>
#include <array>

#include "hodt/domain.hpp"
#include "hodt/format.hpp"
#include "hodt/measures.hpp"
#include "hodt/skeleton.hpp"
#include "containers/out_of_line.hpp"
#include "engines/term_budget.hpp"

namespace hodt {

namespace {

double z(const Mesh& m, uint32_t v) { return m.point(v)[2]; }

// Per vertex: +1 potential minimum, -1 potential maximum, 0 neither (or on the
// hull, or within a domain beside a fixed triangle outside: never counted).
std::vector<int8_t> potential_extrema(const FirstOrder& fo, const Progress& progress) {
  WorkCounter work;
  const Mesh& m = fo.base;
  const std::vector<uint8_t> diagonal = fo.diagonal_mask();
  const uint32_t n = m.num_vertices();
  std::vector<uint8_t> higher(n, 1), lower(n, 1);  // all fixed neighbours strictly higher / lower
  // (Out of line per chunk: containers/out_of_line.hpp.)
  for_each_index(static_cast<uint32_t>(m.triangles.size()), [&](uint32_t e) {
    if (work.tick(8)) report(progress, e, m.triangles.size());
    if (diagonal[e]) return;
    const uint32_t u = m.origin(e), v = m.target(e);
    // Every edge appears as a halfedge from both ends, or once on the hull: visit both ways.
    for (auto [a, b] : {std::pair{u, v}, std::pair{v, u}}) {
      if (!(z(m, b) > z(m, a))) higher[a] = 0;
      if (!(z(m, b) < z(m, a))) lower[a] = 0;
    }
  });
  std::vector<int8_t> kind(n, 0);
  for (uint32_t v : m.hull) higher[v] = lower[v] = 0;
  if (has_domain(m))
    for (uint32_t t = 0; t < m.num_triangles(); ++t)
      if (fo.quad_of_triangle[t] < 0 && !triangle_inside(m, base_triangle(m, t)))
        for (int k = 0; k < 3; ++k) higher[m.triangles[3 * t + k]] = lower[m.triangles[3 * t + k]] = 0;
  for (uint32_t v = 0; v < n; ++v) kind[v] = higher[v] ? 1 : lower[v] ? -1 : 0;
  return kind;
}

// The vertices one side of a quad helps (stops from being counted): at most its four corners.
struct Helped {
  uint32_t n = 0, v[4];
  void add(uint32_t x) {
    if (std::find(v, v + n, x) == v + n) v[n++] = x;
  }
};

// The vertices side s of quad q helps: its diagonal's ends that see a partner not
// above (minimum) or not below (maximum) them, and within a domain the counted
// corners of its triangles outside (a vertex with a triangle outside is not
// counted): touching_outside, quads_touching_outside (domain.hpp), names the quads
// that can have one.
Helped helped(const FirstOrder& fo, const std::vector<int8_t>& kind, uint32_t q, bool s, bool minima_only,
              const std::vector<uint8_t>& touching_outside = {}) {
  const Mesh& m = fo.base;
  const Quad& k = fo.quads[q];
  const uint32_t u = s ? k.c : k.a, w = s ? k.d : k.b;
  Helped h;
  for (auto [v, p] : {std::pair{u, w}, std::pair{w, u}}) {
    if (kind[v] > 0 && z(m, p) <= z(m, v)) h.add(v);
    else if (!minima_only && kind[v] < 0 && z(m, p) >= z(m, v)) h.add(v);
  }
  if (!touching_outside.empty() && touching_outside[q]) {
    uint32_t t[6];
    fo.triangles_of(q, s, t);
    for (int i = 0; i < 6; i += 3)
      if (!triangle_inside(m, {t[i], t[i + 1], t[i + 2]}))
        for (int j = i; j < i + 3; ++j)
          if (minima_only ? kind[t[j]] > 0 : kind[t[j]] != 0) h.add(t[j]);
  }
  return h;
}

// Union-find over the vertices (path halving).
uint32_t find_root(std::vector<uint32_t>& parent, uint32_t v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

// The quads that help some vertex of a component where a side helps two or more
// (ties, or a domain): exactly, through the factor graph, a term per counted
// vertex there, 1 if no chosen side helps it, over the quads that could.
void solve_with_ties(const FirstOrder& fo, const std::vector<Helped> h[2], const std::vector<uint8_t>& tied_quad,
                     const DpLimits& limits, Choice& c) {
  const uint32_t nq = fo.num_quads();
  std::vector<uint32_t> quads;  // the tied quads, numbered from 0 in the factor graph
  for (uint32_t q = 0; q < nq; ++q)
    if (tied_quad[q]) quads.push_back(q);
  if (quads.empty()) return;
  // The vertices they help, numbered from 0 too; per vertex its (quad, side) helpers.
  std::vector<uint32_t> vertices, local_vertex(fo.base.num_vertices(), UINT32_MAX);
  std::vector<std::vector<std::pair<uint32_t, bool>>> helpers;
  for (int s = 0; s < 2; ++s)
    for (uint32_t i = 0; i < quads.size(); ++i)
      for (uint32_t j = 0; j < h[s][quads[i]].n; ++j) {
        const uint32_t v = h[s][quads[i]].v[j];
        if (local_vertex[v] == UINT32_MAX) local_vertex[v] = static_cast<uint32_t>(vertices.size()), vertices.push_back(v), helpers.emplace_back();
        helpers[local_vertex[v]].push_back({i, s == 1});
      }
  const uint32_t n = static_cast<uint32_t>(vertices.size());
  std::vector<std::vector<uint32_t>> scope(n);
  std::vector<TermSize> sizes(n, TermSize{0, 0});
  for (uint32_t v = 0; v < n; ++v) {
    for (auto [q, s] : helpers[v])
      if (std::find(scope[v].begin(), scope[v].end(), q) == scope[v].end()) scope[v].push_back(q);
    sizes[v] = TermSize{static_cast<uint32_t>(scope[v].size()), static_cast<double>(helpers[v].size())};
  }
  plan_terms(sizes, limits, OverBudget::Refuse, [&](size_t v) {  // before any table is allocated
    const double* p = fo.base.point(vertices[v]);
    return "min-local-extrema with equal heights or a domain: the vertex at (" + format_number(p[0]) + ", " +
           format_number(p[1]) + ") has " + std::to_string(sizes[v].scope) + " flippable quads that could help it";
  });
  FactorGraph g;
  g.num_vars = static_cast<uint32_t>(quads.size());
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
  const Choice local_choice = solve_exact(g, limits).choice;
  for (uint32_t i = 0; i < quads.size(); ++i) c[quads[i]] = local_choice[i];
}

// Fewest extrema (or minima only): the claim graph where every side helps at
// most one vertex, the factor graph on the components where one helps more.
Choice fewest_extrema(const FirstOrder& fo, const DpLimits& limits, bool minima_only) {
  const uint32_t nq = fo.num_quads(), n = fo.base.num_vertices();
  const std::vector<int8_t> kind = potential_extrema(fo, limits.progress);
  const std::vector<uint8_t> touching = quads_touching_outside(fo);
  std::vector<Helped> h[2];
  for (int s = 0; s < 2; ++s) {
    h[s].resize(nq);
    for (uint32_t q = 0; q < nq; ++q) h[s][q] = helped(fo, kind, q, s, minima_only, touching);
  }
  // Components of the vertices joined by the quads that help them; a component
  // is tied where a side helps two or more of them.
  std::vector<uint32_t> parent(n);
  for (uint32_t v = 0; v < n; ++v) parent[v] = v;
  std::vector<uint8_t> tied(n, 0), tied_quad(nq, 0);
  for (uint32_t q = 0; q < nq; ++q) {
    int32_t first = -1;
    for (int s = 0; s < 2; ++s)
      for (uint32_t i = 0; i < h[s][q].n; ++i) {
        const uint32_t r = find_root(parent, h[s][q].v[i]);
        if (first < 0) first = static_cast<int32_t>(r);
        else if (r != static_cast<uint32_t>(first)) tied[first] = tied[first] || tied[r], parent[r] = static_cast<uint32_t>(first);
      }
    if (first >= 0 && (h[0][q].n > 1 || h[1][q].n > 1)) tied[first] = 1;
  }
  for (uint32_t q = 0; q < nq; ++q) {
    const uint32_t any = h[0][q].n ? h[0][q].v[0] : h[1][q].n ? h[1][q].v[0] : UINT32_MAX;
    tied_quad[q] = any != UINT32_MAX && tied[find_root(parent, any)];
  }
  Choice c(nq, 0);
  solve_with_ties(fo, h, tied_quad, limits, c);
  // Claim graph: candidates are vertices; a quad helping one candidate on each
  // side is an edge, a quad helping on one side only is a loop (always taken).
  std::vector<std::vector<std::pair<uint32_t, uint32_t>>> adj(n);  // (neighbour, quad)
  std::vector<uint8_t> loop_at(n, 0);
  for (uint32_t q = 0; q < nq; ++q) {
    if (tied_quad[q]) continue;
    if (h[0][q].n && h[1][q].n) {
      adj[h[0][q].v[0]].push_back({h[1][q].v[0], q});
      adj[h[1][q].v[0]].push_back({h[0][q].v[0], q});
    } else if (h[0][q].n || h[1][q].n) {
      c[q] = h[1][q].n > 0;
      loop_at[h[c[q]][q].v[0]] = 1;
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
        c[q] = h[1][q].v[0] == w;  // the side whose candidate is the child
        order.push_back(w);
        if (work.tick(8)) report(limits.progress, s, n);
      }
    if (cycle_quad >= 0) c[cycle_quad] = h[1][cycle_quad].v[0] == root;
  }
  return c;
}

}  // namespace

Choice fewest_local_minima(const FirstOrder& fo, const DpLimits& limits) {
  // Within a domain a quad's side can stop more than one vertex from counting,
  // and both sides can: the general claim structure.
  if (has_domain(fo.base)) return fewest_extrema(fo, limits, true);
  // Only the diagonal through a lowest vertex can help; take the flipped one only
  // when it helps some potential minimum (fewer flips, the same value).
  const std::vector<int8_t> kind = potential_extrema(fo, limits.progress);
  Choice c(fo.num_quads(), 0);
  WorkCounter work;
  for (uint32_t q = 0; q < fo.num_quads(); ++q) {
    if (work.tick(16)) report(limits.progress, q, fo.num_quads());
    c[q] = helped(fo, kind, q, true, true).n > 0 && helped(fo, kind, q, false, true).n == 0;
  }
  return c;
}

Choice fewest_local_extrema(const FirstOrder& fo, const DpLimits& limits) { return fewest_extrema(fo, limits, false); }

}  // namespace hodt
