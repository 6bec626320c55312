// Descent by windows at order k: each window of about per_window vertices
// (tiles of the plane, at four offsets) takes its best fans (fan_trees.hpp),
// every other vertex keeping its star in the triangulation at hand. Fans that
// agree with their neighbours' are a triangulation (star_decode.hpp), so the
// window's best is a branch and bound over its members' fans that agree with
// the outside: a large neighbourhood searched exactly, which flips and region
// descents do not reach (a window changes the stars of many neighbouring
// vertices at once, across region borders). Lists fans one window at a time,
// within a budget of nodes listed in all.
#pragma once
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "hodt/mesh.hpp"
#include "hodt/objectives.hpp"
#include "hodt/progress.hpp"
#include "higher_order/fills/fill_enumerator.hpp"
#include "tuning/budgets.hpp"

namespace hodt {

// (Defaults and reasons: tuning/budgets.hpp, fan_window_*.)
struct WindowLimits {
  uint32_t per_window = kBudgets.fan_window_vertices;
  uint64_t max_steps = kBudgets.fan_window_steps;  // fans tried per window (the best found by then is kept)
  uint64_t max_nodes_per_vertex = kBudgets.fan_window_nodes_per_vertex;  // a vertex with more keeps its star
  // Fans' tree nodes listed in all, the larger of the two: no window starts past it.
  uint64_t max_nodes = kBudgets.fan_window_max_nodes;
  uint64_t max_nodes_per_point = kBudgets.fan_window_nodes_per_point;
  // Stop once the windows improved the start by this much (the objective's
  // units; a gap to a proven bound: nothing more to gain).
  double enough = INFINITY;
  // Where the tiles lie (one of eight placements, in turn): calls with other
  // placements cut the plane elsewhere.
  uint32_t placement = 0;
  Progress progress;
};

// Sums over vertices or edges (fan_terms.hpp), no domain; nothing otherwise,
// or when no window improved `start` (a k-OD triangulation of delaunay's
// points). The triangles of the result, counterclockwise.
std::optional<std::vector<Tri>> improve_by_windows(const Mesh& delaunay, Objective o, const Candidates& candidates,
                                                   const Mesh& start, const WindowLimits& limits = {});

}  // namespace hodt
