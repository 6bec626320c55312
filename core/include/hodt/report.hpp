// JSON documents of the CLI contract.
#pragma once
#include <string>

#include "hodt/solution.hpp"
#include "hodt/terrain.hpp"

namespace hodt {

// {"points", "triangles", "edges", "flippable", "hullVertices", "delaunay": {id: value}}
// With order k > 1 (or k given): also "usefulEdges" and "usefulTriangles" counts.
std::string stats_json(const Terrain& terrain, uint32_t order = 0);
// {"objective", "sense", "method", "value", "delaunayValue", "optimal", "bound",
//  "flipped", "timeMs"[, "critical": {"first", "second", "value"}]
//  [, "trace": [{"threshold", "satisfiable", "clauses"}, ...]][, "triangles"]}
std::string solution_json(const Terrain& terrain, const Solution& s, bool with_triangles, bool with_trace = false);

}  // namespace hodt
