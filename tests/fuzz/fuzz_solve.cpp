// Solve against brute force: a small terrain, an objective, an order 1..5 and
// maybe a domain from the input. Every method that answers must give a finite
// value equal to its triangulation's, a k-OD triangulation, and never claim
// `optimal` (or a bound) that brute force contradicts. At order k > 1 also with
// region budgets of a few kept fills and search nodes, so that regions stay
// incomplete and the bounds and proofs for large terrains (duals, fill graphs,
// views, stars) answer.
#include <cmath>
#include <cstdio>

#include "hodt/error.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/measures.hpp"
#include "hodt/solve.hpp"
#include "hodt/terrain.hpp"
#include "fuzz_input.hpp"
#include "higher_order/k_order.hpp"

using namespace hodt;

namespace {

[[noreturn]] void fail(const char* what, double a, double b) {
  std::fprintf(stderr, "fuzz_solve: %s (%.17g vs %.17g)\n", what, a, b);
  __builtin_trap();
}

bool same(double a, double b) { return a == b || std::fabs(a - b) <= 1e-9 * std::max(std::fabs(a), std::fabs(b)); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::Bytes in{data, size};
  const uint32_t n = 3 + in.byte() % 7;  // 3..9 points: brute force is instant
  const Objective o = static_cast<Objective>(in.byte() % kNumObjectives);
  const uint32_t order = 1 + in.byte() % 5;
  const uint64_t region_budget = 1 + in.byte() % 16;
  const uint8_t domain = in.byte() % 4;
  std::vector<double> xyz = fuzz::points(in, n);
  Terrain t;
  try {
    t = Terrain::from_points(xyz, Dedupe::KeepFirst);
    if (domain) t.set_max_edge(domain * 1.5);
  } catch (const InputError&) {
    return 0;  // refused with a message: fine
  }
  SolveOptions bf;
  bf.method = Method::BruteForce;
  bf.order = order;
  Solution reference;
  try {
    reference = solve(t.structure(), o, bf);
  } catch (const LimitError&) {
    return 0;
  }
  const Sense sense = info(o).sense;
  auto check = [&](const Mesh& mesh, double value, bool optimal, const std::optional<double>& bound) {
    if (!std::isfinite(value)) fail("non-finite value", value, 0);
    if (!same(evaluate(o, mesh), value)) fail("value is not its triangulation's", evaluate(o, mesh), value);
    if (order > 1 && !is_k_order(mesh, t.structure().base, order)) fail("result is not k-OD", order, 0);
    if (better(sense, value, reference.value) && !same(value, reference.value))
      fail("better than brute force", value, reference.value);
    if (optimal && !same(value, reference.value)) fail("optimal but brute force is better", value, reference.value);
    if (!optimal && !bound) fail("neither optimal nor bounded", value, 0);
    if (bound && better(sense, reference.value, *bound) && !same(reference.value, *bound))
      fail("the bound is beaten by brute force", *bound, reference.value);
  };
  if (order > 1) {
    try {
      RegionLimits tiny;
      tiny.first_pass_states = tiny.first_pass_nodes = tiny.large_region_states = region_budget;
      tiny.max_states_per_region_dp = tiny.max_nodes_per_region = 2 * region_budget;
      tiny.max_total_states = tiny.max_total_nodes = 8 * region_budget;
      tiny.max_states_per_region = 3, tiny.max_region_triangles = 6;
      const KOrderResult r = solve_k_order(t.structure(), o, order, {}, tiny);
      check(r.triangulation, r.value, r.optimal, r.bound);
    } catch (const LimitError&) {
    }
  }
  for (Method m : {Method::Auto, Method::Exact, Method::Approx}) {
    SolveOptions options;
    options.method = m;
    options.order = order;
    if (order > 1 && m == Method::Approx) continue;
    Solution s;
    try {
      s = solve(t.structure(), o, options);
    } catch (const LimitError&) {
      continue;  // refused at a limit, with a message: allowed
    }
    check(s.mesh ? *s.mesh : triangulate(t.structure(), s.choice), s.value, s.optimal, s.bound);
  }
  return 0;
}
