// A min-max objective at order k as a sequence of satisfiability questions:
// "is there a k-OD triangulation whose every term is below t?", asked of a CDCL
// solver (engines/cdcl.hpp) for t the best value known, then for the value of
// each triangulation it answers with, until it answers no.
//
// The encoding: a variable per candidate triangle (k-OD, empty, every edge a
// useful k-OD edge: fill_enumerator.hpp) and per candidate edge, and clauses that
// every triangulation of the points by candidates satisfies:
//   - a used triangle uses its edges;
//   - a convex hull edge is used; a used edge has a used triangle on each side
//     that has one (the inside only, on the hull), and at most one;
//   - two crossing edges are not both used;
// and, for the threshold t, what every triangulation whose terms are all below t
// satisfies:
//   - a triangle whose own term is at least t is not used;
//   - two triangles whose pair term (across an edge, or at a shared vertex) is
//     at least t are not both used;
//   - a vertex has fewer used edges than the least degree whose term reaches t
//     (a sequential counter; a degree's term only grows with the degree).
// Every clause is one every such triangulation meets, so "unsatisfiable" proves
// that none exists: the best value known is optimal. Conversely a model's used
// triangles are a triangulation: they do not overlap (sides hold one triangle,
// edges do not cross, candidates are empty), and the region they cover has no
// boundary but the hull (every used edge has a triangle on each side). Its
// terms are below t by the clauses, and it is measured again all the same.
//
// Thresholds only go down, so each question adds clauses to the last one's: the
// solver keeps what it learned (every learned clause follows from fewer clauses).
#pragma once
#include <cstdint>
#include <optional>

#include "hodt/mesh.hpp"
#include "hodt/objectives.hpp"
#include "hodt/progress.hpp"
#include "higher_order/fills/fill_enumerator.hpp"

namespace hodt {

struct ThresholdSat {
  std::optional<Mesh> found;  // the best triangulation better than `known`, if any
  double value = 0;           // its value (else `known`)
  bool complete = false;      // the last question was answered no: value is the optimum
  uint32_t questions = 0;     // questions asked (answered or not)
  uint64_t conflicts = 0;     // the solver's, over every question
  uint64_t work = 0;          // the solver's watches and implications visited, over every question
  size_t clauses = 0;         // the encoding's, at the last question
};

// Whether the objective's terms allow it: the branch and bound's (min-max, no
// domain, terms of triangles, of pairs of triangles or of a vertex's degree).
bool threshold_sat_applies(Objective o, const Mesh& delaunay);

// known: the value of a triangulation in hand; start (optional): one to try
// first, the solver's decisions preferring its triangles and edges (a better
// triangulation is most often a few changes away from a good one).
// max_conflicts, max_work: the solver's budgets over every question
// (Cdcl::solve; when one runs out, complete is false).
ThresholdSat threshold_sat(const Mesh& delaunay, Objective o, const Candidates& candidates, double known,
                           uint64_t max_conflicts, uint64_t max_work, const Progress& progress = {},
                           const Mesh* start = nullptr);

}  // namespace hodt
