#include "engines/term_budget.hpp"

#include <algorithm>
#include <cmath>

#include "hodt/error.hpp"

namespace hodt {

namespace {

std::string power_of_two(double x) {
  char buf[32];
  const double e = std::log2(std::max(x, 1.0));
  std::snprintf(buf, sizeof buf, e == std::floor(e) ? "2^%.0f" : "2^%.1f", e);
  return buf;
}

double work_of(const TermSize& t) { return std::ldexp(1.0, static_cast<int>(std::min(t.scope, 1000u))) * t.work_per_entry; }

}  // namespace

std::vector<uint8_t> plan_terms(const std::vector<TermSize>& terms, const DpLimits& limits, OverBudget over,
                                const std::function<std::string(size_t)>& name) {
  std::vector<uint8_t> keep(terms.size(), 1);
  for (size_t k = 0; k < terms.size(); ++k) {
    const TermSize& t = terms[k];
    const bool too_many = t.scope > limits.max_term_scope;
    if (!too_many && work_of(t) <= limits.max_term_work) continue;
    if (over == OverBudget::Relax) {
      keep[k] = 0;
      continue;
    }
    if (too_many)
      throw LimitError("exact: " + name(k) + ": its term would need 2^" + std::to_string(t.scope) +
                       " entries; the exact limit is 2^" + std::to_string(limits.max_term_scope) +
                       " (use --method approx)");
    throw LimitError("exact: " + name(k) + ": its term would take about " + power_of_two(work_of(t)) +
                     " steps to tabulate (2^" + std::to_string(t.scope) + " entries); the exact limit is " +
                     power_of_two(limits.max_term_work) + " (use --method approx)");
  }
  return keep;
}

}  // namespace hodt
