// Cdcl against exhaustive enumeration: the same answer on random k-SAT at the
// threshold, alone and incrementally (also resumed after running out of
// budget), every model satisfying every clause; pigeonhole instances, long
// implication chains (no recursion), cancellation, degenerate clauses.
#include <doctest/doctest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "engines/cdcl.hpp"

using namespace hodt;

namespace {

using Clauses = std::vector<std::vector<uint32_t>>;
constexpr uint64_t kNoLimit = UINT64_MAX;

bool satisfies(const Clauses& clauses, const Cdcl& s) {
  for (const std::vector<uint32_t>& c : clauses) {
    bool sat = false;
    for (uint32_t l : c) sat = sat || s.value(l >> 1) == ((l & 1) != 0);
    if (!sat) return false;
  }
  return true;
}

// Some assignment of the n (<= 20) variables satisfies every clause.
bool brute_force(uint32_t n, const Clauses& clauses) {
  std::vector<std::pair<uint32_t, uint32_t>> masks;  // variables appearing true, false
  for (const std::vector<uint32_t>& c : clauses) {
    uint32_t pos = 0, neg = 0;
    for (uint32_t l : c) ((l & 1) ? pos : neg) |= 1u << (l >> 1);
    masks.push_back({pos, neg});
  }
  for (uint32_t bits = 0; bits < (1u << n); ++bits) {
    bool all = true;
    for (const auto& [pos, neg] : masks)
      if (!((bits & pos) | (~bits & neg))) {
        all = false;
        break;
      }
    if (all) return true;
  }
  return false;
}

std::vector<uint32_t> random_clause(std::mt19937& rng, uint32_t n, uint32_t k) {
  std::vector<uint32_t> c;
  for (uint32_t i = 0; i < k; ++i) c.push_back(Cdcl::lit(static_cast<uint32_t>(rng() % n), rng() & 1));
  return c;
}

// Clause lengths 2, 3, 4 or a mix, and a clause count near the satisfiability
// threshold of that mix.
uint32_t clause_length(std::mt19937& rng, uint32_t kind) { return kind < 3 ? kind + 2 : 2 + static_cast<uint32_t>(rng() % 3); }
double threshold(uint32_t kind) {
  constexpr double t[] = {1.0, 4.26, 9.93, 3.5};
  return t[kind];
}

// Pigeonhole: p pigeons in h holes, variable p_i in hole j = i * h + j.
Clauses pigeonhole(uint32_t pigeons, uint32_t holes) {
  Clauses cs;
  for (uint32_t i = 0; i < pigeons; ++i) {
    std::vector<uint32_t> c;
    for (uint32_t j = 0; j < holes; ++j) c.push_back(Cdcl::lit(i * holes + j, true));
    cs.push_back(c);
  }
  for (uint32_t j = 0; j < holes; ++j)
    for (uint32_t a = 0; a < pigeons; ++a)
      for (uint32_t b = a + 1; b < pigeons; ++b) cs.push_back({Cdcl::lit(a * holes + j, false), Cdcl::lit(b * holes + j, false)});
  return cs;
}

void add_all(Cdcl& s, const Clauses& cs) {
  for (const std::vector<uint32_t>& c : cs) s.add_clause(c);
}

}  // namespace

TEST_CASE("cdcl: random k-SAT at the threshold, the answer of exhaustive search") {
  std::mt19937 rng(20240611);
  size_t satisfiable = 0, unsatisfiable = 0;
  for (int instance = 0; instance < 3000; ++instance) {
    const uint32_t n = 1 + static_cast<uint32_t>(rng() % 14), kind = static_cast<uint32_t>(rng() % 4);
    const double ratio = threshold(kind) * (0.7 + 0.9 * std::uniform_real_distribution<double>(0, 1)(rng));
    const uint32_t m = static_cast<uint32_t>(ratio * n + 0.5);
    Clauses cs;
    for (uint32_t k = 0; k < m; ++k) cs.push_back(random_clause(rng, n, clause_length(rng, kind)));
    Cdcl s;
    for (uint32_t v = 0; v < n; ++v) CHECK(s.add_var() == v);
    if (rng() & 1)
      for (uint32_t v = 0; v < n; ++v) s.prefer(v, rng() & 1);
    add_all(s, cs);
    const bool expected = brute_force(n, cs);
    const SatAnswer a = s.solve(kNoLimit);
    REQUIRE(a != SatAnswer::Unknown);
    CHECK((a == SatAnswer::Satisfiable) == expected);
    if (a == SatAnswer::Satisfiable) CHECK(satisfies(cs, s));
    CHECK(s.solve(kNoLimit) == a);  // again, from the learned clauses
    (expected ? satisfiable : unsatisfiable)++;
  }
  MESSAGE(satisfiable << " satisfiable, " << unsatisfiable << " unsatisfiable");
  CHECK(satisfiable > 600);
  CHECK(unsatisfiable > 600);
}

TEST_CASE("cdcl: clauses added between solves, and solves resumed after running out of budget") {
  std::mt19937 rng(77);
  size_t unknown = 0, answers = 0;
  for (int instance = 0; instance < 600; ++instance) {
    const uint32_t n = 3 + static_cast<uint32_t>(rng() % 12), kind = static_cast<uint32_t>(rng() % 4);
    Clauses cs;
    Cdcl s;
    for (uint32_t v = 0; v < n; ++v) s.add_var();
    bool was_unsat = false;
    const uint32_t total = static_cast<uint32_t>(threshold(kind) * n * 1.6);
    while (cs.size() < total) {
      const uint32_t batch = 1 + static_cast<uint32_t>(rng() % (n + 2));
      for (uint32_t k = 0; k < batch; ++k) {
        cs.push_back(random_clause(rng, n, rng() % 8 == 0 ? 1 : clause_length(rng, kind)));  // some units
        s.add_clause(cs.back());
      }
      const bool expected = brute_force(n, cs);
      SatAnswer a = s.solve(rng() % 2 == 0 ? 1 : kNoLimit);
      if (a == SatAnswer::Unknown) ++unknown, a = s.solve(kNoLimit);
      REQUIRE(a != SatAnswer::Unknown);
      CHECK((a == SatAnswer::Satisfiable) == expected);
      if (a == SatAnswer::Satisfiable) CHECK(satisfies(cs, s));
      if (was_unsat) CHECK(a == SatAnswer::Unsatisfiable);
      was_unsat = a == SatAnswer::Unsatisfiable;
      ++answers;
    }
  }
  MESSAGE(answers << " answers, " << unknown << " resumed after Unknown");
  CHECK(unknown > 40);
}

TEST_CASE("cdcl: planted satisfiable 3-SAT with enough conflicts to reduce the learned clauses") {
  std::mt19937 rng(5);
  uint64_t most = 0;
  for (int instance = 0; instance < 6; ++instance) {
    const uint32_t n = 260;
    std::vector<bool> planted(n);
    for (uint32_t v = 0; v < n; ++v) planted[v] = rng() & 1;
    Clauses cs;
    while (cs.size() < static_cast<size_t>(4.3 * n)) {
      std::vector<uint32_t> c = random_clause(rng, n, 3);
      bool sat = false;
      for (uint32_t l : c) sat = sat || planted[l >> 1] == ((l & 1) != 0);
      if (sat) cs.push_back(c);
    }
    Cdcl s;
    add_all(s, cs);
    REQUIRE(s.solve(kNoLimit) == SatAnswer::Satisfiable);
    CHECK(satisfies(cs, s));
    most = std::max(most, s.conflicts());
  }
  MESSAGE("most conflicts " << most);
  CHECK(most > 2500);  // at least one reduction of the learned clauses ran
}

TEST_CASE("cdcl: pigeonhole") {
  for (uint32_t h = 4; h <= 7; ++h) {
    Cdcl s;
    add_all(s, pigeonhole(h + 1, h));
    CHECK(s.solve(kNoLimit) == SatAnswer::Unsatisfiable);
    CHECK(s.solve(kNoLimit) == SatAnswer::Unsatisfiable);
    const Clauses fits = pigeonhole(h, h);
    Cdcl t;
    add_all(t, fits);
    CHECK(t.num_clauses() == fits.size());
    REQUIRE(t.solve(kNoLimit) == SatAnswer::Satisfiable);
    CHECK(satisfies(fits, t));
  }
  Cdcl s;
  add_all(s, pigeonhole(8, 7));
  CHECK(s.solve(1) == SatAnswer::Unknown);
  CHECK(s.conflicts() == 1);
  CHECK(s.solve(1) == SatAnswer::Unknown);
  CHECK(s.conflicts() == 2);
  CHECK(s.solve(kNoLimit) == SatAnswer::Unsatisfiable);
  // The work budget: a few hundred watches visited, then Unknown, resumed to
  // the same answer.
  Cdcl w;
  add_all(w, pigeonhole(8, 7));
  const uint64_t before = w.work();
  CHECK(w.solve(kNoLimit, {}, 300) == SatAnswer::Unknown);
  CHECK(w.work() - before < 300 + 2000);  // (checked between propagations: a propagation may overrun it)
  CHECK(w.solve(kNoLimit) == SatAnswer::Unsatisfiable);
}

TEST_CASE("cdcl: a chain of 100000 implications") {
  constexpr uint32_t n = 100000;
  auto chain = [&](Cdcl& s) {
    for (uint32_t v = 0; v + 1 < n; ++v) s.add_clause({Cdcl::lit(v, false), Cdcl::lit(v + 1, true)});
  };
  {
    Cdcl s;
    chain(s);
    s.add_clause({Cdcl::lit(0, true)});
    CHECK(s.solve(kNoLimit) == SatAnswer::Satisfiable);
    for (uint32_t v = 0; v < n; ++v) REQUIRE(s.value(v));
    s.add_clause({Cdcl::lit(n - 1, false)});
    CHECK(s.solve(kNoLimit) == SatAnswer::Unsatisfiable);
  }
  {
    // The chain's ends forced only through conflicts: every chain variable
    // preferred true, x_0 then implies both y and not y at the end, and its
    // refutation reaches back through the whole chain at a decision level.
    Cdcl s;
    chain(s);
    const uint32_t y = s.add_var(), z = s.add_var();
    for (uint32_t v = 0; v < n; ++v) s.prefer(v, true);
    s.add_clause({Cdcl::lit(n - 1, false), Cdcl::lit(z, false), Cdcl::lit(y, true)});
    s.add_clause({Cdcl::lit(n - 1, false), Cdcl::lit(z, false), Cdcl::lit(y, false)});
    s.add_clause({Cdcl::lit(z, true), Cdcl::lit(0, false), Cdcl::lit(y, true)});
    s.add_clause({Cdcl::lit(z, true), Cdcl::lit(0, false), Cdcl::lit(y, false)});
    REQUIRE(s.solve(kNoLimit) == SatAnswer::Satisfiable);
    CHECK_FALSE(s.value(0));
    s.add_clause({Cdcl::lit(0, true)});
    CHECK(s.solve(kNoLimit) == SatAnswer::Unsatisfiable);
  }
}

TEST_CASE("cdcl: cancellation through progress") {
  Cdcl s;
  add_all(s, pigeonhole(10, 9));
  int calls = 0;
  bool in_range = true;
  const Progress stop_soon = [&](double done, double total) {
    in_range = in_range && done >= 0 && done <= total && total == 1e9;
    return ++calls < 5;
  };
  CHECK_THROWS_AS(s.solve(1000000000, stop_soon), Cancelled);
  CHECK(calls == 5);
  CHECK(in_range);
  CHECK(s.conflicts() > 0);
  // Still usable: a budget, then the answer of a smaller instance after a cancel.
  CHECK(s.solve(10) == SatAnswer::Unknown);
  Cdcl t;
  add_all(t, pigeonhole(7, 6));
  calls = 0;
  const Progress stop_later = [&](double, double) { return ++calls < 3; };
  try {
    t.solve(kNoLimit, stop_later);
  } catch (const Cancelled&) {
  }
  CHECK(t.solve(kNoLimit) == SatAnswer::Unsatisfiable);
}

TEST_CASE("cdcl: empty clause, duplicate literals, tautologies, no variables") {
  {
    Cdcl s;
    CHECK(s.num_vars() == 0);
    CHECK(s.solve(kNoLimit) == SatAnswer::Satisfiable);
    CHECK(s.solve(0) == SatAnswer::Satisfiable);
    s.add_clause(std::vector<uint32_t>{});
    CHECK(s.solve(kNoLimit) == SatAnswer::Unsatisfiable);
    s.add_clause({Cdcl::lit(s.add_var(), true)});
    CHECK(s.solve(kNoLimit) == SatAnswer::Unsatisfiable);
    s.add_clause({Cdcl::lit(5, true), Cdcl::lit(6, false)});  // (its variables exist, even now)
    CHECK(s.num_vars() == 7);
  }
  {
    Cdcl s;
    const uint32_t a = s.add_var(), b = s.add_var();
    s.add_clause({Cdcl::lit(a, true), Cdcl::lit(a, false)});  // tautology: no constraint
    s.add_clause({Cdcl::lit(b, true), Cdcl::lit(a, true), Cdcl::lit(b, false)});
    CHECK(s.num_clauses() == 0);
    s.add_clause({Cdcl::lit(a, false), Cdcl::lit(a, false), Cdcl::lit(a, false)});  // the unit not a
    CHECK(s.num_clauses() == 0);
    s.add_clause({Cdcl::lit(a, true), Cdcl::lit(b, true), Cdcl::lit(b, true)});    // b, given not a
    REQUIRE(s.solve(kNoLimit) == SatAnswer::Satisfiable);
    CHECK_FALSE(s.value(a));
    CHECK(s.value(b));
    s.add_clause({Cdcl::lit(b, false), Cdcl::lit(b, false)});
    CHECK(s.solve(kNoLimit) == SatAnswer::Unsatisfiable);
  }
  {
    // Literals of variables not yet added add them; a free variable gets its preferred value.
    Cdcl s;
    s.prefer(3, true);
    CHECK(s.num_vars() == 4);
    s.add_clause({Cdcl::lit(5, true), Cdcl::lit(4, true)});
    CHECK(s.num_vars() == 6);
    REQUIRE(s.solve(kNoLimit) == SatAnswer::Satisfiable);
    CHECK(s.value(3));
    CHECK((s.value(4) || s.value(5)));
  }
}
