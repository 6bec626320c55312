// The one answer of an order-k solve: the best triangulation found, its value,
// the proven bound on the optimum, and what produced each. The solve's phases
// (phases/phase_table.hpp) offer triangulations and tighten the bound; nothing
// else writes the answer, and only here is `optimal` decided: when the bound
// meets the value. A phase that proves its own triangulation optimal (an exact
// DP, a dual proof) takes it with `prove_with`, which is the same rule with the
// bound set to the value it proved.
#pragma once
#include <optional>
#include <string>

#include "hodt/mesh.hpp"
#include "hodt/objectives.hpp"

namespace hodt {

class Incumbent {
 public:
  explicit Incumbent(Sense sense) : sense_(sense) {}

  // A triangulation of value v, found by `by` (in a few words). Taken when it
  // is the first, or strictly better (or as good, with on_tie); returns
  // whether it was taken.
  bool offer(Mesh m, double v, const std::string& by, bool on_tie = false) {
    if (has_ && (on_tie ? better(sense_, value_, v) : !better(sense_, v, value_))) return false;
    triangulation_ = std::move(m), value_ = v, has_ = true;
    found_by_ = found_by_.empty() ? by : found_by_ + ", then " + by;
    return true;
  }
  // Replaces what was found (its record too): a phase's answer that starts the
  // record anew.
  void restart(Mesh m, double v, const std::string& by) {
    triangulation_ = std::move(m), value_ = v, has_ = true, found_by_ = by;
  }
  // A proven bound on the optimum (from `by`); kept when tighter.
  void tighten(double bound, const std::string& by) {
    if (bound_ && !better(sense_, *bound_, bound)) return;
    bound_ = bound;
    bound_by_ = by;
  }
  // A proof that the value held is the optimum.
  void prove(const std::string& why) { tighten(value_, why), proof_ = why; }
  // A triangulation proven optimal by `why` (of value v): taken even over an
  // equal one, so that the proof's own optimum is the answer.
  void prove_with(Mesh m, double v, const std::string& by, const std::string& why) {
    if (!has_ || !better(sense_, value_, v)) triangulation_ = std::move(m), value_ = v, has_ = true, found_by_ = by;
    prove(why);
  }
  // A remark for the details (a phase that ran and changed nothing).
  void note(const std::string& text) { notes_ += text; }

  bool has() const { return has_; }
  const Mesh& triangulation() const { return triangulation_; }
  Mesh take_triangulation() { return std::move(triangulation_); }
  double value() const { return value_; }
  // The bound, never on the wrong side of the value.
  std::optional<double> bound() const {
    if (!bound_) return bound_;
    return has_ && better(sense_, value_, *bound_) ? value_ : *bound_;
  }
  bool optimal() const { return has_ && bound_ && !better(sense_, *bound_, value_); }

  const std::string& found_by() const { return found_by_; }
  const std::string& bound_by() const { return bound_by_; }
  // What proved the answer optimal by a proof of its own (empty when the bound
  // of bound_by() met it).
  const std::string& proof() const { return proof_; }
  const std::string& notes() const { return notes_; }
  Sense sense() const { return sense_; }

 private:
  Sense sense_;
  Mesh triangulation_;
  double value_ = 0;
  bool has_ = false;
  std::optional<double> bound_;
  std::string found_by_, bound_by_, proof_, notes_;
};

}  // namespace hodt
