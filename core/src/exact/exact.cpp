// The polynomial exact algorithms, one function per objective family.
#include "exact/exact.hpp"

#include "hodt/domain.hpp"
#include "hodt/error.hpp"
#include "hodt/explain.hpp"
#include "hodt/measures.hpp"
#include "hodt/skeleton.hpp"
#include "exact/bottleneck.hpp"
#include "exact/extrema.hpp"
#include "exact/free_quads.hpp"
#include "objectives/objective_terms.hpp"
#include "objectives/pair_measures.hpp"

#include <algorithm>

namespace hodt {

namespace {

// The objectives whose optimum is a rule applied to each quad alone: `flip(q)`
// says whether quad q takes its other diagonal. Within a domain the quads
// touching an outside triangle interact (which terms count depends on them), so
// for any choice of theirs the rule is still best in the others, and those
// quads alone go to the factor graph.
template <class Flip>
Choice by_rule_per_quad(const FirstOrder& fo, Objective o, const DpLimits& limits, Flip flip) {
  Choice c(fo.num_quads(), 0);
  WorkCounter work;
  for (uint32_t q = 0; q < fo.num_quads(); ++q) {
    if (work.tick(16)) report(limits.progress, q, fo.num_quads());
    c[q] = flip(fo.quads[q]);
  }
  if (has_domain(fo.base)) solve_free_quads(fo, o, quads_touching_outside(fo), c, limits);
  return c;
}

// Theorem 1: in every quad take the reflex diagonal. A convex vertex stays convex
// when a convex diagonal at it is replaced by the reflex one, and non-convex
// vertices can only become convex, so this maximises convex vertices. (Within a
// domain, which vertices count depends only on the quads touching outside.)
Choice reflex_diagonals(const FirstOrder& fo, const DpLimits& limits) {
  const Mesh& m = fo.base;
  return by_rule_per_quad(fo, Objective::MaxConvexVertices, limits, [&](const Quad& k) {
    return edge_shape(m.point(k.a), m.point(k.b), m.point(k.c), m.point(k.d)) == kConvexEdge;
  });
}

// Total edge length is a sum over edges, and a quad's choice changes only its
// diagonal: the shorter diagonal in every quad is optimal (ties keep Delaunay).
// (Within a domain, a quad whose triangles are inside either way still counts
// its diagonal and its sides whatever the rest choose.)
Choice shorter_diagonals(const FirstOrder& fo, const DpLimits& limits) {
  const Mesh& m = fo.base;
  return by_rule_per_quad(fo, Objective::MinTotalEdgeLength, limits, [&](const Quad& k) {
    return edge_length(m.point(k.c), m.point(k.d)) < edge_length(m.point(k.a), m.point(k.b));
  });
}

// The largest triangle is the max over fixed triangles and, per quad, the larger
// of its two triangles: independent per quad, so each quad takes the diagonal
// whose larger triangle is smaller (ties keep Delaunay).
Choice smaller_largest_triangles(const FirstOrder& fo, const Progress& progress) {
  WorkCounter work;
  // The optimum is the larger of the largest fixed triangle and, over the quads,
  // the smaller of their two options; a quad flips only if Delaunay exceeds it.
  const Mesh& m = fo.base;
  // Triangles whose area is bounded below the running optimum by the margin
  // 2^-46 (the accurate area is within 4 ulps of the exact one) cannot raise it
  // or exceed it: most skip the accurate area.
  double optimum = 0;
  // (Within a domain a triangle outside is not measured: below anything.)
  auto below = [&](uint32_t a, uint32_t b, uint32_t c) {
    return rough_area_bounds(m.point(a), m.point(b), m.point(c)).hi * (1 + 0x1p-46) <= optimum ||
           !triangle_inside(m, {a, b, c});
  };
  auto largest = [&](uint32_t q, bool flipped) {  // of the choice's measured triangles
    if (!has_domain(m)) return largest_triangle(fo, q, flipped);
    uint32_t t[6];
    fo.triangles_of(q, flipped, t);
    double a = 0;
    for (int k = 0; k < 6; k += 3)
      if (triangle_inside(m, {t[k], t[k + 1], t[k + 2]})) a = std::max(a, triangle_area(m.point(t[k]), m.point(t[k + 1]), m.point(t[k + 2])));
    return a;
  };
  auto choice_below = [&](uint32_t q, bool flipped) {  // both triangles of the choice
    uint32_t t[6];
    fo.triangles_of(q, flipped, t);
    return below(t[0], t[1], t[2]) && below(t[3], t[4], t[5]);
  };
  for (uint32_t t = 0; t < m.num_triangles(); ++t) {
    if (fo.quad_of_triangle[t] < 0 && !below(m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]))
      optimum = std::max(optimum, triangle_area(m.point(m.triangles[3 * t]), m.point(m.triangles[3 * t + 1]),
                                                m.point(m.triangles[3 * t + 2])));
    if (work.tick(8)) report(progress, t, m.num_triangles());
  }
  for (uint32_t q = 0; q < fo.num_quads(); ++q) {
    if (!choice_below(q, false) && !choice_below(q, true))
      optimum = std::max(optimum, std::min(largest(q, false), largest(q, true)));
    if (work.tick(16)) report(progress, q, fo.num_quads());
  }
  Choice c(fo.num_quads(), 0);
  for (uint32_t q = 0; q < fo.num_quads(); ++q) {
    c[q] = !choice_below(q, false) && largest(q, false) > optimum;
    if (work.tick(8)) report(progress, q, fo.num_quads());
  }
  return c;
}

BottleneckModel pair_model(const FirstOrder& fo, Objective o, const Progress& progress) {
  const Mesh& m = fo.base;
  // Within a domain only pairs of inside triangles are measured; whether a
  // triangle is inside depends on its own quad's choice alone, so the model keeps
  // its terms and a pair with a triangle outside is worth 0 (the least value).
  // A measure may answer any value up to the cut for a pair at most the cut
  // (pair_measures.hpp), as 0 is: only a value above it needs the domain's word.
  const bool domain = has_domain(m);
  auto measured = [&](const Tri& s, const Tri& t, double cut, double v) {
    return v <= cut || !domain || (triangle_inside(m, s) && triangle_inside(m, t)) ? v : 0;
  };
  // With a cut: the search needs only values above the floor (a pruned model),
  // and most pairs are far below it (pair_measures.hpp).
  auto ratio = [&](const Tri& s, const Tri& t, double cut) { return measured(s, t, cut, pair_area_ratio(m, s, t, cut)); };
  auto angle = [&](const Tri& s, const Tri& t, double cut) { return measured(s, t, cut, pair_normal_angle(m, s, t, cut)); };
  auto circle = [&](const Tri& s, const Tri& t, double cut) {
    return measured(s, t, cut, pair_enclosing_circle(m, s, t, cut));
  };
  // A star's filter (pair_measures.hpp) sees its inside triangles only.
  std::vector<Tri> inside;
  auto star_filter = [&](bool (*below)(const Mesh&, const Tri*, size_t, double)) {
    return [&, below](const Tri* t, size_t n, double cut) {
      if (!domain) return below(m, t, n, cut);
      inside.clear();
      for (size_t i = 0; i < n; ++i)
        if (triangle_inside(m, t[i])) inside.push_back(t[i]);
      return below(m, inside.data(), inside.size(), cut);
    };
  };
  const ObjectiveTerms& d = objective_terms_inside(o);
  const bool edge = d.site == TermSite::EdgePair;
  switch (d.measure) {
    case PairMeasure::AreaRatio:
      if (edge) return edge_pair_model(fo, ratio, progress);
      return vertex_pair_model(fo, ratio, progress, star_filter(star_area_ratio_below));
    case PairMeasure::NormalAngle:
      if (edge) return edge_pair_model(fo, angle, progress);
      return vertex_pair_model(fo, angle, progress, star_filter(star_normal_angle_below));
    case PairMeasure::EnclosingCircle:
      if (edge) return edge_pair_model(fo, circle, progress);
      break;
    case PairMeasure::None: break;
  }
  throw std::logic_error("not an objective over edge pairs or vertex pairs");
}

}  // namespace

bool has_polynomial_exact(Objective o) { return info(o).polynomial; }

Solution solve_polynomial(const FirstOrder& fo, Objective o, const ExactOptions& options) {
  Solution s;
  s.objective = o;
  s.method = "exact";
  s.optimal = true;
  const Progress& progress = options.limits.progress;
  double expected = -INFINITY;  // the search's optimum, for the critical pair
  if (!info(o).polynomial) throw LimitError(std::string(info(o).id) + " is NP-hard: it has no polynomial exact algorithm");
  if (is_pair_objective(o)) {  // the paper's bottleneck search over its measure's model
    BottleneckResult r = solve_bottleneck(pair_model(fo, o, progress), progress,
                                          options.explanation ? &options.explanation->search.emplace() : nullptr);
    s.choice = std::move(r.choice);
    expected = r.value;
    if (options.trace) s.trace = std::move(r.trace);
  } else {
    switch (o) {
      case Objective::MaxConvexVertices: s.choice = reflex_diagonals(fo, options.limits); break;
      case Objective::MinTotalEdgeLength: s.choice = shorter_diagonals(fo, options.limits); break;
      case Objective::MinmaxTriangleArea: s.choice = smaller_largest_triangles(fo, progress); break;
      case Objective::MinLocalMinima: s.choice = fewest_local_minima(fo, options.limits); break;
      case Objective::MinLocalExtrema: s.choice = fewest_local_extrema(fo, options.limits); break;
      default: throw std::logic_error(std::string(info(o).id) + ": the table calls it polynomial, but no algorithm is given");
    }
  }
  const Mesh mesh = triangulate(fo, s.choice);
  s.critical = critical_pair(o, mesh, progress, expected);
  s.value = s.critical ? s.critical->value : evaluate(o, mesh, progress);  // the same number, computed once
  return s;
}

}  // namespace hodt
