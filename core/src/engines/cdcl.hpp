// A CDCL SAT solver in the style of MiniSat: two watched literals (binary
// clauses in their own implication lists, long clauses watched with a blocker
// literal), first-UIP conflict analysis with recursive clause minimization
// (on an explicit stack), VSIDS variable order, phase saving, Luby restarts and
// periodic reduction of learned clauses (by glue, the number of decision levels
// a clause spans, and activity).
//
// Why its answers are right: every learned clause is a resolvent of clauses it
// holds (the conflict clause resolved with reasons, minimization only drops
// literals whose negation the remaining ones imply by resolution), so it holds in
// every model of the clauses added. Unsatisfiable comes only from a conflict at
// decision level 0 (where every assignment is a consequence of the clauses,
// so resolving it out gives the empty clause) or from an added empty clause.
// Satisfiable comes only with every variable assigned and propagation at a
// fixed point without conflict: each long clause watches two literals of which
// neither is false unless the clause is satisfied or unit-propagated, each binary
// clause is propagated from either side, so a full conflict-free assignment
// satisfies every clause. Deleting learned clauses loses no answer (they are
// consequences) and keeps every clause that is the reason of an assignment.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <vector>

#include "hodt/progress.hpp"

namespace hodt {

enum class SatAnswer : uint8_t { Satisfiable, Unsatisfiable, Unknown };

class Cdcl {
 public:
  // Literal "variable v has value b" (the same as TwoSat::lit in
  // engines/two_sat.hpp); l ^ 1 negates.
  static uint32_t lit(uint32_t v, bool b) { return 2 * v + (b ? 1 : 0); }
  uint32_t add_var();  // a new variable, numbered from 0
  uint32_t num_vars() const { return static_cast<uint32_t>(level_.size()); }
  // Adds a clause (duplicate literals and tautologies allowed; the empty clause
  // makes the instance unsatisfiable for good; a literal of a variable not yet
  // added adds the variables up to it). Allowed between solve() calls
  // (incremental: clauses are only ever added, so learned clauses stay valid).
  void add_clause(const uint32_t* lits, size_t n);
  void add_clause(std::initializer_list<uint32_t> lits) { add_clause(lits.begin(), lits.size()); }
  void add_clause(const std::vector<uint32_t>& lits) { add_clause(lits.data(), lits.size()); }
  // The value a decision tries first for v (phase saving then takes over).
  // Default false.
  void prefer(uint32_t v, bool b);
  // Searches until an answer or until max_conflicts more conflicts (then
  // Unknown; a later call resumes, keeping the learned clauses; an answer found
  // before the first conflict comes even with a budget of 0). progress is
  // called with (conflicts so far in this call, max_conflicts); cancelling it
  // throws Cancelled (the solver stays usable). max_work: Unknown as well once
  // the call has visited this many watches and implications (a conflict's
  // cost grows with the instance: this bounds the time, where the conflicts
  // bound the search).
  SatAnswer solve(uint64_t max_conflicts, const Progress& progress = {}, uint64_t max_work = UINT64_MAX);
  // After Satisfiable: the model's value of v (false for a variable added since).
  bool value(uint32_t v) const { return v < model_.size() && model_[v] != 0; }
  uint64_t conflicts() const { return conflicts_; }  // total, over every call
  uint64_t work() const { return work_; }            // watches and implications visited, over every call
  size_t num_clauses() const { return num_original_; }  // original clauses of 2+ literals kept

 private:
  // A reason or conflict: a long clause (its offset in the arena), a binary
  // clause (kBinary | the other literal, false), or none. (kNone has the
  // kBinary bit too: every test of that bit comes after a test for kNone.
  // Offsets and literals stay below 2^31: an arena of 8 GiB.)
  static constexpr uint32_t kNone = UINT32_MAX;
  static constexpr uint32_t kBinary = 0x80000000u;
  // Long clause header in the arena: size, flags (learned, deleted, glue << 2),
  // activity (float bits); then the literals. The first two are watched; the
  // literal a clause implies is its first.
  static constexpr uint32_t kHeader = 3;
  struct Watch {
    uint32_t clause, blocker;  // blocker: a literal of the clause; true => clause satisfied
  };

  int8_t val(uint32_t l) const { return val_[l]; }  // 1 true, -1 false, 0 unassigned
  uint32_t level(uint32_t l) const { return level_[l >> 1]; }
  uint32_t decision_level() const { return static_cast<uint32_t>(trail_lim_.size()); }
  void assign(uint32_t l, uint32_t reason);
  uint32_t propagate();  // the conflict, or kNone
  void backtrack(uint32_t to_level);
  void analyze(uint32_t conflict, std::vector<uint32_t>& learned, uint32_t& back_level, uint32_t& glue);
  bool redundant(uint32_t l, uint32_t abstract_levels);
  uint32_t add_long(const std::vector<uint32_t>& lits, bool learned, uint32_t glue);
  void reduce();
  void bump_var(uint32_t v);
  void bump_clause(uint32_t c);
  void heap_insert(uint32_t v);
  void heap_up(uint32_t i);
  void heap_down(uint32_t i);
  uint32_t heap_pop();

  std::vector<uint32_t> arena_;
  std::vector<uint32_t> learned_;              // offsets of the learned long clauses
  std::vector<std::vector<Watch>> watches_;    // per literal: long clauses watching its negation
  std::vector<std::vector<uint32_t>> binary_;  // per literal p: literals p implies
  std::vector<int8_t> val_;                    // per literal
  std::vector<uint32_t> level_, reason_;       // per variable
  std::vector<uint8_t> phase_, seen_, model_;  // per variable
  std::vector<double> activity_;               // per variable
  std::vector<uint32_t> heap_;                 // VSIDS order: a binary max-heap of variables
  std::vector<int32_t> heap_pos_;              // per variable, -1 outside the heap
  std::vector<uint32_t> trail_, trail_lim_;
  uint32_t qhead_ = 0;
  uint32_t conflict_binary_[2] = {0, 0};  // the clause of a binary conflict (propagate returned kBinary)
  uint64_t work_ = 0;                     // watches and implications visited, to pace progress
  double var_inc_ = 1;
  float clause_inc_ = 1;
  std::vector<uint32_t> clause_buf_, learned_buf_, stack_, to_clear_;
  std::vector<uint64_t> level_stamp_;
  uint64_t stamp_ = 0;
  bool unsat_ = false;
  uint64_t conflicts_ = 0;
  uint64_t next_reduce_ = 2000, reduce_step_ = 2000;
  uint64_t restarts_ = 0;
  size_t num_original_ = 0;
};

}  // namespace hodt
