#include "hodt/solve.hpp"

#include <chrono>
#include <cmath>

#include "hodt/brute_force.hpp"
#include "hodt/error.hpp"
#include "hodt/format.hpp"

namespace hodt {

namespace {
constexpr const char* kMethodIds[] = {"brute-force", "exact", "approx", "auto"};
}

const char* method_id(Method m) { return kMethodIds[static_cast<size_t>(m)]; }

std::optional<Method> parse_method(std::string_view id) {
  for (size_t k = 0; k < 4; ++k)
    if (id == kMethodIds[k]) return static_cast<Method>(k);
  return std::nullopt;
}

std::string method_ids() { return "brute-force, exact, approx, auto"; }

Solution solve(const FirstOrder& fo, Objective objective, const SolveOptions& options) {
  if (!(options.epsilon > 0 && options.epsilon < 1))
    throw InputError("epsilon is " + format_number(options.epsilon) + ", expected a number in (0, 1)");
  switch (options.method) {
    case Method::BruteForce:
      return brute_force(fo, objective);
    case Method::Auto:
      if (fo.num_quads() <= 16) return brute_force(fo, objective);
      [[fallthrough]];
    case Method::Exact:
    case Method::Approx:
      break;
  }
  throw LimitError(std::string("method ") + method_id(options.method) + " is not implemented yet for " +
                   info(objective).id + " with " + std::to_string(fo.num_quads()) +
                   " quads; brute-force handles up to " + std::to_string(kBruteForceMaxQuads));
}

}  // namespace hodt
