// The reference at order k: brute force, every k-OD triangulation of the
// instance enumerated.
#pragma once
#include <cstdint>

#include "hodt/k_order.hpp"
#include "hodt/solve_options.hpp"

namespace hodt::test {

inline KOrderResult k_order_brute_force(const FirstOrder& fo, Objective o, uint32_t k, uint64_t max_nodes = 300'000) {
  SolveOptions bf;
  bf.method = Method::BruteForce;
  return solve_k_order(fo, o, k, bf, max_nodes);
}

}  // namespace hodt::test
