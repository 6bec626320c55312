// Every exact solver against exhaustive enumeration of all 2^m triangulations.
#include <doctest/doctest.h>

#include <cmath>

#include "hodt/brute_force.hpp"
#include "hodt/delaunay.hpp"
#include "hodt/points.hpp"
#include "hodt/solve.hpp"
#include "exact/exact.hpp"
#include "exact/extrema.hpp"
#include "generators.hpp"
#include "exact/factor_models.hpp"
#include "objectives/pair_measures.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

// Small instances of several kinds, with at most max_quads quads.
struct Instances {
  uint32_t max_quads;
  uint64_t seed = 0;
  FirstOrder next() {
    for (;;) {
      ++seed;
      Rng r(seed);
      const int kind = static_cast<int>(seed % 5);
      const int n = 6 + r.below(11);
      std::vector<double> p;
      if (kind == 0) p = uniform_points(n, seed);
      else if (kind == 1) p = dem_points(n, seed);
      else if (kind == 2) p = jittered_grid(3 + r.below(2), 3 + r.below(2), 0.3, seed);
      else if (kind == 3) p = grid_points(3 + r.below(2), 3, seed, true);  // ties in heights, cocircular
      else {  // integer coordinates and heights: collinear and coplanar cases
        for (int i = 0; i < n; ++i) p.insert(p.end(), {double(r.below(6)), double(r.below(6)), double(r.below(3))});
      }
      try {
        FirstOrder fo = first_order(delaunay(validate_points(p, Dedupe::KeepFirst).xyz));
        if (fo.num_quads() <= max_quads) return fo;
      } catch (const std::exception&) {  // collinear draws
      }
    }
  }
};

double optimum(const std::vector<std::array<double, kNumObjectives>>& all, Objective o) {
  const size_t k = static_cast<size_t>(o);
  double best = all[0][k];
  for (const auto& v : all) best = info(o).sense == Sense::Min ? std::min(best, v[k]) : std::max(best, v[k]);
  return best;
}

}  // namespace

TEST_CASE("exact polynomial algorithms equal brute force on 1000 instances per objective") {
  Instances gen{10};
  int mismatches = 0;
  for (int i = 0; i < 1000; ++i) {
    const FirstOrder fo = gen.next();
    const auto all = enumerate_all(fo);
    for (const auto& oi : objectives()) {
      if (!has_polynomial_exact(oi.objective)) continue;
      const Solution s = solve_polynomial(fo, oi.objective, {});
      const double best = optimum(all, oi.objective);
      const bool ok = oi.objective == Objective::MinTotalEdgeLength ? std::abs(s.value - best) <= 1e-12 * best : s.value == best;
      if (!ok && ++mismatches < 10)
        MESSAGE("instance seed " << gen.seed << " " << oi.id << ": exact " << s.value << " brute force " << best);
      CHECK(ok);
      CHECK(s.optimal);
    }
  }
  CHECK(mismatches == 0);
}

TEST_CASE("the factor graph engine equals brute force for every objective") {
  Instances gen{9};
  for (int i = 0; i < 400; ++i) {
    const FirstOrder fo = gen.next();
    const auto all = enumerate_all(fo);
    for (const auto& oi : objectives()) {
      const FactorGraph g = factor_model(fo, oi.objective);
      // The model evaluates every choice as the triangulation does.
      for (size_t c = 0; c < all.size(); c += 1 + all.size() / 7) {
        Choice x(fo.num_quads());
        for (uint32_t q = 0; q < fo.num_quads(); ++q) x[q] = (c >> q) & 1;
        CHECK(g.evaluate(x) == doctest::Approx(all[c][static_cast<size_t>(oi.objective)]).epsilon(1e-12));
      }
      const DpResult r = solve_exact(g);
      const double value = evaluate(oi.objective, triangulate(fo, r.choice));
      CHECK(value == doctest::Approx(optimum(all, oi.objective)).epsilon(1e-12));
    }
  }
}

TEST_CASE("min-max results report the critical pair and the search trace") {
  Instances gen{10};
  for (int i = 0; i < 50; ++i) {
    const FirstOrder fo = gen.next();
    for (Objective o : {Objective::MinmaxEdgeAreaRatio, Objective::MinmaxVertexNormalAngle}) {
      const Solution s = solve_polynomial(fo, o, ExactOptions{true});
      REQUIRE(s.critical);
      CHECK(s.critical->value == s.value);
      for (const ThresholdStep& t : s.trace) CHECK((t.satisfiable == (t.threshold >= s.value)));
    }
  }
}

TEST_CASE("exact is deterministic and handles large random inputs") {
  const FirstOrder fo = first_order(delaunay(uniform_points(5000, 77)));
  for (const auto& oi : objectives()) {
    SolveOptions opt;
    opt.method = Method::Exact;
    const Solution a = solve(fo, oi.objective, opt), b = solve(fo, oi.objective, opt);
    CHECK(a.choice == b.choice);
    CHECK(a.optimal);
    const double delaunay = evaluate(oi.objective, fo.base);
    CHECK_FALSE(better(info(oi.objective).sense, delaunay, a.value));
  }
}

TEST_CASE("exact NP-hard objectives (factor graph DP, degree threshold search) equal brute force on 1000 instances") {
  Instances gen{10};
  for (int i = 0; i < 1000; ++i) {
    const FirstOrder fo = gen.next();
    const auto all = enumerate_all(fo);
    for (Objective o : {Objective::MaxConvexEdges, Objective::MinMixedVertices, Objective::MinmaxDegree}) {
      SolveOptions opt;
      opt.method = Method::Exact;
      const Solution s = solve(fo, o, opt);
      CHECK(s.optimal);
      CHECK(s.value == optimum(all, o));
    }
  }
}
