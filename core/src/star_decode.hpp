// A triangulation read off the vertices' fans (fan_trees.hpp): one fan per
// vertex, the fans of every two neighbours agreeing on the triangles of their
// edge. Agreeing stars are a triangulation: each triangle of a fan is then in
// the fans of its other two corners, and every fan winds once round its vertex
// (or from hull edge to hull edge), so the triangles cover the hull once.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "fan_trees.hpp"
#include "hodt/mesh.hpp"

namespace hodt {

// A search over the vertices in sweep order (along `axis`, ties by index), each taking its
// fans in the order of `value` (per fan, highest first), each choice removing
// the neighbours' fans that disagree with it, back to the last choice when a
// neighbour has none left. When the values are the star bound's reduced
// values and its relaxation is tight (as at order 8 on DEM grids), the first
// fans agree nearly everywhere: a triangulation of about the bound's value.
// Nothing when a vertex has no fan or after max_steps fans tried.
std::optional<std::vector<Tri>> decode_fans(const Mesh& delaunay, const FanTrees& trees,
                                            const std::vector<int64_t>& value, const double axis[2], uint64_t max_steps);

}  // namespace hodt
