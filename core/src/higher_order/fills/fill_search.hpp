// A branch and bound over the triangulations of a polygon by candidate triangles
// (fill_enumerator.hpp): the same exact cover, grown from the open edge with the
// fewest triangles that fit and that the pruning accepts, so that a dead end
// anywhere on the frontier ends a branch at once.
//
// Two devices keep it from searching the same failure twice:
// - Backjumping. A branch that fails has a reason: the placed triangles that
//   refuse every triangle of some open edge (they overlap it, or make a term
//   no better than the best known with it), that opened that edge, and those
//   that failed each branch below it. Every triangulation that keeps them all
//   fails too, so where the last triangle placed is not among them, its
//   siblings fail the same way: the search returns to the latest one that is.
// - A memo of partial fills searched to the end. Which triangles can complete
//   a partial fill depends on its frontier alone (the covered part is what the
//   frontier bounds), and what their terms read of the placed ones is the
//   pruning's context: two partial fills that agree on both have the same
//   completions, with the same terms.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "higher_order/fills/fill_enumerator.hpp"

namespace hodt {

// The branch and bound's part: which triangles may join those placed, and what
// it read of them. Triangles are placed and removed in stack order; a placed
// triangle's position is how many were placed before it.
struct FillPruning {
  virtual ~FillPruning() = default;
  // Whether t may join the placed triangles (the search then visits only fills
  // whose every triangle was accepted). Refusals only grow as the best known
  // improves.
  virtual bool accept(const Tri& t) = 0;
  virtual void place(const Tri& t) = 0;
  virtual void remove(const Tri& t) = 0;
  // 0, or c when the first c placed triangles alone make every completion no
  // better than the best known (after a better fill was found).
  virtual uint32_t dead() const { return 0; }
  // For a triangle accept() refuses: appends the positions of the placed
  // triangles that make it refuse (none: it fails alone). false: not known
  // (every placed triangle is taken as a reason).
  virtual bool reasons(const Tri& /*t*/, std::vector<uint32_t>& /*positions*/) const { return false; }
  // The memo (memo_words > 0): appends to key what accept() and the value of a
  // completion read of the placed triangles beyond the frontier (open, sorted);
  // explored(): once a partial fill's search ended, what it proved of its
  // completions (nothing: not kept); settled(x): whether a partial fill whose
  // twin proved x needs no search now.
  virtual void context(const std::vector<uint64_t>& /*open*/, std::vector<uint32_t>& /*key*/) const {}
  virtual std::optional<double> explored() const { return std::nullopt; }
  virtual bool settled(double /*proved*/) const { return false; }
  // The memo's size in 32-bit words (0: no memo; once full, the partial fills
  // after are searched without it).
  uint64_t memo_words = 0;
};

// Calls visit for every fill of the polygon bounded by `boundary` (directed
// edges with the inside on their left) that the pruning accepts, except those
// it shows no better than the best known (visit may improve that). Returns
// false if it stopped because `max_nodes` search nodes were used (then
// *nodes_used adds them either way). progress as enumerate_fills'.
bool search_fills(const Mesh& delaunay, const Candidates& candidates,
                  const std::vector<std::pair<uint32_t, uint32_t>>& boundary, uint64_t max_nodes, FillPruning& pruning,
                  const std::function<void(const std::vector<Tri>&)>& visit, const Progress& progress = {},
                  uint64_t* nodes_used = nullptr);

}  // namespace hodt
