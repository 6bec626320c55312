#include "exact/factor_models.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "hodt/domain.hpp"
#include "hodt/format.hpp"
#include "hodt/measures.hpp"
#include "hodt/skeleton.hpp"
#include "exact/bottleneck.hpp"
#include "geometry/exact_sum.hpp"
#include "objectives/neighbourhood_classes.hpp"
#include "objectives/objective_terms.hpp"
#include "objectives/pair_measures.hpp"

namespace hodt {

namespace {

// The vertex's position, to name it in a message (the core knows no input index).
std::string vertex_at(const Mesh& m, uint32_t v) {
  return "the vertex at (" + format_number(m.point(v)[0]) + ", " + format_number(m.point(v)[1]) + ")";
}

// A vertex's neighbours over the choices of its quads: the fixed ones, and one
// per quad that comes with one of its diagonals (bit i of present: quad i's).
struct StarChoices {
  uint32_t vertex;
  const double* centre;
  std::vector<const double*> fixed, optional;
  std::vector<uint32_t> fixed_ids, optional_ids;  // the same neighbours, as vertex indices
  uint32_t present;
  // The neighbours of the present choice (in a buffer of its own).
  const std::vector<const double*>& neighbours() const {
    nb = fixed;
    for (uint32_t i = 0; i < optional.size(); ++i)
      if ((present >> i) & 1) nb.push_back(optional[i]);
    return nb;
  }
  mutable std::vector<const double*> nb;
};

// A term per vertex: value(star) over all choices of the quads at the star's vertex.
// work(d): steps to compute one entry for d neighbours. Terms over the budget are
// refused or left out (g.relaxed counts them) before any table is allocated.
template <class Work, class Value>
void vertex_terms(const FirstOrder& fo, bool interior_only, bool constants, FactorGraph& g, const DpLimits& limits,
                  OverBudget over, Work work, Value value) {
  const Mesh& m = fo.base;
  const VertexIncidence vi = vertex_incidence(fo);
  std::vector<uint8_t> on_hull(m.num_vertices(), 0);
  for (uint32_t v : m.hull) on_hull[v] = 1;
  // Fixed neighbours: the ends of non-diagonal edges (each seen from both ends, or
  // once on the hull: then the apex side gives the other).
  const std::vector<int32_t> out = vertex_halfedges(m);
  std::vector<uint32_t> fixed, around;
  auto fixed_neighbours = [&](uint32_t v) {
    fixed.clear();
    around.clear();
    if (out[v] >= 0) walk_star(m, static_cast<uint32_t>(out[v]), [&](uint32_t w, uint32_t) { around.push_back(w); });
    const uint32_t* qs = vi.quads_begin(v);
    const uint32_t nq = static_cast<uint32_t>(vi.quads_end(v) - qs);
    for (uint32_t w : around) {
      bool is_diagonal = false;  // v w is the base diagonal of one of v's quads
      for (uint32_t i = 0; i < nq; ++i) {
        const Quad& q = fo.quads[qs[i]];
        is_diagonal = is_diagonal || (q.a == v && q.b == w) || (q.b == v && q.a == w);
      }
      if (!is_diagonal) fixed.push_back(w);
    }
  };
  const uint32_t n = m.num_vertices();
  // Within a domain an interior vertex counts only with all its triangles inside
  // (docs/objectives.md, "The domain"): one beside a fixed triangle outside never
  // counts and has no term; per quad, the choices that put a triangle at the
  // vertex outside zero its term.
  const bool domain = has_domain(m);
  if (domain && !interior_only) throw std::logic_error("vertex terms within a domain: interior vertex sums only");
  auto left_out = [&](uint32_t v) {  // (on the hull, or beside a fixed triangle outside)
    if (on_hull[v] || !domain) return on_hull[v] != 0;
    for (uint32_t k = vi.fixed_offset[v]; k < vi.fixed_offset[v + 1]; ++k)
      if (!triangle_inside(m, base_triangle(m, vi.fixed[k]))) return true;
    return false;
  };
  std::vector<TermSize> sizes(n, TermSize{0, 0});
  WorkCounter progress;
  for (uint32_t v = 0; v < n; ++v) {
    if (progress.tick(32)) report(limits.progress, 0, n);
    const uint32_t nq = static_cast<uint32_t>(vi.quads_end(v) - vi.quads_begin(v));
    if (!constants && nq == 0) continue;
    if (interior_only && left_out(v)) {
      on_hull[v] = 1;
      continue;
    }
    if (nq == 0) continue;
    fixed_neighbours(v);
    sizes[v] = TermSize{nq, work(static_cast<uint32_t>(fixed.size()) + nq)};
  }
  const std::vector<uint8_t> keep = plan_terms(sizes, limits, over, [&](size_t v) {
    fixed_neighbours(static_cast<uint32_t>(v));
    return vertex_at(m, static_cast<uint32_t>(v)) + " has " + std::to_string(sizes[v].scope) +
           " flippable quads and " + std::to_string(fixed.size() + sizes[v].scope) + " possible neighbours around it";
  });
  StarChoices star;
  for (uint32_t v = 0; v < n; ++v) {
    if (progress.tick(32)) report(limits.progress, v, n);
    if ((interior_only && on_hull[v]) || (!constants && vi.quads_end(v) == vi.quads_begin(v))) continue;
    if (!keep[v]) {
      ++g.relaxed;
      continue;
    }
    fixed_neighbours(v);
    const uint32_t* qs = vi.quads_begin(v);
    const uint32_t nq = static_cast<uint32_t>(vi.quads_end(v) - qs);
    Factor f;
    f.scope.assign(qs, qs + nq);
    f.table.resize(size_t(1) << nq);
    // Each quad's diagonal through v adds its opposite corner, in one state.
    star.vertex = v, star.centre = m.point(v);
    star.fixed.clear();
    star.optional.clear();
    star.fixed_ids = fixed;
    star.optional_ids.clear();
    for (uint32_t w : fixed) star.fixed.push_back(m.point(w));
    uint32_t when_flipped = 0;  // bit i: quad i's corner comes with its flipped diagonal
    uint32_t outside_when[2] = {0, 0};  // bit i: quad i's choice puts a triangle at v outside
    for (uint32_t i = 0; i < nq; ++i) {
      const Quad& q = fo.quads[qs[i]];
      const bool on_base = v == q.a || v == q.b;
      star.optional_ids.push_back(on_base ? (v == q.a ? q.b : q.a) : (v == q.c ? q.d : q.c));
      star.optional.push_back(m.point(star.optional_ids.back()));
      if (!on_base) when_flipped |= 1u << i;
      for (int x = 0; x < 2 && domain; ++x) {
        Tri t[2];
        const uint32_t count = quad_triangles_at(fo, qs[i], v, x, t);
        for (uint32_t j = 0; j < count; ++j)
          if (!triangle_inside(m, t[j])) outside_when[x] |= 1u << i;
      }
    }
    for (size_t idx = 0; idx < f.table.size(); ++idx) {
      star.present = ~(static_cast<uint32_t>(idx) ^ when_flipped) & ((nq < 32 ? 1u << nq : 0u) - 1);
      const uint32_t choice = static_cast<uint32_t>(idx);
      if ((~choice & outside_when[0]) | (choice & outside_when[1])) {
        f.table[idx] = 0;
        continue;
      }
      f.table[idx] = value(star);
      if (progress.tick(sizes[v].work_per_entry + 1)) report(limits.progress, v, n);
    }
    if (nq == 0) {
      g.constant = g.combine == Combine::Sum ? g.constant + f.table[0] : std::max(g.constant, f.table[0]);
    } else {
      g.factors.push_back(std::move(f));
    }
  }
}

void add_factor(FactorGraph& g, std::vector<uint32_t> scope, std::vector<double> table) {
  g.factors.push_back(Factor{std::move(scope), std::move(table)});
}

// A sum term over the quads beside an edge: value(x, y) for choice x on the left
// (side L) and y on the right (R); a constant if both sides are fixed.
template <class Value>
void add_edge_factor(FactorGraph& g, const Side& L, const Side& R, Value value) {
  if (L.quad < 0 && R.quad < 0) g.constant += value(0, 0);
  else if (R.quad < 0) add_factor(g, {static_cast<uint32_t>(L.quad)}, {value(0, 0), value(1, 0)});
  else if (L.quad < 0) add_factor(g, {static_cast<uint32_t>(R.quad)}, {value(0, 0), value(0, 1)});
  else
    add_factor(g, {static_cast<uint32_t>(L.quad), static_cast<uint32_t>(R.quad)},
               {value(0, 0), value(1, 0), value(0, 1), value(1, 1)});
}

// Interior edge sums (convex edges): a term per edge of the skeleton and per
// quad diagonal, read from the objective's edge term.
void interior_edge_terms(const FirstOrder& fo, const ObjectiveTerms& d, FactorGraph& g, const Progress& progress) {
  WorkCounter work;  // a unit: about one predicate
  const double total = static_cast<double>(fo.num_quads() + fo.base.halfedges.size());
  const Mesh& m = fo.base;
  // Within a domain an interior edge counts with an inside triangle on each side.
  auto term = [&](const Tri& left, uint32_t x) {  // edge left[0] -> left[1], x across it
    if (has_domain(m) && (!triangle_inside(m, left) || !triangle_inside(m, {left[1], left[0], x}))) return 0.0;
    return d.edge(m, left[0], left[1], left[2], x);
  };
  auto across = [](const Tri& t, uint32_t u, uint32_t v) {  // the vertex of t other than u, v
    for (uint32_t w : t)
      if (w != u && w != v) return w;
    return t[0];
  };
  const std::vector<uint8_t> diagonal = fo.diagonal_mask();
  g.factors.reserve(fo.num_quads() + m.halfedges.size() / 2);
  for (uint32_t q = 0; q < fo.num_quads(); ++q) {
    const Quad& k = fo.quads[q];
    add_factor(g, {q}, {term({k.a, k.b, k.c}, k.d), term({k.d, k.c, k.a}, k.b)});
    if (work.tick(16)) report(progress, q, total);
  }
  for (uint32_t e = 0; e < m.halfedges.size(); ++e) {
    if (work.tick(16)) report(progress, fo.num_quads() + e, total);
    const int32_t f = m.halfedges[e];
    if (f < static_cast<int32_t>(e) || diagonal[e]) continue;
    const uint32_t u = m.origin(e), v = m.target(e);
    const Side L = side_of(fo, e), R = side_of(fo, static_cast<uint32_t>(f));
    auto value = [&](int x, int y) {
      const Tri& l = L.tri[x];
      // Rotate l to start at u (it holds u -> v).
      const Tri lu = l[0] == u ? l : l[1] == u ? Tri{l[1], l[2], l[0]} : Tri{l[2], l[0], l[1]};
      return term(lu, across(R.tri[y], u, v));
    };
    add_edge_factor(g, L, R, value);
  }
}

// Edge sums whose terms read no apex (total length): a term per quad diagonal
// and per skeleton edge. Within a domain an edge counts with an inside triangle
// on either side, so an edge of a quad's boundary depends on the quads on both
// sides. Without one the fixed edges are one constant (summed as evaluate sums).
// (Within a domain the constant is a plain sum: the solvers report the value
// they evaluate on the triangulation, never this one.)
void apex_free_edge_terms(const FirstOrder& fo, const ObjectiveTerms& d, bool constants, FactorGraph& g) {
  const Mesh& m = fo.base;
  auto term = [&](uint32_t u, uint32_t v) { return d.edge(m, u, v, kNoApex, kNoApex); };
  const bool domain = has_domain(m);
  auto in = [&](const Tri& t) { return !domain || triangle_inside(m, t); };
  for (uint32_t q = 0; q < fo.num_quads(); ++q) {
    const Quad& k = fo.quads[q];
    const bool base = in({k.a, k.b, k.c}) || in({k.b, k.a, k.d}), flipped = in({k.d, k.c, k.a}) || in({k.c, k.d, k.b});
    add_factor(g, {q}, {base ? term(k.a, k.b) : 0, flipped ? term(k.c, k.d) : 0});
  }
  const std::vector<uint8_t> diagonal = fo.diagonal_mask();
  ExactSum fixed;
  for (uint32_t e = 0; e < m.halfedges.size(); ++e) {
    const int32_t f = m.halfedges[e];
    if (diagonal[e] || f > static_cast<int32_t>(e)) continue;
    if (!domain) {
      fixed.add(term(m.origin(e), m.target(e)));
      continue;
    }
    if (!constants && fo.quad_of_triangle[e / 3] < 0 && (f < 0 || fo.quad_of_triangle[static_cast<uint32_t>(f) / 3] < 0)) continue;
    const Side L = side_of(fo, e);
    const Side R = f >= 0 ? side_of(fo, static_cast<uint32_t>(f)) : Side{-1, {}};
    if (!constants && L.quad < 0 && R.quad < 0) continue;
    const double len = term(m.origin(e), m.target(e));
    auto value = [&](int x, int y) { return in(L.tri[x]) || (f >= 0 && in(R.tri[y])) ? len : 0.0; };
    add_edge_factor(g, L, R, value);
  }
  if (!domain) g.constant = fixed.value();
}

// Triangle terms: the fixed triangles' as the constant, each quad's two
// triangles for either diagonal as its factor.
void triangle_terms(const FirstOrder& fo, const ObjectiveTerms& d, FactorGraph& g) {
  const Mesh& m = fo.base;
  // (Within a domain a triangle outside is not measured.)
  auto triangle_term = [&](const ObjectiveTerms& terms, const Mesh& mesh, const Tri& t) {
    return has_domain(mesh) && !triangle_inside(mesh, t) ? 0.0 : terms.triangle(mesh, t);
  };
  for (uint32_t t = 0; t < m.num_triangles(); ++t)
    if (fo.quad_of_triangle[t] < 0) g.constant = combine(g.combine, g.constant, triangle_term(d, m, base_triangle(m, t)));
  auto choice = [&](uint32_t q, bool flipped) {
    uint32_t t[6];
    fo.triangles_of(q, flipped, t);
    return combine(g.combine, triangle_term(d, m, {t[0], t[1], t[2]}), triangle_term(d, m, {t[3], t[4], t[5]}));
  };
  for (uint32_t q = 0; q < fo.num_quads(); ++q) add_factor(g, {q}, {choice(q, false), choice(q, true)});
}

void pair_terms(const BottleneckModel& bm, FactorGraph& g) {
  g.constant = std::max(g.constant, bm.floor);
  for (const PairTerm& t : bm.terms) {
    if (t.r < 0) add_factor(g, {static_cast<uint32_t>(t.q)}, {t.v[0], t.v[1]});
    else add_factor(g, {static_cast<uint32_t>(t.q), static_cast<uint32_t>(t.r)}, {t.v[0], t.v[1], t.v[2], t.v[3]});
  }
}

}  // namespace

FactorGraph factor_model(const FirstOrder& fo, Objective o, const DpLimits& limits, OverBudget over, bool constants) {
  const Mesh& m = fo.base;
  // The objective's terms (objective_terms.hpp) with every summary: the model
  // follows their site and the summary they offer, and handles the domain itself.
  const ObjectiveTerms& d = objective_terms_inside(o);
  FactorGraph g;
  g.num_vars = fo.num_quads();
  g.sense = info(o).sense;
  g.combine = info(o).combine;
  // Steps per entry: a vertex class tests triples of neighbours, the others scan them.
  auto triples = [](uint32_t n) { return n * (n - 1.0) * (n - 2.0) / 6 + n * (n - 1.0) / 2; };
  auto scan = [](uint32_t n) { return static_cast<double>(n); };
  // The classes of a vertex over the choices of its quads, from one look at its
  // candidate neighbours (the choices come one vertex after another).
  std::optional<NeighbourhoodClasses> classes;
  uint32_t classes_of = UINT32_MAX;
  auto class_of = [&](const StarChoices& star) {
    if (star.vertex != classes_of) classes.emplace(star.centre, star.fixed, star.optional), classes_of = star.vertex;
    return classes->of(star.present);
  };
  auto neighbour_classes = [&](const StarChoices& star) {
    uint32_t mask = 0;
    for (uint32_t w : star.fixed_ids) mask |= 1u << d.neighbor_class(m, star.vertex, w);
    for (uint32_t i = 0; i < star.optional_ids.size(); ++i)
      if ((star.present >> i) & 1) mask |= 1u << d.neighbor_class(m, star.vertex, star.optional_ids[i]);
    return mask;
  };
  switch (d.site) {
    case TermSite::InteriorVertex:
    case TermSite::Vertex: {
      const bool interior = d.site == TermSite::InteriorVertex;
      if (d.term_of_vertex_class)
        vertex_terms(fo, interior, constants, g, limits, over, triples,
                     [&](const StarChoices& star) { return d.term_of_vertex_class(class_of(star)); });
      else if (d.term_of_classes)
        vertex_terms(fo, interior, constants, g, limits, over, scan,
                     [&](const StarChoices& star) { return d.term_of_classes(neighbour_classes(star)); });
      else if (d.term_of_degree)
        vertex_terms(fo, interior, constants, g, limits, over, scan, [&](const StarChoices& star) {
          return d.term_of_degree(static_cast<uint32_t>(star.fixed.size()) + static_cast<uint32_t>(__builtin_popcount(star.present)));
        });
      else
        throw std::logic_error("factor model: a vertex term without a summary of its star");
      break;
    }
    case TermSite::InteriorEdge: interior_edge_terms(fo, d, g, limits.progress); break;
    case TermSite::Edge:
      if (d.edge_reads_apexes) throw std::logic_error("factor model: an edge term over every edge that reads its apexes");
      apex_free_edge_terms(fo, d, constants, g);
      break;
    case TermSite::Triangle: triangle_terms(fo, d, g); break;
    case TermSite::EdgePair:
    case TermSite::VertexPair: {
      const bool edge = d.site == TermSite::EdgePair;
      auto model = [&](auto measure) { return edge ? edge_pair_model(fo, measure) : vertex_pair_model(fo, measure); };
      switch (d.measure) {
        case PairMeasure::AreaRatio: pair_terms(model([&](const Tri& s, const Tri& t) { return pair_area_ratio(m, s, t); }), g); break;
        case PairMeasure::NormalAngle: pair_terms(model([&](const Tri& s, const Tri& t) { return pair_normal_angle(m, s, t); }), g); break;
        case PairMeasure::EnclosingCircle:
          pair_terms(model([&](const Tri& s, const Tri& t) { return pair_enclosing_circle(m, s, t); }), g);
          break;
        case PairMeasure::None: throw std::logic_error("factor model: a pair term without a measure");
      }
      break;
    }
  }
  g.simplify(limits.progress);
  return g;
}

}  // namespace hodt
