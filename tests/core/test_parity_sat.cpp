// ParitySat against every assignment: satisfiable exactly when some assignment
// meets all constraints, and then its answer meets them.
#include <doctest/doctest.h>

#include "engines/parity_sat.hpp"
#include "generators.hpp"

using namespace hodt;
using namespace hodt::test;

TEST_CASE("parity sat: the answer of exhaustive search, and a solution when there is one") {
  size_t satisfiable = 0, systems = 0;
  for (uint64_t seed = 1; seed <= 3000; ++seed) {
    Rng r(seed);
    const uint32_t n = 1 + static_cast<uint32_t>(r.below(9)), m = static_cast<uint32_t>(r.below(2 * static_cast<int>(n) + 2));
    struct Constraint {
      uint32_t v, w;  // w == n: x_v = value
      bool c;
    };
    std::vector<Constraint> cs;
    ParitySat p(n);
    for (uint32_t k = 0; k < m; ++k) {
      const uint32_t v = static_cast<uint32_t>(r.below(static_cast<int>(n)));
      const uint32_t w = r.below(4) == 0 ? n : static_cast<uint32_t>(r.below(static_cast<int>(n)));
      const bool c = r.below(2);
      cs.push_back({v, w, c});
      if (w == n) p.fix(v, c);
      else p.relate(v, w, c);
    }
    auto meets = [&](auto value) {
      for (const Constraint& k : cs)
        if ((k.w == n ? value(k.v) != k.c : (value(k.v) != value(k.w)) != k.c)) return false;
      return true;
    };
    bool any = false;
    for (uint32_t bits = 0; bits < (1u << n) && !any; ++bits) any = meets([&](uint32_t v) { return ((bits >> v) & 1) != 0; });
    const std::optional<std::vector<uint8_t>> x = p.solve();
    CHECK(x.has_value() == any);
    if (x) CHECK(meets([&](uint32_t v) { return (*x)[v] != 0; }));
    ++systems, satisfiable += any;
  }
  MESSAGE(systems << " systems, " << satisfiable << " satisfiable");
  CHECK(satisfiable > 300);
  CHECK(systems - satisfiable > 300);
}
