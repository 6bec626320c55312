#include "approx/approx.hpp"

#include <algorithm>

#include "hodt/error.hpp"
#include "hodt/explain.hpp"
#include "hodt/skeleton.hpp"
#include "approx/baker.hpp"
#include "exact/min_max_degree.hpp"
#include "exact/factor_models.hpp"

namespace hodt {

namespace {

// The count of non-mixed interior vertices, as a maximised sum: 1 - mixed per factor.
// A vertex whose term was relaxed (left out) counts as non-mixed: its best.
FactorGraph non_mixed_model(const FirstOrder& fo, FactorGraph g) {
  const uint32_t interior = fo.base.num_vertices() - static_cast<uint32_t>(fo.base.hull.size());
  g.sense = Sense::Max;
  g.constant = interior - g.constant - static_cast<double>(g.factors.size());
  for (Factor& f : g.factors)
    for (double& v : f.table) v = 1 - v;
  return g;
}

// Every factor at its best: a bound on the optimum of a maximised sum.
double best_possible(const FactorGraph& g) {
  double top = g.constant;
  for (const Factor& f : g.factors) top += *std::max_element(f.table.begin(), f.table.end());
  return top;
}

Solution baker_solution(const FirstOrder& fo, Objective o, const SolveOptions& options, ReducedModel* built) {
  DpLimits limits;
  limits.max_width = options.max_width;
  limits.progress = options.progress;
  const bool mixed = o == Objective::MinMixedVertices;
  // After exact refused (built given): pairwise terms (convex edges) first go
  // through the roof dual, the scheme runs on the variables it leaves free, and
  // the better of the two bounds holds. Asked for by name, approx is the paper's
  // scheme over every quad (the teaching view shows its shifts).
  const bool reduce = built != nullptr;
  std::optional<ReducedModel> own;
  if (!built || built->model.sense != Sense::Max) {
    // Vertex terms too large to tabulate are relaxed: counted at their best value
    // in the bound (which stays certified), and measured for real in the value.
    FactorGraph g = factor_model(fo, o, limits, OverBudget::Relax);
    if (mixed) g = non_mixed_model(fo, std::move(g));
    if (reduce) built = &own.emplace(reduce_by_roof_dual(std::move(g), limits.progress));
    else (built = &own.emplace())->model = std::move(g);
  }
  ReducedModel& m = *built;
  auto tighter = [&](double b) {
    if (!m.roof) return b;
    return m.model.sense == Sense::Max ? std::min(b, m.roof->bound) : std::max(b, m.roof->bound);
  };
  Solution s;
  s.objective = o;
  s.method = "approx";
  double bound;
  const uint32_t interior = fo.base.num_vertices() - static_cast<uint32_t>(fo.base.hull.size());
  // The scheme maximises non-mixed vertices; the fewest mixed is interior - that.
  auto units = [&](double x) { return mixed ? interior - x : x; };
  Choice x;  // over m.graph()
  try {
    std::vector<uint32_t> layer = quad_layers(fo, limits.progress);
    BakerResult r = baker(m.graph(), m.restrict(layer), options.epsilon, limits, UINT32_MAX, options.explanation != nullptr);
    if (options.explanation) {
      BakerExplanation& e = options.explanation->baker.emplace();
      e.lambda = r.lambda, e.width = r.width, e.layer = std::move(layer);
      for (size_t i = 0; i < r.shifts.size(); ++i) {
        const BakerShift& b = r.shifts[i];
        Choice shift = m.expand(r.shift_choices[i]);
        e.shifts.push_back({b.shift, units(b.relaxed), evaluate(o, triangulate(fo, shift), limits.progress),
                            units(b.bound), b.dropped, std::move(shift)});
      }
    }
    x = std::move(r.choice);
    bound = tighter(r.bound);
    s.details = "lambda " + std::to_string(r.lambda) + ", " + std::to_string(r.shifts.size()) +
                " shifts, widest thick layer " + std::to_string(r.width);
  } catch (const LimitError& e) {
    // A thick layer too wide for the DP: the local search alone, from Delaunay,
    // with every term at its best as the bound.
    x.assign(m.graph().num_vars, 0);
    bound = tighter(best_possible(m.graph()));
    s.details = std::string("Baker's scheme refused (") + e.what() + "); local search from Delaunay, bound: every term at its best";
  }
  if (m.roof)
    s.details = "the roof dual fixed " + std::to_string(m.roof->num_fixed) + " of " + std::to_string(m.model.num_vars) +
                " quads; on the others: " + s.details;
  if (m.model.relaxed)
    s.details += "; " + std::to_string(m.model.relaxed) +
                 " vertex terms too large to tabulate were relaxed (counted at their best in the bound)";
  s.local_search_improved = improve_locally(m.graph(), x, options.progress);
  s.choice = m.expand(x);
  prefer_delaunay(m.model, s.choice, options.progress);
  s.value = evaluate(o, triangulate(fo, s.choice), options.progress);
  s.bound = units(bound);  // mixed: a lower bound on the fewest mixed
  s.optimal = s.value == *s.bound;
  return s;
}

// Max degree: repeatedly flip a quad at a vertex of maximum degree when that
// lowers the number of vertices at the maximum without creating a new one.
Solution degree_solution(const FirstOrder& fo, const SolveOptions& options) {
  const Mesh& m = fo.base;
  const uint32_t n = m.num_vertices(), nq = fo.num_quads();
  const VertexIncidence vi = vertex_incidence(fo);
  std::vector<uint32_t> degree(n, 0);
  for (uint32_t e = 0; e < m.triangles.size(); ++e)
    if (m.halfedges[e] < static_cast<int32_t>(e)) ++degree[m.origin(e)], ++degree[m.target(e)];
  Choice x(nq, 0);
  auto ends = [&](uint32_t q, bool side) {
    const Quad& k = fo.quads[q];
    return side ? std::pair{k.c, k.d} : std::pair{k.a, k.b};
  };
  auto flip = [&](uint32_t q) {
    auto [u, w] = ends(q, x[q]);
    --degree[u], --degree[w];
    x[q] ^= 1;
    auto [p, r] = ends(q, x[q]);
    ++degree[p], ++degree[r];
  };
  WorkCounter work;
  for (int round = 0; round < 1000; ++round) {
    report(options.progress, round, 1000);
    const uint32_t top = *std::max_element(degree.begin(), degree.end());
    bool moved = false;
    for (uint32_t v = 0; v < n; ++v) {
      if (work.tick()) report(options.progress, round + double(v) / n, 1000);
      if (degree[v] != top) continue;
      for (const uint32_t* q = vi.quads_begin(v); q != vi.quads_end(v); ++q) {
        auto [u, w] = ends(*q, x[*q]);
        if (u != v && w != v) continue;  // the chosen diagonal does not touch v
        auto [p, r] = ends(*q, !x[*q]);
        if (degree[p] + 1 >= top || degree[r] + 1 >= top) continue;
        flip(*q);
        moved = true;
        break;
      }
    }
    if (!moved) break;
  }
  Solution s;
  s.objective = Objective::MinmaxDegree;
  s.method = "approx";
  s.choice = std::move(x);
  s.value = evaluate(Objective::MinmaxDegree, triangulate(fo, s.choice), options.progress);
  // Raise the lower bound (or lower the value) with every feasibility test that
  // fits the memory cap: "no" proves the bound, "yes" gives a better choice.
  uint32_t bound = degree_bounds(fo).lower;
  DpLimits limits;
  limits.max_width = options.max_width;
  limits.progress = options.progress;
  std::string how = "local search";
  try {
    while (bound < s.value) {
      const DpResult r = solve_exact(degree_feasibility_model(fo, bound, limits), limits);
      if (r.value == 0) {
        s.choice = r.choice;
        s.value = bound;
        how = "feasibility DP";
        break;
      }
      ++bound;
    }
  } catch (const LimitError& e) {
    how += "; feasibility DP refused at degree " + std::to_string(bound) + " (" + e.what() + ")";
  }
  s.bound = bound;
  s.optimal = s.value == bound;
  s.details = how + "; proven ratio 2 (value <= 2 * bound)";
  return s;
}

}  // namespace

Solution approximate(const FirstOrder& fo, Objective o, const SolveOptions& options, ReducedModel* built) {
  if (info(o).polynomial) throw std::logic_error("approximate: polynomial objectives are solved exactly");
  // Baker's shifting approximates any sum of local terms (Theorems 7 and 8);
  // the degree has its own bound.
  if (info(o).combine == Combine::Sum) return baker_solution(fo, o, options, built);
  if (o == Objective::MinmaxDegree) return degree_solution(fo, options);
  throw std::logic_error(std::string("approximate: no approximation for ") + info(o).id);
}

}  // namespace hodt
