// JSON documents of the CLI contract.
#pragma once
#include <string>

#include "hodt/drainage.hpp"
#include "hodt/solution.hpp"
#include "hodt/terrain.hpp"

namespace hodt {

// {"points", "triangles", "edges", "flippable", "hullVertices", "delaunay": {id: value},
//  "drainage": {"pits", "outlets"}} (of the base triangulation; drainage.hpp)
// With order k > 1 (or k given): also "usefulEdges" and "usefulTriangles" counts.
// drainage: the base triangulation's, when the caller has it (else computed).
std::string stats_json(const Terrain& terrain, uint32_t order = 0, const Drainage* drainage = nullptr);
// How long the CLI's steps took, in milliseconds.
struct PhaseTimes {
  double read_ms = 0;   // reading and parsing the file
  double build_ms = 0;  // Delaunay triangulation and first order structure
  double solve_ms = 0;  // the solve, with the Delaunay value it is compared to
};

// {"objective", "sense", "method", "value", "delaunayValue", "optimal", "bound",
//  "flipped", "timeMs"[, "times": {"readMs", "buildMs", "solveMs"}][, "order"],
//  "drainage": {"pits", "outlets"}
//  [, "critical": {"first", "second", "value"}]
//  [, "trace": [{"threshold", "satisfiable", "clauses"}, ...]][, "phases": [...]]}
// triangulation: the solution's (its mesh, or its choice triangulated), and
// drainage its network: the caller has them for its other outputs too. The
// triangles, when wanted, are added by with_triangles_json.
std::string solution_json(const Terrain& terrain, const Solution& s, const Mesh& triangulation, const Drainage& drainage,
                          bool with_trace = false, const PhaseTimes* times = nullptr);
// A JSON document (an object) with "key": [[i, j, k], ...] (input indices) added last.
std::string with_triangles_json(std::string document, const std::vector<uint32_t>& input_triangles,
                                const std::string& key = "triangles");

}  // namespace hodt
