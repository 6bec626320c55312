#include "hodt/solve_options.hpp"

#include <cmath>
#include <string>

#include "hodt/error.hpp"
#include "hodt/format.hpp"

namespace hodt {

namespace {

std::string order_range() { return "an integer from " + std::to_string(kMinOrder) + " to " + std::to_string(kMaxOrder); }

}  // namespace

uint32_t order_from_number(double k) {
  if (!(k >= kMinOrder && k <= kMaxOrder && k == std::floor(k)))
    throw InputError("order is " + format_number(k) + ", expected " + order_range());
  return static_cast<uint32_t>(k);
}

void check_options(const SolveOptions& options) {
  if (options.order < kMinOrder || options.order > kMaxOrder)
    throw InputError("order is " + std::to_string(options.order) + ", expected " + order_range());
  // Checked at every order, used or not: a bad value is a mistake either way.
  if (!(options.epsilon > 0 && options.epsilon < 1))  // false for NaN; infinities are outside
    throw InputError("epsilon is " + format_number(options.epsilon) + ", expected a number in (0, 1)");
  if (static_cast<size_t>(options.method) > static_cast<size_t>(Method::Auto))
    throw InputError("method is " + std::to_string(static_cast<int>(options.method)) + ", expected " + method_ids());
}

}  // namespace hodt
