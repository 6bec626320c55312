// Local edits of a Delaunay mesh built by delaunay(): afterwards the mesh is the
// Delaunay triangulation (same perturbation) of the new vertex set, and only the
// triangles around the edit were rewritten. Used by Terrain's live edits.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "hodt/mesh.hpp"

namespace hodt {

struct MeshEdit {
  std::vector<uint32_t> changed_vertices;  // vertices whose star changed (repeats possible)
  // Triangle slots moved to fill the holes a removal leaves: (from, to), in order.
  std::vector<std::pair<uint32_t, uint32_t>> moved_triangles;
};

// The vertex at (x, y), if any: a walk from triangle `start`.
int64_t vertex_at(const Mesh& m, double x, double y, uint32_t start = 0);

// Appends vertex (x, y, z) (number num_vertices()) and retriangulates around it.
// The caller checks first that no vertex is at (x, y) (vertex_at).
MeshEdit insert_vertex(Mesh& m, double x, double y, double z, uint32_t start = 0);

// Removes interior vertex v: its star is replaced by the Delaunay triangles of its
// neighbours inside the star, the last vertex takes number v and the last triangles
// fill the freed slots. Returns false, leaving the mesh unchanged, if v is on the
// hull or has more than max_degree neighbours (the caller rebuilds instead).
bool remove_vertex(Mesh& m, uint32_t v, MeshEdit& edit, uint32_t max_degree = 64);

}  // namespace hodt
