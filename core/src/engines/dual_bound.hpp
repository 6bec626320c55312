// A proof for sums too wide for the exact DP (state_graph.hpp).
//
// The dual of the local-polytope relaxation: messages from each factor to the
// classes of each of its variables move value between the factor and the
// variable, so any messages leave every assignment's value unchanged, and the
// sum of every piece's own best (each variable's best state, each factor's best
// entry) bounds the optimum. Block coordinate ascent (MPLP, Globerson and
// Jaakkola 2007) raises that bound. On graphs of integer values the messages
// live on a dyadic grid, so every sum is exact: the bound is a proof, not an
// estimate.
//
// With an incumbent, a state whose reduced cost alone takes the bound past the
// incumbent cannot be in a better assignment, nor can a factor entry: both are
// dropped, and the exact DP over what remains (usually far narrower) either
// finds the better assignment or proves the incumbent optimal.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "engines/state_graph.hpp"
#include "tuning/budgets.hpp"

namespace hodt {

// (Defaults and reasons: tuning/budgets.hpp.)
struct DualLimits {
  double cluster_entries = kBudgets.dual_cluster_entries;  // table entries per cluster of factors (1: none)
  uint32_t max_sweeps = kBudgets.dual_max_sweeps;          // passes over every factor
  uint32_t max_rounds = kBudgets.dual_max_rounds;          // rounds of proving
  double min_gain = kBudgets.dual_min_gain;                // a pass raising the bound by less stops
  Progress progress;
};

// A factor too large to tabulate, read through its min-marginals (a region's
// fills, region_dual.hpp): the ascent updates it like a table. Min form (a
// maximised objective's values negated); its values must be integers.
struct ImplicitFactor {
  std::vector<uint32_t> scope;  // distinct variables, each read state by state
  virtual ~ImplicitFactor() = default;
  // With costs[j][s] added where scope variable j is in state s: the least
  // total, exact; marginals (when not null): per j and s the least total with j
  // in state s (an estimate is enough: it only steers the ascent).
  virtual double least(const std::vector<std::vector<double>>& costs,
                       std::vector<std::vector<double>>* marginals) const = 0;
};

// A sum whose every value is an integer of moderate size (counts): what the
// bound can prove exactly.
bool integral_sum(const StateGraph& g);

// The ascent, run once; then bounds, a decoded start, and proofs of incumbents.
class DualProof {
 public:
  // stop_at: the ascent may stop once its bound proves an assignment of this
  // value optimal. Applies to sum graphs whose every value is a moderate
  // integer (counts), with no relaxed terms and no partial variables.
  // implicit: factors beside the graph's (they must outlive this); with them,
  // prove() proves only what the bound alone proves.
  DualProof(const StateGraph& g, const DualLimits& limits = {}, std::optional<double> stop_at = std::nullopt,
            std::vector<const ImplicitFactor*> implicit = {});
  ~DualProof();
  DualProof(const DualProof&) = delete;

  bool applies() const;
  // No assignment is better (rounded to the integer side; nothing if not applies()).
  std::optional<double> bound() const;
  uint32_t sweeps() const;
  // Per variable, its best state under the final messages: a start for local
  // search (often far from any incumbent's neighbourhood).
  std::vector<uint32_t> decoded() const;
  // Implicit factor i's costs for decoding (its variables' final beliefs, min
  // form): its least state under them is a start for the same search.
  std::vector<std::vector<double>> implicit_costs(size_t i) const;
  // Implicit factor i held at one of its values (min form): with these costs
  // on its variables' states, `offset` plus its least total over the values
  // that take them bounds every assignment that does (as prove() bounds
  // states and entries). Nothing when the values left the exact range.
  struct ImplicitReduced {
    std::vector<std::vector<double>> costs;
    double offset = 0;
  };
  std::optional<ImplicitReduced> implicit_reduced(size_t i) const;
  // Proves an incumbent optimal or finds a better optimum: pruning by the
  // bound, then the exact DP over what is left (a LimitError there leaves
  // `proven` false; dp_limits.mini_buckets is ignored). The incumbent must be
  // the value of an assignment the caller holds: "proven" with no `better`
  // means no assignment beats it, which makes it optimal only if it is reached.
  struct Proof {
    bool proven = false;                          // the incumbent, or `better`, is optimal
    std::optional<std::vector<uint32_t>> better;  // an optimum better than the incumbent
    double better_value = 0;
    uint64_t states = 0, kept_states = 0;         // before and after pruning
    uint64_t entries = 0, kept_entries = 0;       // factor table entries, the same
  };
  Proof prove(double incumbent, const StateDpLimits& dp_limits = {}) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hodt
