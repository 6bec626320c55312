// Branch and bound over every k-OD triangulation of the instance, for min-max
// objectives. The fill search (fill_search.hpp) places one triangle at a
// time; a min-max objective's terms are read off triangles alone (a triangle,
// a pair sharing an edge or a vertex) or only grow as triangles are placed (a
// vertex's degree), so each is final, or a floor, once its triangles are
// placed. A triangle that makes a term no better than the best value known
// cannot be in a better triangulation and is not placed; once a better one is
// found, a branch whose placed terms already reach its value is left. The
// search backjumps and keeps a memo (fill_search.hpp): its context is what the
// terms still to come read of the placed triangles. A search that ends within
// its budget has seen every better triangulation: the best it found is optimal.
#pragma once
#include <cstdint>
#include <optional>

#include "hodt/mesh.hpp"
#include "hodt/objectives.hpp"
#include "hodt/progress.hpp"
#include "higher_order/fills/fill_search.hpp"

namespace hodt {

struct BranchAndBound {
  std::optional<Mesh> found;  // the best triangulation better than `known`, if any
  double value = 0;           // its value (else `known`)
  bool complete = false;      // the search ended within its budget: value is the optimum
  uint64_t nodes = 0;
};

// Whether the objective's terms allow it (min-max, no domain).
bool branch_and_bound_applies(Objective o, const Mesh& delaunay);

// known: the value of a triangulation in hand. memo_words: the size of the
// memo of partial fills searched to the end (FillPruning; 0: none).
BranchAndBound branch_and_bound(const Mesh& delaunay, Objective o, const Candidates& candidates, double known,
                                uint64_t max_nodes, uint64_t memo_words, const Progress& progress = {});

}  // namespace hodt
