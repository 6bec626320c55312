// The options of a solve, checked in one place for every order and every front
// end (the CLI, the wasm bindings and through them the JS API).
#pragma once
#include <cstdint>

#include "hodt/solve.hpp"

namespace hodt {

// The orders k a solve accepts (k-th order Delaunay triangulations).
constexpr uint32_t kMinOrder = 1, kMaxOrder = 16;

// Throws InputError naming the value: an order outside kMinOrder..kMaxOrder, an
// epsilon that is not a number in (0, 1) (at every order, used or not), a method
// that is none of the four. Every method runs at every order (k_order.hpp: at
// order k, brute-force and exact enumerate or refuse, approx is the heuristic).
void check_options(const SolveOptions& options);

// An order given as a number (the CLI's text, a JS number): an integer in range,
// else InputError.
uint32_t order_from_number(double k);

}  // namespace hodt
