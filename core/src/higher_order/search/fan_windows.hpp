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

namespace hodt {

struct WindowLimits {
  uint32_t per_window = 25;
  uint64_t max_steps = 2'000;               // fans tried per window (the best found by then is kept)
  uint64_t max_nodes_per_vertex = 50'000;  // a vertex with more fans keeps its star
  // Fans' tree nodes listed in all (a window's members listed anew at each of
  // the four offsets), the larger of the two: no window starts past it. The
  // windows run in rows from one side, so a budget short of the whole leaves
  // the far side as it was: per point, enough for the four offsets at k = 8 on
  // DEMs (a few thousand nodes per point at that order), so that a large
  // terrain is searched whole; max_nodes is the floor for small inputs.
  uint64_t max_nodes = 16'000'000;
  uint64_t max_nodes_per_point = 8'192;
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
