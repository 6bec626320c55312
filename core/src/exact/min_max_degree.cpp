#include "exact/min_max_degree.hpp"

#include <algorithm>
#include <optional>

#include "hodt/domain.hpp"
#include "hodt/format.hpp"
#include "hodt/objectives.hpp"
#include "hodt/skeleton.hpp"
#include "engines/term_budget.hpp"
#include "objectives/objective_terms.hpp"

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

// Within a domain the degree counts the neighbours joined by an edge of an inside
// triangle (docs/objectives.md, "The domain"); the triangles beside an edge at v
// all contain v, so the degree still depends on v's quads only: per choice of
// them (bit i of choice: quad i flipped), the inside triangles at v.
class DomainDegree {
 public:
  DomainDegree(const FirstOrder& fo, const VertexIncidence& vi, uint32_t v) : fo_(fo), v_(v) {
    const Mesh& m = fo.base;
    for (uint32_t k = vi.fixed_offset[v]; k < vi.fixed_offset[v + 1]; ++k) {
      const Tri t = base_triangle(m, vi.fixed[k]);
      if (triangle_inside(m, t)) fixed_.push_back(t);
    }
    qs_.assign(vi.quads_begin(v), vi.quads_end(v));
  }
  // The neighbours through the fixed inside triangles alone: in every triangulation.
  uint32_t sure() {
    star_neighbors(v_, fixed_, nb_);
    return static_cast<uint32_t>(nb_.size());
  }
  uint32_t of(size_t choice) {
    tris_ = fixed_;
    for (uint32_t i = 0; i < qs_.size(); ++i) {
      Tri t[2];
      const uint32_t count = quad_triangles_at(fo_, qs_[i], v_, (choice >> i) & 1, t);
      for (uint32_t j = 0; j < count; ++j)
        if (triangle_inside(fo_.base, t[j])) tris_.push_back(t[j]);
    }
    star_neighbors(v_, tris_, nb_);
    return static_cast<uint32_t>(nb_.size());
  }

 private:
  const FirstOrder& fo_;
  uint32_t v_;
  std::vector<Tri> fixed_, tris_;
  std::vector<uint32_t> qs_, nb_;
};

// Within a domain, U: the vertices whose triangles are inside in every
// triangulation (fixed ones inside, no quad at them touching a triangle outside):
// their degree is their degree without a domain. A flip takes one neighbour from
// a and b each and gives one to c and d, so the sum of U's degrees changes by
// |{c, d} in U| - |{a, b} in U| per flipped quad, independently: its least value
// is Delaunay's plus every negative change, and some vertex of U has at least
// the average (rounded up).
uint32_t domain_average_degree(const FirstOrder& fo, const DegreeStructure& d) {
  const Mesh& m = fo.base;
  const uint32_t n = m.num_vertices();
  const std::vector<uint8_t> touching = quads_touching_outside(fo);
  std::vector<uint8_t> in_u(n, 1);
  for (uint32_t v = 0; v < n; ++v) {
    for (uint32_t k = d.incidence.fixed_offset[v]; k < d.incidence.fixed_offset[v + 1] && in_u[v]; ++k)
      in_u[v] = triangle_inside(m, base_triangle(m, d.incidence.fixed[k]));
    for (const uint32_t* q = d.incidence.quads_begin(v); q != d.incidence.quads_end(v) && in_u[v]; ++q)
      in_u[v] = !touching[*q];
  }
  int64_t sum = 0, members = 0;
  for (uint32_t v = 0; v < n; ++v)
    if (in_u[v]) {
      ++members, sum += d.fixed[v];
      for (const uint32_t* q = d.incidence.quads_begin(v); q != d.incidence.quads_end(v); ++q) sum += on_side(fo.quads[*q], v, false);
    }
  for (const Quad& q : fo.quads) sum += std::min<int64_t>(0, in_u[q.c] + in_u[q.d] - in_u[q.a] - in_u[q.b]);
  return members > 0 && sum > 0 ? static_cast<uint32_t>((sum + members - 1) / members) : 0;
}

}  // namespace

DegreeBounds degree_bounds(const FirstOrder& fo) {
  const DegreeStructure d = degree_structure(fo);
  DegreeBounds b{0, 0};
  // Every triangulation of the points has the same number of edges E, so some
  // vertex has degree at least the average 2E / n.
  const Mesh& m = fo.base;
  const uint64_t edges = (m.triangles.size() + m.hull.size()) / 2;
  // Within a domain neither holds as such (edges outside are not counted): the
  // lower bound is the most neighbours a vertex has through fixed inside
  // triangles, or the average over the vertices whose triangles are inside in
  // every triangulation (domain_average_degree), and the Delaunay degree without
  // a domain stays an upper bound.
  const bool domain = has_domain(m);
  b.lower = domain ? domain_average_degree(fo, d)
                   : static_cast<uint32_t>((2 * edges + m.num_vertices() - 1) / m.num_vertices());
  for (uint32_t v = 0; v < d.fixed.size(); ++v) {
    uint32_t base = d.fixed[v];
    for (const uint32_t* q = d.incidence.quads_begin(v); q != d.incidence.quads_end(v); ++q)
      base += on_side(fo.quads[*q], v, false);
    b.lower = std::max(b.lower, domain ? DomainDegree(fo, d.incidence, v).sure() : d.fixed[v]);
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
  const bool domain = has_domain(fo.base);
  WorkCounter work;
  for (uint32_t v = 0; v < n; ++v) {
    const uint32_t* qs = d.incidence.quads_begin(v);
    const uint32_t nq = static_cast<uint32_t>(d.incidence.quads_end(v) - qs);
    if (d.fixed[v] + nq <= bound) continue;  // cannot exceed the bound
    Factor f;
    f.scope.assign(qs, qs + nq);
    f.table.resize(size_t(1) << nq);
    std::optional<DomainDegree> in_domain;
    if (domain) in_domain.emplace(fo, d.incidence, v);
    for (size_t idx = 0; idx < f.table.size(); ++idx) {
      uint32_t degree = d.fixed[v];
      for (uint32_t i = 0; i < nq; ++i) degree += on_side(fo.quads[qs[i]], v, (idx >> i) & 1);
      if (domain && degree > bound) degree = in_domain->of(idx);  // (never more than without one)
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
  // Within a domain the Delaunay triangulation's degree (over inside triangles)
  // is the tighter upper bound.
  if (has_domain(fo.base)) hi = std::min(hi, static_cast<uint32_t>(evaluate(Objective::MinmaxDegree, fo.base, limits.progress)));
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
