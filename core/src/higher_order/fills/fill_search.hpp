// A branch and bound over the triangulations of a polygon by candidate triangles
// (fill_enumerator.hpp): the same exact cover, grown from the open edge with the
// fewest triangles that fit and that the pruning accepts, so that a dead end
// anywhere on the frontier ends a branch at once.
//
// A branch fails when none of its fills is better than the best known. Two
// devices keep the search from proving the same failure twice:
//
// - Backjumping. Each failed branch leaves a reason: placed triangles such that
//   every fill holding all of them fails. The reason of a node whose open edge
//   u -> v was chosen is the union of
//     the triangle that opened u -> v (every fill holding it has the edge u v,
//     and something on its open side: a candidate u v w, the candidates being
//     every triangle a fill may have);
//     for each w tried: its child's reason, less w itself;
//     for each w not tried: why it was not. It overlaps a placed triangle
//     (named by the placed edge it meets, or the triangle already behind one
//     of its sides), or the pruning refused it and names the placed triangles
//     it makes a term no better than the best known with (reasons()).
//   A fill holding the union and the opener holds some u v w and the rest of
//   that w's reason, so it fails. When a child's reason does not hold the
//   triangle just tried, it is already a reason for this node: its siblings
//   are not tried, and the search returns to the latest triangle the reason
//   holds. The best known only improves, so a reason found against an older
//   best still holds.
//
// - A memo of partial fills searched to the end. The fills that complete a
//   partial fill are the triangulations of the uncovered part by candidates,
//   and that part is what the frontier (the open edges) bounds. The terms a
//   completion adds are its own and those it makes with the placed triangles,
//   which the pruning's context tells (context()). When a partial fill's
//   search ended, its placed triangles' own terms below the best known
//   (explored()), every completion added a term at least the best known then:
//   a later partial fill with the same frontier and context has the same
//   completions adding the same terms, each at least the best then, so no
//   less than the best now (it only improves). That fill fails, with every
//   placed triangle as its reason.
#pragma once
#include <cstdint>
#include <functional>
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
  // 0, or c when the first c placed triangles alone make every fill holding
  // them no better than the best known (after a better fill was found).
  virtual uint32_t dead() const { return 0; }
  // For a triangle accept() refuses: appends the positions of the placed
  // triangles that make it refuse, so that every fill holding them and t is no
  // better than the best known (none: t alone is). false: not known (every
  // placed triangle is taken as the reason).
  virtual bool reasons(const Tri& /*t*/, std::vector<uint32_t>& /*positions*/) const { return false; }
  // The memo (memo_words > 0). context: appends to key what a completion's
  // terms read of the placed triangles, given the frontier (open, sorted
  // directed edges), so that equal frontiers and keys mean equal terms for
  // every completion. explored: whether the placed triangles' own terms are
  // below the best known (then a search of their completions that failed
  // proved every completion adds a term at least the best known).
  virtual void context(const std::vector<uint64_t>& /*open*/, std::vector<uint32_t>& /*key*/) const {}
  virtual bool explored() const { return false; }
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
