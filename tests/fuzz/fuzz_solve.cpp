// Solve against brute force: a small terrain, an objective, an order 1..3 and
// maybe a domain from the input. Every method that answers must give a finite
// value equal to its triangulation's, a k-OD triangulation, and never claim
// `optimal` (or a bound) that brute force contradicts.
#include <cmath>
#include <cstdio>

#include "fuzz_input.hpp"
#include "hodt/error.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/measures.hpp"
#include "hodt/solve.hpp"
#include "hodt/terrain.hpp"

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
  const uint32_t order = 1 + in.byte() % 3;
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
    const Mesh mesh = s.mesh ? *s.mesh : triangulate(t.structure(), s.choice);
    if (!std::isfinite(s.value)) fail("non-finite value", s.value, 0);
    if (!same(evaluate(o, mesh), s.value)) fail("value is not its triangulation's", evaluate(o, mesh), s.value);
    if (order > 1 && !is_k_order(mesh, t.structure().base, order)) fail("result is not k-OD", order, 0);
    if (better(sense, s.value, reference.value) && !same(s.value, reference.value))
      fail("better than brute force", s.value, reference.value);
    if (s.optimal && !same(s.value, reference.value)) fail("optimal but brute force is better", s.value, reference.value);
    if (!s.optimal && !s.bound) fail("neither optimal nor bounded", s.value, 0);
    if (s.bound && better(sense, reference.value, *s.bound) && !same(reference.value, *s.bound))
      fail("the bound is beaten by brute force", *s.bound, reference.value);
  }
  return 0;
}
