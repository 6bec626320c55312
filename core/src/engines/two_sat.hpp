// 2-SAT in linear time (Aspvall, Plass, Tarjan): implication graph, strongly
// connected components (iterative Tarjan), assignment from their topological order.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "hodt/progress.hpp"

namespace hodt {

class TwoSat {
 public:
  explicit TwoSat(uint32_t num_vars) : n_(num_vars) {}
  // Literal "variable v has value b".
  static uint32_t lit(uint32_t v, bool b) { return 2 * v + (b ? 1 : 0); }
  // Adds the clause (l1 or l2); l1 == l2 forces l1.
  void add_clause(uint32_t l1, uint32_t l2) { clauses_.push_back({l1, l2}); }
  // Forbids the combination (v = a and w = b), or (v = a) alone when w < 0.
  void forbid(uint32_t v, bool a, int64_t w = -1, bool b = false) {
    if (w < 0) add_clause(lit(v, !a), lit(v, !a));
    else add_clause(lit(v, !a), lit(static_cast<uint32_t>(w), !b));
  }
  size_t num_clauses() const { return clauses_.size(); }
  // A satisfying assignment (one byte per variable), or nothing. progress is
  // called with (done, total) as given, to pace a long search.
  // components (optional): per literal its strongly connected component (Tarjan's
  // numbering, a reverse topological order), -1 for literals in no clause.
  std::optional<std::vector<uint8_t>> solve(const Progress& progress = {}, double done = 0, double total = 1,
                                            std::vector<int32_t>* components = nullptr) const;
  struct Clause { uint32_t a, b; };
  const std::vector<Clause>& clauses() const { return clauses_; }

 private:
  uint32_t n_;
  std::vector<Clause> clauses_;
};

}  // namespace hodt
