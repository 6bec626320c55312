// The order-k engine: objectives as local terms, regions of order k, and the
// state graph DP, against exhaustive enumeration of every k-OD triangulation.
#include <doctest/doctest.h>

#include <cmath>

#include "generators.hpp"
#include "hodt/brute_force.hpp"
#include "hodt/delaunay.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/k_order.hpp"
#include "hodt/objective_terms.hpp"
#include "hodt/points.hpp"
#include "hodt/region_model.hpp"
#include "hodt/regions.hpp"
#include "hodt/solve.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

bool close(double a, double b) { return a == b || std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b)); }

}  // namespace

TEST_CASE("every objective's terms evaluate to the objective on any triangulation") {
  for (uint64_t seed = 1; seed <= 60; ++seed) {
    const FirstOrder fo = first_order(delaunay(validate_points(mixed_instance(seed, 1)).xyz));
    for (uint32_t k : {1u, 3u}) {
      int seen = 0;
      enumerate_k_order(fo.base, k, 100'000, [&](const std::vector<Tri>& tris) {
        if (++seen > 20) return;
        const Mesh m = mesh_of(fo.base.coords, tris);
        for (const auto& oi : objectives()) CHECK(evaluate_terms(oi.objective, m) == evaluate(oi.objective, m));
      });
    }
  }
}

TEST_CASE("regions of order 1 are the flippable quads") {
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    const FirstOrder fo = first_order(delaunay(validate_points(seed % 2 ? uniform_points(200, seed) : grid_points(8, 8, seed, true)).xyz));
    const Regions R = k_order_regions(fo.base, 1);
    uint32_t with_choice = 0;
    for (const Region& r : R.regions) {
      CHECK(r.complete);
      if (r.states.size() > 1) {
        ++with_choice;
        CHECK(r.states.size() == 2);
        CHECK(r.delaunay_triangles.size() == 2);
      } else {
        CHECK(r.delaunay_triangles.size() == 1);
      }
    }
    CHECK(with_choice == fo.num_quads());
  }
}

TEST_CASE("regions: the product of the regions' triangulations is every k-OD triangulation") {
  for (uint64_t seed = 1; seed <= 60; ++seed) {
    const FirstOrder fo = first_order(delaunay(validate_points(mixed_instance(seed, 1)).xyz));
    for (uint32_t k : {1u, 2u, 3u, 4u}) {
      uint64_t all = 0;
      REQUIRE(enumerate_k_order(fo.base, k, 10'000'000, [&](const std::vector<Tri>&) { ++all; }));
      const Regions R = k_order_regions(fo.base, k);
      uint64_t product = 1;
      for (const Region& r : R.regions) {
        CHECK(r.complete);
        product *= r.states.size();
      }
      CHECK(product == all);
    }
  }
}

TEST_CASE("exact at order k equals brute force for every objective (k = 2, 3, 4)") {
  for (uint32_t k : {2u, 3u, 4u}) {
    for (uint64_t seed = 1; seed <= 300; ++seed) {
      const FirstOrder fo = first_order(delaunay(validate_points(mixed_instance(seed * 7 + k, 1)).xyz));
      for (const auto& oi : objectives()) {
        SolveOptions bf;
        bf.method = Method::BruteForce;
        SolveOptions ex;
        ex.method = Method::Exact;
        const KOrderResult want = solve_k_order(fo, oi.objective, k, bf);
        const KOrderResult got = solve_k_order(fo, oi.objective, k, ex);
        CAPTURE(seed);
        CAPTURE(oi.id);
        CHECK(got.optimal);
        CHECK(close(got.value, want.value));
        CHECK(got.value == evaluate(oi.objective, got.triangulation));
        CHECK(is_k_order(got.triangulation, fo.base, k));
        CHECK(validate(got.triangulation) == "");
      }
    }
  }
}

TEST_CASE("order 1 through the general engine equals the specialised first order solvers") {
  for (uint64_t seed = 1; seed <= 60; ++seed) {
    const FirstOrder fo = first_order(delaunay(validate_points(seed % 2 ? uniform_points(60, seed) : dem_points(60, seed)).xyz));
    for (const auto& oi : objectives()) {
      SolveOptions ex;
      ex.method = Method::Exact;
      const KOrderResult general = solve_k_order(fo, oi.objective, 1, ex);
      const Solution special = solve(fo, oi.objective, ex);
      CAPTURE(seed);
      CAPTURE(oi.id);
      CHECK(general.optimal);
      CHECK(special.optimal);
      CHECK(close(general.value, special.value));
    }
  }
}

TEST_CASE("heuristic at order k: a valid k-OD triangulation and a bound on the right side") {
  const FirstOrder fo = first_order(delaunay(validate_points(dem_points(600, 3)).xyz));
  for (uint32_t k : {2u, 4u}) {
    for (const auto& oi : objectives()) {
      SolveOptions approx;
      approx.method = Method::Approx;
      const KOrderResult h = solve_k_order(fo, oi.objective, k, approx);
      SolveOptions ex;
      ex.method = Method::Auto;
      const KOrderResult e = solve_k_order(fo, oi.objective, k, ex);
      CAPTURE(oi.id);
      CHECK(is_k_order(h.triangulation, fo.base, k));
      if (e.optimal) {
        if (h.bound) CHECK(!better(oi.sense, e.value, *h.bound));  // the bound holds for the optimum
        CHECK(!better(oi.sense, h.value, e.value));
      }
    }
  }
}
