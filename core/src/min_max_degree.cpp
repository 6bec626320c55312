#include "hodt/min_max_degree.hpp"

#include <algorithm>

#include "hodt/format.hpp"
#include "hodt/skeleton.hpp"
#include "hodt/term_budget.hpp"

namespace hodt {

namespace {

// Per vertex: degree through fixed edges, and the quads whose diagonal choice adds
// one neighbour (side 0: the base diagonal ab, side 1: cd).
struct DegreeStructure {
  std::vector<uint32_t> fixed;
  VertexIncidence incidence;
};

DegreeStructure degree_structure(const FirstOrder& fo) {
  const Mesh& m = fo.base;
  DegreeStructure d;
  d.incidence = vertex_incidence(fo);
  d.fixed.assign(m.num_vertices(), 0);
  const std::vector<uint8_t> diagonal = fo.diagonal_mask();
  for (uint32_t e = 0; e < m.triangles.size(); ++e) {
    if (diagonal[e]) continue;
    if (m.halfedges[e] < 0 || m.halfedges[e] > static_cast<int32_t>(e)) {
      ++d.fixed[m.origin(e)];
      ++d.fixed[m.target(e)];
    }
  }
  return d;
}

bool on_side(const Quad& q, uint32_t v, bool side) { return side ? (v == q.c || v == q.d) : (v == q.a || v == q.b); }

}  // namespace

DegreeBounds degree_bounds(const FirstOrder& fo) {
  const DegreeStructure d = degree_structure(fo);
  DegreeBounds b{0, 0};
  // Every triangulation of the points has the same number of edges E, so some
  // vertex has degree at least the average 2E / n.
  const Mesh& m = fo.base;
  const uint64_t edges = (m.triangles.size() + m.hull.size()) / 2;
  b.lower = static_cast<uint32_t>((2 * edges + m.num_vertices() - 1) / m.num_vertices());
  for (uint32_t v = 0; v < d.fixed.size(); ++v) {
    uint32_t base = d.fixed[v];
    for (const uint32_t* q = d.incidence.quads_begin(v); q != d.incidence.quads_end(v); ++q)
      base += on_side(fo.quads[*q], v, false);
    b.lower = std::max(b.lower, d.fixed[v]);
    b.upper = std::max(b.upper, base);
  }
  return b;
}

FactorGraph degree_feasibility_model(const FirstOrder& fo, uint32_t bound, const DpLimits& limits) {
  const DegreeStructure d = degree_structure(fo);
  const uint32_t n = static_cast<uint32_t>(d.fixed.size());
  // Terms of the vertices that could exceed the bound; refused if too large,
  // before any table is allocated.
  std::vector<TermSize> sizes(n, TermSize{0, 0});
  for (uint32_t v = 0; v < n; ++v) {
    const uint32_t nq = static_cast<uint32_t>(d.incidence.quads_end(v) - d.incidence.quads_begin(v));
    if (d.fixed[v] + nq > bound) sizes[v] = TermSize{nq, static_cast<double>(nq)};
  }
  plan_terms(sizes, limits, OverBudget::Refuse, [&](size_t v) {
    const double* p = fo.base.point(static_cast<uint32_t>(v));
    return "the vertex at (" + format_number(p[0]) + ", " + format_number(p[1]) + ") has " +
           std::to_string(sizes[v].scope) + " flippable quads around it";
  });
  FactorGraph g;
  g.num_vars = fo.num_quads();
  g.sense = Sense::Min;
  WorkCounter work;
  for (uint32_t v = 0; v < n; ++v) {
    const uint32_t* qs = d.incidence.quads_begin(v);
    const uint32_t nq = static_cast<uint32_t>(d.incidence.quads_end(v) - qs);
    if (d.fixed[v] + nq <= bound) continue;  // cannot exceed the bound
    Factor f;
    f.scope.assign(qs, qs + nq);
    f.table.resize(size_t(1) << nq);
    for (size_t idx = 0; idx < f.table.size(); ++idx) {
      uint32_t degree = d.fixed[v];
      for (uint32_t i = 0; i < nq; ++i) degree += on_side(fo.quads[qs[i]], v, (idx >> i) & 1);
      f.table[idx] = degree > bound ? 1 : 0;
      if (work.tick(nq + 1)) report(limits.progress, v, n);
    }
    g.factors.push_back(std::move(f));
  }
  g.simplify(limits.progress);
  return g;
}

Choice min_max_degree_exact(const FirstOrder& fo, const DpLimits& limits) {
  const DegreeBounds b = degree_bounds(fo);
  Choice best(fo.num_quads(), 0);  // Delaunay: achieves b.upper
  uint32_t lo = b.lower, hi = b.upper;
  while (lo < hi) {
    const uint32_t mid = lo + (hi - lo) / 2;
    const DpResult r = solve_exact(degree_feasibility_model(fo, mid, limits), limits);
    if (r.value == 0) {
      hi = mid;
      best = r.choice;
    } else {
      lo = mid + 1;
    }
  }
  return best;
}

}  // namespace hodt
