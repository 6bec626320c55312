#include "engines/cdcl.hpp"

#include <algorithm>
#include <cstring>

namespace hodt {

namespace {
// A clause's activity is a float kept in its header word (std::bit_cast is not
// in every standard library this builds with).
uint32_t bits_of(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}
float float_of(uint32_t u) {
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

// The i-th term (from 0) of the Luby sequence 1 1 2 1 1 2 4 1 1 2 1 1 2 4 8 ...:
// restart intervals whose mix of short and long runs is within a constant factor
// of the best fixed schedule for an unknown run-time distribution.
uint64_t luby(uint64_t i) {
  uint64_t size = 1, seq = 0;
  while (size < i + 1) ++seq, size = 2 * size + 1;
  while (size - 1 != i) size = (size - 1) >> 1, --seq, i %= size;
  return uint64_t{1} << seq;
}

constexpr uint32_t kLearned = 1, kDeleted = 2;
constexpr uint64_t kRestartUnit = 100;  // conflicts per unit of the Luby sequence
constexpr double kVarDecay = 0.95, kClauseDecay = 0.999;

}  // namespace

uint32_t Cdcl::add_var() {
  const uint32_t v = num_vars();
  level_.push_back(0);
  reason_.push_back(kNone);
  phase_.push_back(0);
  seen_.push_back(0);
  activity_.push_back(0);
  heap_pos_.push_back(-1);
  for (int side = 0; side < 2; ++side) val_.push_back(0), watches_.emplace_back(), binary_.emplace_back();
  heap_insert(v);
  return v;
}

void Cdcl::prefer(uint32_t v, bool b) {
  while (v >= num_vars()) add_var();
  phase_[v] = b;
}

void Cdcl::assign(uint32_t l, uint32_t reason) {
  val_[l] = 1;
  val_[l ^ 1] = -1;
  level_[l >> 1] = decision_level();
  reason_[l >> 1] = reason;
  trail_.push_back(l);
}

// Clauses are added at level 0 with its propagation complete, so a literal is
// either assigned there (a consequence of the clauses: true satisfies the clause
// for good, false can never help it) or unassigned. What is left then has two
// unassigned literals to watch, or is a unit to assign, or empty.
void Cdcl::add_clause(const uint32_t* lits, size_t n) {
  backtrack(0);
  for (size_t i = 0; i < n; ++i)
    while ((lits[i] >> 1) >= num_vars()) add_var();
  if (unsat_) return;
  if (propagate() != kNone) {
    unsat_ = true;
    return;
  }
  clause_buf_.assign(lits, lits + n);
  std::sort(clause_buf_.begin(), clause_buf_.end());
  clause_buf_.erase(std::unique(clause_buf_.begin(), clause_buf_.end()), clause_buf_.end());
  size_t k = 0;
  for (size_t i = 0; i < clause_buf_.size(); ++i) {
    const uint32_t l = clause_buf_[i];
    if (i + 1 < clause_buf_.size() && clause_buf_[i + 1] == (l ^ 1)) return;  // tautology (l and its negation sort together)
    if (val(l) > 0) return;
    if (val(l) == 0) clause_buf_[k++] = l;
  }
  clause_buf_.resize(k);
  if (k == 0) {
    unsat_ = true;
  } else if (k == 1) {
    assign(clause_buf_[0], kNone);
    if (propagate() != kNone) unsat_ = true;
  } else {
    ++num_original_;
    if (k == 2) binary_[clause_buf_[0] ^ 1].push_back(clause_buf_[1]), binary_[clause_buf_[1] ^ 1].push_back(clause_buf_[0]);
    else add_long(clause_buf_, false, 0);
  }
}

uint32_t Cdcl::add_long(const std::vector<uint32_t>& lits, bool learned, uint32_t glue) {
  const uint32_t c = static_cast<uint32_t>(arena_.size());
  arena_.push_back(static_cast<uint32_t>(lits.size()));
  arena_.push_back((learned ? kLearned : 0) | glue << 2);
  arena_.push_back(bits_of(0.0f));
  arena_.insert(arena_.end(), lits.begin(), lits.end());
  watches_[lits[0] ^ 1].push_back({c, lits[1]});
  watches_[lits[1] ^ 1].push_back({c, lits[0]});
  if (learned) learned_.push_back(c);
  return c;
}

// Unit propagation of the trail from qhead_. A true literal p implies what its
// binary clauses name, and visits the long clauses watching p's negation: a
// clause whose blocker or other watch is true stays; else it moves the watch to
// a non-false literal, or (none left) implies its other watch, or conflicts.
// Each long clause keeps its implied literal first (its false watch second).
uint32_t Cdcl::propagate() {
  while (qhead_ < trail_.size()) {
    const uint32_t p = trail_[qhead_++], false_lit = p ^ 1;
    const std::vector<uint32_t>& implied = binary_[p];
    work_ += implied.size();
    for (uint32_t q : implied) {
      const int8_t v = val(q);
      if (v > 0) continue;
      if (v == 0) {
        assign(q, kBinary | false_lit);
      } else {
        conflict_binary_[0] = q, conflict_binary_[1] = false_lit;
        qhead_ = static_cast<uint32_t>(trail_.size());
        return kBinary;
      }
    }
    std::vector<Watch>& ws = watches_[p];
    work_ += ws.size();
    uint32_t conflict = kNone;
    size_t i = 0, j = 0;
    const size_t n = ws.size();
    while (i < n) {
      const Watch w = ws[i++];
      if (val(w.blocker) > 0) {
        ws[j++] = w;
        continue;
      }
      uint32_t* c = &arena_[w.clause + kHeader];
      const uint32_t size = arena_[w.clause];
      if (c[0] == false_lit) std::swap(c[0], c[1]);
      const uint32_t first = c[0];
      if (first != w.blocker && val(first) > 0) {
        ws[j++] = {w.clause, first};
        continue;
      }
      bool moved = false;
      for (uint32_t k = 2; k < size; ++k) {
        if (val(c[k]) >= 0) {
          c[1] = c[k];
          c[k] = false_lit;
          watches_[c[1] ^ 1].push_back({w.clause, first});  // another list: c[1] is not false, so not false_lit
          moved = true;
          break;
        }
      }
      if (moved) continue;
      ws[j++] = {w.clause, first};
      if (val(first) < 0) {
        conflict = w.clause;
        qhead_ = static_cast<uint32_t>(trail_.size());
        while (i < n) ws[j++] = ws[i++];
      } else {
        assign(first, w.clause);
      }
    }
    ws.resize(j);
    if (conflict != kNone) return conflict;
  }
  return kNone;
}

void Cdcl::backtrack(uint32_t to_level) {
  if (decision_level() <= to_level) return;
  const uint32_t keep = trail_lim_[to_level];
  for (size_t k = trail_.size(); k-- > keep;) {
    const uint32_t l = trail_[k], v = l >> 1;
    val_[l] = val_[l ^ 1] = 0;
    reason_[v] = kNone;
    phase_[v] = l & 1;  // phase saving
    heap_insert(v);
  }
  trail_.resize(keep);
  trail_lim_.resize(to_level);
  qhead_ = keep;
}

// First-UIP learning: resolve the conflict clause with the reasons of its
// current-level literals, latest first along the trail, until one current-level
// literal is left (the unique implication point); its negation is asserted by
// the learned clause after backtracking to the highest other level in it.
// Level-0 literals are left out (they are false in every model).
void Cdcl::analyze(uint32_t conflict, std::vector<uint32_t>& out, uint32_t& back_level, uint32_t& glue) {
  out.assign(1, 0);  // the UIP's place
  uint32_t path = 0, p = kNone, reason = conflict;
  size_t index = trail_.size();
  auto visit = [&](uint32_t q) {
    const uint32_t v = q >> 1;
    if (seen_[v] || level_[v] == 0) return;
    bump_var(v);
    seen_[v] = 1;
    if (level_[v] >= decision_level()) ++path;
    else out.push_back(q);
  };
  for (;;) {
    if (p == kNone && reason == kBinary) {
      visit(conflict_binary_[0]), visit(conflict_binary_[1]);
    } else if (reason & kBinary) {
      visit(reason & ~kBinary);
    } else {
      if (arena_[reason + 1] & kLearned) bump_clause(reason);
      const uint32_t* c = &arena_[reason + kHeader];
      for (uint32_t k = p == kNone ? 0 : 1; k < arena_[reason]; ++k) visit(c[k]);  // c[0] is p
    }
    do p = trail_[--index];
    while (!seen_[p >> 1]);
    seen_[p >> 1] = 0;
    if (--path == 0) break;
    reason = reason_[p >> 1];  // p is implied: the level's decision is its last literal reached
  }
  out[0] = p ^ 1;

  // Minimization: drop a literal whose negation the others imply (each literal of
  // its reason is in the clause, at level 0, or recursively so). abstract: the
  // clause's levels as a 32-bit signature, a quick test that a reason literal at
  // a level the clause lacks cannot be dropped.
  uint32_t abstract = 0;
  for (size_t k = 1; k < out.size(); ++k) abstract |= 1u << (level(out[k]) & 31);
  to_clear_.assign(out.begin(), out.end());
  size_t kept = 1;
  for (size_t k = 1; k < out.size(); ++k)
    if (reason_[out[k] >> 1] == kNone || !redundant(out[k], abstract)) out[kept++] = out[k];
  out.resize(kept);
  for (uint32_t l : to_clear_) seen_[l >> 1] = 0;

  back_level = 0;
  if (out.size() > 1) {
    size_t best = 1;
    for (size_t k = 2; k < out.size(); ++k)
      if (level(out[k]) > level(out[best])) best = k;
    std::swap(out[1], out[best]);
    back_level = level(out[1]);
  }
  ++stamp_;
  glue = 0;
  for (uint32_t l : out)
    if (level_stamp_[level(l)] != stamp_) level_stamp_[level(l)] = stamp_, ++glue;
}

// Whether the clause's literals imply l's negation (l false, with a reason):
// depth-first through the reasons on an explicit stack. Literals shown implied
// stay seen (so later tests reuse them); on failure the ones this test marked
// are unmarked.
bool Cdcl::redundant(uint32_t l, uint32_t abstract) {
  stack_.assign(1, l);
  const size_t top = to_clear_.size();
  while (!stack_.empty()) {
    const uint32_t q = stack_.back();
    stack_.pop_back();
    const uint32_t r = reason_[q >> 1];
    const uint32_t* c;
    uint32_t from, to, other;
    if (r & kBinary) other = r & ~kBinary, c = &other, from = 0, to = 1;
    else c = &arena_[r + kHeader], from = 1, to = arena_[r];
    for (uint32_t k = from; k < to; ++k) {
      const uint32_t a = c[k], v = a >> 1;
      if (seen_[v] || level_[v] == 0) continue;
      if (reason_[v] != kNone && ((abstract >> (level_[v] & 31)) & 1)) {
        seen_[v] = 1;
        stack_.push_back(a);
        to_clear_.push_back(a);
        continue;
      }
      for (size_t i = top; i < to_clear_.size(); ++i) seen_[to_clear_[i] >> 1] = 0;
      to_clear_.resize(top);
      return false;
    }
  }
  return true;
}

// Keeps every learned clause of glue <= 2 and every clause that is a reason of
// an assignment (its implied literal, first, is true with it as reason); of the
// others, deletes the worse half (higher glue, then lower activity). Then the
// arena is compacted, reasons follow their clauses, and the watch lists are
// rebuilt on the same first two literals (so the watch invariant still holds).
void Cdcl::reduce() {
  std::vector<uint32_t> candidates;
  for (uint32_t c : learned_) {
    const uint32_t first = arena_[c + kHeader];
    const bool locked = reason_[first >> 1] == c && val(first) > 0;
    if ((arena_[c + 1] >> 2) > 2 && !locked) candidates.push_back(c);
  }
  std::sort(candidates.begin(), candidates.end(), [&](uint32_t a, uint32_t b) {
    const uint32_t ga = arena_[a + 1] >> 2, gb = arena_[b + 1] >> 2;
    if (ga != gb) return ga > gb;
    return float_of(arena_[a + 2]) < float_of(arena_[b + 2]);
  });
  for (size_t k = 0; k < candidates.size() / 2; ++k) arena_[candidates[k] + 1] |= kDeleted;

  std::vector<uint32_t> fresh;
  fresh.reserve(arena_.size());
  learned_.clear();
  for (uint32_t c = 0; c < arena_.size(); c += kHeader + arena_[c]) {
    if (arena_[c + 1] & kDeleted) continue;
    const uint32_t moved = static_cast<uint32_t>(fresh.size());
    fresh.insert(fresh.end(), arena_.begin() + c, arena_.begin() + c + kHeader + arena_[c]);
    if (arena_[c + 1] & kLearned) learned_.push_back(moved);
    arena_[c + 2] = moved;  // the old copy's activity word now forwards
  }
  for (uint32_t l : trail_) {
    uint32_t& r = reason_[l >> 1];
    if (r != kNone && !(r & kBinary)) r = arena_[r + 2];
  }
  arena_.swap(fresh);
  for (std::vector<Watch>& ws : watches_) ws.clear();
  for (uint32_t c = 0; c < arena_.size(); c += kHeader + arena_[c]) {
    const uint32_t* lits = &arena_[c + kHeader];
    watches_[lits[0] ^ 1].push_back({c, lits[1]});
    watches_[lits[1] ^ 1].push_back({c, lits[0]});
  }
}

void Cdcl::bump_var(uint32_t v) {
  if ((activity_[v] += var_inc_) > 1e100) {
    for (double& a : activity_) a *= 1e-100;
    var_inc_ *= 1e-100;
  }
  if (heap_pos_[v] >= 0) heap_up(static_cast<uint32_t>(heap_pos_[v]));
}

void Cdcl::bump_clause(uint32_t c) {
  const float a = float_of(arena_[c + 2]) + clause_inc_;
  arena_[c + 2] = bits_of(a);
  if (a > 1e20f) {
    for (uint32_t d : learned_) arena_[d + 2] = bits_of(float_of(arena_[d + 2]) * 1e-20f);
    clause_inc_ *= 1e-20f;
  }
}

void Cdcl::heap_insert(uint32_t v) {
  if (heap_pos_[v] >= 0) return;
  heap_pos_[v] = static_cast<int32_t>(heap_.size());
  heap_.push_back(v);
  heap_up(static_cast<uint32_t>(heap_.size() - 1));
}

void Cdcl::heap_up(uint32_t i) {
  const uint32_t v = heap_[i];
  while (i > 0) {
    const uint32_t parent = (i - 1) / 2;
    if (activity_[heap_[parent]] >= activity_[v]) break;
    heap_[i] = heap_[parent];
    heap_pos_[heap_[i]] = static_cast<int32_t>(i);
    i = parent;
  }
  heap_[i] = v;
  heap_pos_[v] = static_cast<int32_t>(i);
}

void Cdcl::heap_down(uint32_t i) {
  const uint32_t v = heap_[i], n = static_cast<uint32_t>(heap_.size());
  for (;;) {
    uint32_t child = 2 * i + 1;
    if (child >= n) break;
    if (child + 1 < n && activity_[heap_[child + 1]] > activity_[heap_[child]]) ++child;
    if (activity_[heap_[child]] <= activity_[v]) break;
    heap_[i] = heap_[child];
    heap_pos_[heap_[i]] = static_cast<int32_t>(i);
    i = child;
  }
  heap_[i] = v;
  heap_pos_[v] = static_cast<int32_t>(i);
}

uint32_t Cdcl::heap_pop() {
  const uint32_t v = heap_[0], last = heap_.back();
  heap_.pop_back();
  heap_pos_[v] = -1;
  if (!heap_.empty()) {
    heap_[0] = last;
    heap_pos_[last] = 0;
    heap_down(0);
  }
  return v;
}

SatAnswer Cdcl::solve(uint64_t max_conflicts, const Progress& progress, uint64_t max_work) {
  backtrack(0);
  if (unsat_ || propagate() != kNone) {
    unsat_ = true;
    return SatAnswer::Unsatisfiable;
  }
  level_stamp_.resize(num_vars() + 1, 0);
  const double total = static_cast<double>(max_conflicts);
  uint64_t done = 0, since_restart = 0, restart_limit = kRestartUnit * luby(restarts_);
  WorkCounter work;
  work.every = 65536;  // a unit: a watch or implication visited
  uint64_t reported = work_;
  const uint64_t work_at_start = work_;
  report(progress, 0, total);
  for (;;) {
    // Progress (and a possible Cancelled, or the end of the work budget) only
    // here, where the state is whole: propagation done or still to do from
    // qhead_, no conflict pending.
    if (work.tick(static_cast<double>(work_ - reported) + 1)) report(progress, static_cast<double>(done), total);
    reported = work_;
    if (work_ - work_at_start > max_work) return SatAnswer::Unknown;
    const uint32_t conflict = propagate();
    if (conflict != kNone) {
      ++conflicts_, ++done, ++since_restart;
      if (decision_level() == 0) {
        unsat_ = true;
        return SatAnswer::Unsatisfiable;
      }
      uint32_t back_level, glue;
      analyze(conflict, learned_buf_, back_level, glue);
      backtrack(back_level);
      const std::vector<uint32_t>& c = learned_buf_;
      if (c.size() == 1) {
        assign(c[0], kNone);
      } else if (c.size() == 2) {
        binary_[c[0] ^ 1].push_back(c[1]), binary_[c[1] ^ 1].push_back(c[0]);
        assign(c[0], kBinary | c[1]);
      } else {
        const uint32_t added = add_long(c, true, glue);
        bump_clause(added);
        assign(c[0], added);
      }
      var_inc_ /= kVarDecay;
      clause_inc_ /= static_cast<float>(kClauseDecay);
      if (conflicts_ >= next_reduce_) {
        reduce_step_ += 300;
        next_reduce_ = conflicts_ + reduce_step_;
        reduce();
      }
      if (done >= max_conflicts) return SatAnswer::Unknown;
      continue;
    }
    if (since_restart >= restart_limit) {
      since_restart = 0;
      restart_limit = kRestartUnit * luby(++restarts_);
      backtrack(0);
      continue;
    }
    uint32_t v = kNone;
    while (!heap_.empty()) {
      const uint32_t u = heap_pop();
      if (val_[2 * u] == 0) {
        v = u;
        break;
      }
    }
    if (v == kNone) {
      model_.resize(num_vars());
      for (uint32_t u = 0; u < num_vars(); ++u) model_[u] = val_[2 * u + 1] > 0;
      return SatAnswer::Satisfiable;
    }
    trail_lim_.push_back(static_cast<uint32_t>(trail_.size()));
    assign(lit(v, phase_[v] != 0), kNone);
  }
}

}  // namespace hodt
