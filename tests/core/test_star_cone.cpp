// Reduced stars (star_cone.hpp, ObjectiveTerms::drop_neighbors): a star's
// neighbours reduced one at a time, given the neighbours every completion has,
// give the same convex / mixed term as the whole star, for every completion.
// Random and integer (degenerate: coplanar, equal heights) stars.
#include <doctest/doctest.h>

#include <algorithm>

#include "generators.hpp"
#include "objectives/objective_terms.hpp"
#include "objectives/star_cone.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

// v = vertex 0; up to n neighbours on distinct rays from v; the first three
// surround v (every completion has them: stars are interior).
Mesh random_star(Rng& r, bool integer) {
  std::vector<double> c;
  auto add = [&](double x, double y, double z) { c.insert(c.end(), {x, y, z}); };
  add(0, 0, integer ? r.below(3) - 1 : r.uniform() - 0.5);
  const int n = 6 + r.below(7);
  for (int i = 0; i < 40 && static_cast<int>(c.size() / 3) < n + 1; ++i) {
    const size_t have = c.size() / 3 - 1;
    double x, y, z;
    if (have < 3) {  // around v
      const double a = 2.1 * static_cast<double>(have) + r.uniform() * 0.3;
      x = std::round(4 * std::cos(a)), y = std::round(4 * std::sin(a));
    } else if (integer) {
      x = r.below(9) - 4, y = r.below(9) - 4;
    } else {
      x = 2 * r.uniform() - 1, y = 2 * r.uniform() - 1;
    }
    z = integer ? r.below(5) - 2 : r.uniform() - 0.5;
    bool ok = x != 0 || y != 0;
    for (size_t j = 1; j < c.size() / 3 && ok; ++j) {  // (one neighbour per ray)
      const double px = c[3 * j], py = c[3 * j + 1];
      ok = !(px * y - py * x == 0 && px * x + py * y > 0);
    }
    if (ok) add(x, y, z);
  }
  Mesh m;
  m.coords = std::move(c);
  return m;
}

double term(const ObjectiveTerms& d, const Mesh& m, std::vector<uint32_t> nb) {
  std::sort(nb.begin(), nb.end());
  nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
  return d.vertex(m, Star(0, nb, {}));
}

}  // namespace

TEST_CASE("star cone: a reduced star has the whole star's class in every completion") {
  uint64_t reduced = 0, kept = 0;
  for (uint64_t seed = 1; seed <= 3000; ++seed) {
    Rng r(seed);
    const bool integer = seed % 2 == 0;
    const Mesh m = random_star(r, integer);
    const uint32_t n = m.num_vertices() - 1;
    if (n < 4) continue;
    std::vector<uint32_t> fixed, part, rest;
    for (uint32_t w = 1; w <= n; ++w) {
      const int pick = r.below(4);
      (pick == 0 ? fixed : pick == 1 ? rest : part).push_back(w);
    }
    for (const Objective o : {Objective::MaxConvexVertices, Objective::MinMixedVertices}) {
      const ObjectiveTerms& d = objective_terms(o, m);
      REQUIRE(static_cast<bool>(d.drop_neighbors));
      std::vector<uint32_t> order = part, nb;
      for (size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[static_cast<size_t>(r.below(static_cast<int>(i)))]);
      for (uint32_t w : order) {  // one at a time, as a fill grows
        nb.insert(std::lower_bound(nb.begin(), nb.end(), w), w);
        d.drop_neighbors(m, 0, fixed, nb);
      }
      reduced += part.size(), kept += std::count_if(nb.begin(), nb.end(), [](uint32_t w) { return w < kNoPlaneAbove; });
      for (int trial = 0; trial < 8; ++trial) {
        std::vector<uint32_t> completion = fixed;
        for (uint32_t w : {1u, 2u, 3u}) completion.push_back(w);
        for (uint32_t w : rest)
          if (r.below(2)) completion.push_back(w);
        std::vector<uint32_t> whole = completion, small = completion;
        whole.insert(whole.end(), part.begin(), part.end());
        // The reduced list keeps its marks last (they are the largest ids).
        small.insert(small.end(), nb.begin(), nb.end());
        CAPTURE(seed);
        CAPTURE(trial);
        CHECK(term(d, m, whole) == term(d, m, small));
      }
    }
  }
  MESSAGE("kept " << kept << " of " << reduced << " neighbours");
  CHECK(kept < reduced);  // (the reduction does something)
}
