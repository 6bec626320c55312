// The options of a solve, checked in one place for every order and every front
// end (the CLI, the wasm bindings and through them the JS API).
#pragma once
#include <cstdint>

#include "hodt/solve.hpp"

namespace hodt {

// The orders k a solve accepts (k-th order Delaunay triangulations).
constexpr uint32_t kMinOrder = 1, kMaxOrder = 16;

// Every method at order 1; above it auto (enumeration when the instance is small
// enough, else a heuristic) and brute-force (enumeration or a refusal).
bool method_allowed(Method method, uint32_t order);

// Throws InputError naming the value: an order outside kMinOrder..kMaxOrder, a
// method the order does not have, an epsilon that is not a number in (0, 1).
void check_options(const SolveOptions& options);

// An order given as a number (the CLI's text, a JS number): an integer in range,
// else InputError.
uint32_t order_from_number(double k);

}  // namespace hodt
