// Optimising over k-th order Delaunay triangulations (k >= 1; paper Section 4.3).
//
// The paper's DP over augmented tree decompositions is impractical as written;
// what runs here:
//  - exact: every k-OD triangulation is enumerated (exact cover of the hull by
//    candidate triangles: k-OD, all edges useful, empty), and the best kept; used
//    when the enumeration fits its node budget, so `optimal` is then proven;
//  - otherwise: the first order optimum (a k-OD triangulation for every k >= 1)
//    improved by flips that keep every triangle k-OD and strictly improve the
//    objective (after the flip heuristic of de Kok, van Kreveld and Loeffler),
//    reported with optimal = false and a bound where one is known.
// options.method: brute-force and exact run the enumeration alone (a LimitError
// when it does not fit), approx the heuristic alone, auto both in turn.
// Every returned triangulation is verified k-OD.
#pragma once
#include <functional>

#include "hodt/first_order.hpp"
#include "hodt/objectives.hpp"
#include "hodt/skeleton.hpp"
#include "hodt/solution.hpp"
#include "hodt/solve.hpp"

namespace hodt {

struct KOrderResult {
  Mesh triangulation;
  double value = 0;
  double delaunay_value = 0;
  bool optimal = false;
  std::optional<double> bound;
  uint64_t enumerated = 0;  // triangulations enumerated (exact)
  std::string method;       // "exact" (enumeration) or "heuristic"
};

// Calls visit for every k-OD triangulation of the points of `delaunay` (as a list
// of triangles); returns false if it stopped because `max_nodes` was reached.
// progress (if given) is called every few thousand nodes; returning false cancels.
bool enumerate_k_order(const Mesh& delaunay, uint32_t k, uint64_t max_nodes,
                       const std::function<void(const std::vector<Tri>&)>& visit, const Progress& progress = {});

KOrderResult solve_k_order(const FirstOrder& fo, Objective o, uint32_t k, const SolveOptions& options,
                           uint64_t max_nodes = 300'000);

// The same as a Solution (for the CLI and the bindings).
Solution k_order_solution(const FirstOrder& fo, Objective o, uint32_t k, const SolveOptions& options);

// A mesh (canonical order) from a list of counterclockwise triangles.
Mesh mesh_of(const Coords& coords, const std::vector<Tri>& triangles);

}  // namespace hodt
