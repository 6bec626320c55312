// A proven bound for counts at order k from the vertices' stars alone: every
// vertex picks one of its fans, and the fans agree only through multipliers.
//
// A vertex's fan is the cycle of its triangles in one triangulation (at a hull
// vertex, from one hull edge round to the other). In a k-OD triangulation each is
// made of candidate triangles (k-OD, empty, three useful edges), so listing every
// such cycle lists every star the vertex can have. A count whose terms sit at
// vertices (over the star) or at interior edges (over the two triangles, both in
// the fan of the edge's smaller end) is then the sum over vertices of a term of
// its fan. Lagrangian relaxation of "a diamond (an edge with the triangles on
// either side) is in the fans of both its ends, or of neither"
// (diamond_ends.hpp): with the two ends' multipliers summing to 0, any
// triangulation keeps its value, and the sum of each vertex's best fan bounds
// the optimum. Block coordinate descent over each diamond's ends (MPLP) lowers
// it. No region is needed, so the bound stays close where the fixed edges
// leave one region too large to list, whose terms a relaxation over regions
// can only read at their best. Diamonds bind tighter than triangles (agreeing
// on each triangle alone): the two ends of an edge then agree on both its
// sides at once.
//
// Exact: multipliers are integers in units of 2^-12, every sum an integer, and
// the bound is the floor of the best (max) or the ceiling (min).
#pragma once
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "hodt/mesh.hpp"
#include "hodt/objectives.hpp"
#include "hodt/progress.hpp"
#include "higher_order/fills/fill_enumerator.hpp"
#include "tuning/budgets.hpp"

namespace hodt {

class StarDecoder;  // (star_decode.hpp)

// (Defaults and reasons: tuning/budgets.hpp, star_*.)
struct StarBoundLimits {
  // Fans' tree nodes per vertex (vertices beyond are left out, their terms at
  // their best; when more than max_left_out of them are, no bound) and per tile.
  uint64_t max_nodes_per_vertex = kBudgets.star_max_nodes_per_vertex;
  uint64_t max_nodes = kBudgets.star_max_nodes;
  double max_left_out = kBudgets.star_max_left_out;
  uint32_t iterations = kBudgets.star_iterations;  // sweeps over every diamond, at most
  // A bound proven already (as the objective's, not the relaxation's sign; NAN
  // for none): for counts, sweeps also stop once they cannot pass it.
  double known_bound = NAN;
  // Fans the sweeps read, in all, shared among the tiles by their vertices.
  uint64_t max_visits = kBudgets.star_max_visits;
  // A gap left: keep the fans and their values under the multipliers, to read
  // triangulations off them (StarDecoder), within this many fans tried per vertex.
  bool decode = false;
  uint64_t decode_steps_per_vertex = kBudgets.star_decode_steps_per_vertex;
  // Decoding over tiles of many (their trees are not all in memory at once):
  // after each tile's sweeps, a decoder over its vertices' fans with every
  // other vertex held at its fan in *start (a k-OD triangulation of the
  // points), passed to decoded_tile, which may change *start before the next.
  const Mesh* start = nullptr;
  std::function<void(const StarDecoder&)> decoded_tile;
  Progress progress;
};

struct StarBound {
  double bound;           // no k-OD triangulation is better
  uint64_t nodes = 0;     // of the fans' prefix trees (the largest tile's)
  uint32_t tiles = 1;     // (more than one: no decoder; decoded_tile had each tile's)
  uint32_t left_out = 0;  // vertices whose fans were over the budgets
  std::shared_ptr<const StarDecoder> decoder;  // (decode, a gap left, no vertex left out)
};

// Counts (terms summed, integers, at vertices, not vertex pairs, or at
// interior edges) and minimised lengths over every edge (in fixed point, each
// rounded down: the bound is then not an integer), no domain; nothing
// otherwise, or when too many vertices were left out. incumbent: the value of a
// triangulation at hand (the steps aim at it; they stop once it is proven).
std::optional<StarBound> star_bound(const Mesh& delaunay, Objective o, const Candidates& candidates, double incumbent,
                                    const StarBoundLimits& limits = {});

// Min-max objectives: every vertex has one of its fans, so the optimum is at
// least, over the vertices, the least over each one's fans of the worst term
// the fan holds (terms within one star: the vertex's own, its triangles, its
// edges with both their triangles, pairs of its triangles). Vertices whose
// fans are over max_nodes_per_vertex say nothing. Nothing for other objectives.
std::optional<double> star_floor(const Mesh& delaunay, Objective o, const Candidates& candidates,
                                 const StarBoundLimits& limits = {});

}  // namespace hodt
