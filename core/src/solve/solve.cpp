#include "hodt/solve.hpp"

#include <algorithm>
#include <chrono>
#include <unordered_set>

#include "hodt/brute_force.hpp"
#include "hodt/domain.hpp"
#include "hodt/error.hpp"
#include "hodt/explain.hpp"
#include "hodt/solve_options.hpp"
#include "approx/approx.hpp"
#include "approx/baker.hpp"
#include "engines/roof_dual.hpp"
#include "exact/exact.hpp"
#include "exact/min_max_degree.hpp"
#include "higher_order/fills/fill_enumerator.hpp"
#include "higher_order/k_order.hpp"
#include "exact/factor_models.hpp"
#include "objectives/pair_measures.hpp"

namespace hodt {

namespace {
constexpr const char* kMethodIds[] = {"brute-force", "exact", "approx", "auto"};
}

const char* method_id(Method m) { return kMethodIds[static_cast<size_t>(m)]; }

std::optional<Method> parse_method(std::string_view id) {
  for (size_t k = 0; k < 4; ++k)
    if (id == kMethodIds[k]) return static_cast<Method>(k);
  return std::nullopt;
}

std::string method_ids() { return "brute-force, exact, approx, auto"; }

namespace {

DpLimits dp_limits(const SolveOptions& options) {
  DpLimits limits;
  limits.max_width = options.max_width;
  limits.progress = options.progress;
  return limits;
}

// The NP-hard objectives exactly: the factor graph DP over a tree decomposition.
// On a refusal, the model (and its roof dual) is left in *refused for Baker's scheme.
Solution solve_factor_graph(const FirstOrder& fo, Objective objective, const SolveOptions& options,
                            std::optional<ReducedModel>* refused = nullptr) {
  const DpLimits limits = dp_limits(options);
  Solution s;
  s.objective = objective;
  s.method = "exact";
  if (objective == Objective::MinmaxDegree) {
    s.choice = min_max_degree_exact(fo, limits);
  } else {
    // Pairwise terms (convex edges): the roof dual's persistent assignment first,
    // the decomposition then covers only the variables it leaves free.
    ReducedModel m = reduce_by_roof_dual(factor_model(fo, objective, limits), limits.progress);
    DpResult dp;
    try {
      dp = solve_exact(m.graph(), limits);
    } catch (const LimitError&) {
      if (refused) refused->emplace(std::move(m));
      throw;
    }
    if (options.explanation) {
      // Per quad: the free ones in their order and components, then each fixed
      // quad alone (a component of its own, as a quad without interactions).
      const Decomposition& d = dp.decomposition;
      ExactExplanation e{d.width, d.num_components, {}, std::vector<uint32_t>(fo.num_quads(), UINT32_MAX)};
      for (uint32_t i = 0; i < d.order.size(); ++i) {
        const uint32_t q = m.roof ? m.original[d.order[i]] : d.order[i];
        e.order.push_back(q), e.component[q] = d.component[d.order[i]];
      }
      for (uint32_t q = 0; q < fo.num_quads(); ++q)
        if (e.component[q] == UINT32_MAX) e.order.push_back(q), e.component[q] = e.num_components++;
      options.explanation->exact = std::move(e);
    }
    s.choice = m.expand(dp.choice);
    prefer_delaunay(m.model, s.choice, limits.progress);
  }
  s.optimal = true;
  s.value = evaluate(objective, triangulate(fo, s.choice), in_phase(limits.progress, Phase::Measuring));
  return s;
}

// options with progress in phase (progress.hpp).
SolveOptions in_phase(SolveOptions options, Phase phase) {
  options.progress = in_phase(options.progress, phase);
  return options;
}

Solution dispatch(const FirstOrder& fo, Objective objective, const SolveOptions& options) {
  // (Brute force: one count over every triangulation, so the phase knows its size.)
  if (options.method == Method::BruteForce)
    return brute_force(fo, objective, in_phase(options.progress, Phase::SolvingExactly, 1));
  const SolveOptions exactly = in_phase(options, Phase::SolvingExactly);
  // Polynomial objectives are always solved exactly (approx would only be worse).
  if (has_polynomial_exact(objective))
    return solve_polynomial(fo, objective, ExactOptions{options.trace, dp_limits(exactly), options.explanation});
  switch (options.method) {
    case Method::Exact:
      return solve_factor_graph(fo, objective, exactly);
    case Method::Approx:
      return approximate(fo, objective, in_phase(options, Phase::Approximating));
    case Method::Auto: {
      std::optional<ReducedModel> refused;
      try {  // exact when every component's decomposition fits the memory cap
        return solve_factor_graph(fo, objective, exactly, &refused);
      } catch (const LimitError& e) {
        Solution s = approximate(fo, objective, in_phase(options, Phase::Approximating), refused ? &*refused : nullptr);
        s.details = std::string("exact refused (") + e.what() + "); " + s.details;
        return s;
      }
    }
    default:
      break;
  }
  throw std::logic_error("unknown method");
}

// Can a first order triangulation have a triangle outside the domain? If not,
// every measure is the one without a domain, and the first order paths apply.
bool domain_reachable(const FirstOrder& fo) {
  if (!has_domain(fo.base)) return false;
  const Mesh& m = fo.base;
  for (uint32_t t = 0; t < m.num_triangles(); ++t)  // (the first one outside answers)
    if (!triangle_inside(m, base_triangle(m, t))) return true;
  for (uint32_t q = 0; q < fo.num_quads(); ++q)
    if (!edge_inside(m, fo.quads[q].c, fo.quads[q].d)) return true;  // (its sides are the base's)
  return false;
}

// Within a domain the exact first order paths read what the domain measures: a
// triangle's being inside depends on its own quad's choice only, so the 2-SAT
// models keep their terms, the extrema keep their claim structure, and the rules
// for convex vertices and total edge length leave to the factor graph only the
// quads that touch a triangle outside (exact.cpp, extrema.cpp, factor_models.cpp).
// The degree's feasibility tests count each vertex's neighbours over inside
// triangles (min_max_degree.cpp).
bool has_exact_in_domain(Method method) { return method == Method::Exact || method == Method::Auto; }

// Elsewhere (Baker's scheme, and what is over the factor graph's
// budget) the region engine, which reads the objective's terms as the domain
// measures them, solves order 1 too (its regions are the quads), and its
// triangulation becomes a choice of diagonals.
Solution solve_in_domain(const FirstOrder& fo, Objective objective, const SolveOptions& options) {
  if (!fo.is_delaunay) throw InputError("a domain (maxEdge) needs a terrain built from points, not a given triangulation");
  Solution s = k_order_solution(fo, objective, 1, options);
  std::unordered_set<uint64_t> edges;
  const Mesh& m = *s.mesh;
  for (uint32_t e = 0; e < m.triangles.size(); ++e) edges.insert(edge_key(m.origin(e), m.target(e)));
  s.choice.assign(fo.num_quads(), 0);
  for (uint32_t q = 0; q < fo.num_quads(); ++q) s.choice[q] = edges.count(edge_key(fo.quads[q].c, fo.quads[q].d)) > 0;
  s.mesh.reset();
  s.non_delaunay_edges = 0;
  return s;
}

}  // namespace

Solution solve(const FirstOrder& fo, Objective objective, const SolveOptions& options) {
  check_options(options);
  SolveOptions run = options;
  run.progress = as_phased(options.progress, options.progress_interval_ms);
  if (run.order > 1) return k_order_solution(fo, objective, run.order, run);
  const bool domain = run.method != Method::BruteForce && domain_reachable(fo);
  if (domain && (!fo.is_delaunay || !has_exact_in_domain(run.method))) return solve_in_domain(fo, objective, run);
  const auto t0 = std::chrono::steady_clock::now();
  Solution s;
  if (domain) {
    try {
      SolveOptions exact = run;
      exact.method = Method::Exact;
      s = dispatch(fo, objective, exact);
    } catch (const LimitError&) {
      return solve_in_domain(fo, objective, run);
    }
  } else {
    s = dispatch(fo, objective, run);
  }
  if (!s.critical && is_pair_objective(objective))
    s.critical = critical_pair(objective, triangulate(fo, s.choice), in_phase(run.progress, Phase::Measuring));
  s.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

}  // namespace hodt
