// The reference at order k: brute force, every k-OD triangulation of the
// instance enumerated; and the small instances the order-k tests run over.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "hodt/delaunay.hpp"
#include "hodt/first_order.hpp"
#include "hodt/measures.hpp"
#include "hodt/objectives.hpp"
#include "hodt/points.hpp"
#include "hodt/solve_options.hpp"
#include "generators.hpp"
#include "higher_order/k_order.hpp"
#include "mesh/mesh_of.hpp"
#include "higher_order/regions/region_engine.hpp"

namespace hodt::test {

inline KOrderResult k_order_brute_force(const FirstOrder& fo, Objective o, uint32_t k, uint64_t max_nodes = 300'000) {
  SolveOptions bf;
  bf.method = Method::BruteForce;
  return solve_k_order(fo, o, k, bf, max_nodes);
}

// The optimum of every objective over every k-OD triangulation of dt's points,
// each triangulation listed once and measured as dt's coordinates say (their
// domain too); nullopt when listing them takes more than max_nodes search nodes.
inline std::optional<std::array<double, kNumObjectives>> k_order_optima(const Mesh& dt, uint32_t k, uint64_t max_nodes) {
  std::array<double, kNumObjectives> best{};
  bool have = false;
  const bool complete = enumerate_k_order(dt, k, max_nodes, [&](const std::vector<Tri>& tris) {
    const Mesh m = mesh_of(dt.coords, tris);
    for (const auto& oi : objectives()) {
      double& b = best[static_cast<size_t>(oi.objective)];
      const double v = evaluate(oi.objective, m);
      if (!have || better(oi.sense, v, b)) b = v;
    }
    have = true;
  }, {});
  if (!complete || !have) return std::nullopt;
  return best;
}

// f(k, seed, fo, structure) for each order k and seed 1..seeds: the mixed
// instance (random, integer grid with equal heights, cocircular) of seed *
// salt + k, its first order structure and its order-k candidates.
template <class F>
void for_small_k_instances(std::initializer_list<uint32_t> orders, uint64_t seeds, uint64_t salt, const F& f) {
  for (const uint32_t k : orders)
    for (uint64_t seed = 1; seed <= seeds; ++seed) {
      const FirstOrder fo = first_order(delaunay(validate_points(mixed_instance(seed * salt + k, 1)).xyz));
      const KOrderStructure structure(fo.base, k, {});
      f(k, seed, fo, structure);
    }
}

// An instance for orders 5 to 8, where brute force still enumerates: 10 to 13
// points (uniform, DEM-like, an integer grid with equal heights, cocircular).
// (Below k + 4 points every triangulation is k-OD: larger ones restrict more.)
inline std::vector<double> high_order_instance(uint64_t seed) {
  Rng r(seed);
  switch (seed % 4) {
    case 0: return uniform_points(10 + r.below(4), seed);
    case 1: return dem_points(10 + r.below(4), seed);
    case 2: return grid_points(3 + r.below(2), 4, seed, true);
    default: return cocircular_points(8 + r.below(5), seed);
  }
}

// An instance of 12 to 16 points where a tiny region budget leaves the regions
// incomplete, as on large terrains, and brute force still enumerates at k <= 5:
// uniform, DEM-like, an integer grid with equal heights, a jittered grid rounded
// to quarters (quantised coordinates and heights), a cocircular ring with points
// around it.
inline std::vector<double> medium_instance(uint64_t seed) {
  Rng r(seed);
  switch (seed % 5) {
    case 0: return uniform_points(12 + r.below(5), seed);
    case 1: return dem_points(12 + r.below(5), seed);
    case 2: return grid_points(4, 3 + r.below(2), seed, true);
    case 3: {
      std::vector<double> p = jittered_grid(4, 3 + r.below(2), 0.3, seed);
      for (double& v : p) v = std::round(v * 4) / 4;
      return p;
    }
    default: {
      std::vector<double> p = cocircular_points(12, seed);
      for (int i = 0; i < 2 + r.below(3); ++i) p.insert(p.end(), {16 * r.uniform() - 8, 16 * r.uniform() - 8, r.uniform()});
      return p;
    }
  }
}

// The min-max objectives: those the searches over every fill (the branch and
// bound, the threshold SAT search) read the terms of.
inline constexpr Objective kMinmaxObjectives[] = {
    Objective::MinmaxEdgeAreaRatio,   Objective::MinmaxEdgeNormalAngle,   Objective::MinmaxEdgeEnclosingCircle,
    Objective::MinmaxVertexAreaRatio, Objective::MinmaxVertexNormalAngle, Objective::MinmaxTriangleArea,
    Objective::MinmaxDegree};

// The optimum of o over every k-OD triangulation of dt's points, by plain
// enumeration; NaN when listing them takes more than max_nodes search nodes.
inline double k_order_optimum(const Mesh& dt, uint32_t k, Objective o, uint64_t max_nodes = 5'000'000) {
  double best = INFINITY;
  const bool complete = enumerate_k_order(dt, k, max_nodes, [&](const std::vector<Tri>& tris) {
    best = std::min(best, evaluate(o, mesh_of(dt.coords, tris)));
  });
  return complete ? best : NAN;
}

// An instance of 10 to 15 points for the searches over every fill, ties
// included: integer-height grids, uniform, cocircular, near-collinear points.
inline std::vector<double> fill_search_instance(uint64_t seed) {
  switch (seed % 6) {
    case 0: return grid_points(seed % 4 ? 3 : 4, 4, seed, true);
    case 1: return uniform_points(10 + static_cast<int>(seed % 4), seed);
    case 2: return cocircular_points(10 + static_cast<int>(seed % 3), seed);
    case 3: return grid_points(3, 5, seed, true);
    case 4: return near_collinear_points(12, seed);
    default: return uniform_points(12, seed);
  }
}

// f(dt, k, structure, o, best, known) for the searches over every fill: 30
// instances of fill_search_instance at orders 2 to 5, each min-max objective
// with its enumerated optimum, from four values in hand: none at all (the best
// improves all along), the Delaunay value, just above the optimum (only the
// optimum is better) and the optimum itself (nothing is). Returns the calls.
template <class F>
int for_fill_search_cases(const F& f) {
  int calls = 0;
  for (uint64_t seed = 1; seed <= 30; ++seed) {
    const Mesh dt = delaunay(validate_points(fill_search_instance(seed)).xyz);
    for (uint32_t k = 2; k <= 5; ++k) {
      const KOrderStructure structure(dt, k, {});
      for (Objective o : kMinmaxObjectives) {
        const std::string id = info(o).id;
        CAPTURE(seed);
        CAPTURE(k);
        CAPTURE(id);
        const double best = k_order_optimum(dt, k, o);
        REQUIRE(!std::isnan(best));
        for (const double known : {double{INFINITY}, evaluate(o, dt), std::nextafter(best, double{INFINITY}), best}) {
          CAPTURE(known);
          f(dt, k, structure, o, best, known);
          ++calls;
        }
      }
    }
  }
  return calls;
}

}  // namespace hodt::test
