#include "higher_order/k_order.hpp"

#include <algorithm>
#include <chrono>
#include <unordered_set>

#include "hodt/error.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/solve.hpp"
#include "hodt/solve_options.hpp"
#include "higher_order/fills/fill_enumerator.hpp"
#include "higher_order/phases/phase_table.hpp"
#include "mesh/mesh_of.hpp"
#include "objectives/pair_measures.hpp"
#include "tuning/budgets.hpp"

namespace hodt {

bool enumerate_k_order(const Mesh& dt, uint32_t k, uint64_t max_nodes,
                       const std::function<void(const std::vector<Tri>&)>& visit, const Progress& progress) {
  const Candidates cand = k_order_candidates(dt, k, useful_edges(dt, k));
  std::vector<std::pair<uint32_t, uint32_t>> hull;
  for (size_t i = 0; i < dt.hull.size(); ++i) hull.push_back({dt.hull[i], dt.hull[(i + 1) % dt.hull.size()]});
  return enumerate_fills(dt, cand, hull, max_nodes, visit, progress);
}

namespace {

KOrderResult brute_force_k_order(const Mesh& dt, Objective o, uint32_t k, uint64_t max_nodes, const Progress& progress) {
  if (dt.num_vertices() > kBudgets.brute_force_max_points)
    throw LimitError("brute force at order " + std::to_string(k) + " enumerates every k-OD triangulation and refuses " +
                     std::to_string(dt.num_vertices()) + " points (at most " +
                     std::to_string(kBudgets.brute_force_max_points) + "); use --method exact or auto");
  KOrderResult r;
  const Sense sense = info(o).sense;
  bool have = false;
  std::vector<Tri> best;
  const bool complete = enumerate_k_order(dt, k, max_nodes, [&](const std::vector<Tri>& tris) {
    ++r.enumerated;
    const double v = evaluate(o, mesh_of(dt.coords, tris));
    if (!have || better(sense, v, r.value)) r.value = v, best = tris, have = true;
  }, progress);
  if (!complete || !have)
    throw LimitError("brute force at order " + std::to_string(k) + ": more than " + std::to_string(max_nodes) +
                     " search nodes; use --method exact or auto");
  r.triangulation = mesh_of(dt.coords, best);
  r.optimal = true;
  r.method = "brute-force";
  r.details = std::to_string(r.enumerated) + " k-OD triangulations enumerated";
  return r;
}

}  // namespace

KOrderResult solve_k_order(const FirstOrder& fo, Objective o, uint32_t k, const SolveOptions& options,
                           const RegionLimits& budgets) {
  if (!fo.is_delaunay) throw InputError("higher order needs the Delaunay triangulation: not for user triangulations");
  KOrderResult r;
  if (options.method == Method::BruteForce) {
    r = brute_force_k_order(fo.base, o, k, budgets.max_nodes_per_region, in_phase(options.progress, Phase::SolvingExactly));
  } else {
    FirstOrderStart first_order{fo, o, options, {}, 0, {}};
    VertexTermMemo memo;
    const KOrderShared shared{fo, o, options, budgets, first_order, &memo, {}};
    r = solve_at_order(shared, k, options, true, nullptr);
  }
  r.delaunay_value = evaluate(o, fo.base);
  return r;
}

KOrderResult solve_k_order(const FirstOrder& fo, Objective o, uint32_t k, const SolveOptions& options, uint64_t max_nodes) {
  RegionLimits budgets;
  budgets.max_nodes_per_region = max_nodes;
  return solve_k_order(fo, o, k, options, budgets);
}

Solution k_order_solution(const FirstOrder& fo, Objective o, uint32_t k, const SolveOptions& options) {
  SolveOptions checked = options;
  checked.order = k;
  check_options(checked);
  const auto t0 = std::chrono::steady_clock::now();
  KOrderResult r = solve_k_order(fo, o, k, options);
  if (!is_k_order(r.triangulation, fo.base, k, in_phase(options.progress, Phase::Measuring))) throw std::logic_error("order k result is not k-OD");
  Solution s;
  s.objective = o;
  s.method = r.method;
  s.order = k;
  s.value = r.value;
  s.delaunay_value = r.delaunay_value;
  s.optimal = r.optimal;
  s.bound = r.bound;
  s.details = r.details;
  if (options.trace) s.phases = std::move(r.phases);
  // Edges of the result that are not Delaunay edges.
  std::unordered_set<uint64_t> delaunay_edges;
  const Mesh& dt = fo.base;
  for (uint32_t e = 0; e < dt.triangles.size(); ++e)
    delaunay_edges.insert(edge_key(std::min(dt.origin(e), dt.target(e)), std::max(dt.origin(e), dt.target(e))));
  const Mesh& m = r.triangulation;
  for (uint32_t e = 0; e < m.triangles.size(); ++e)
    if (m.halfedges[e] < static_cast<int32_t>(e))
      s.non_delaunay_edges += !delaunay_edges.count(edge_key(std::min(m.origin(e), m.target(e)), std::max(m.origin(e), m.target(e))));
  s.critical = critical_pair(o, m, {}, r.value);  // (its value known: pairs below it cut short)
  s.mesh = std::move(r.triangulation);
  s.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

}  // namespace hodt
