// Counting the points inside a circle by walking the Delaunay triangulation.
#pragma once
#include <cstdint>
#include <vector>

#include "hodt/mesh.hpp"

namespace hodt {

// Walks a Delaunay mesh from the vertices a, b, c (counterclockwise) and counts the
// vertices strictly inside their circumcircle (perturbed in_circle), stopping as
// soon as the count exceeds `limit`. Correct because the vertices inside any circle
// through three vertices, with those three, induce a connected subgraph of the
// Delaunay triangulation (on the lifted paraboloid they are the vertices of the
// lower hull below a plane, and a linear function on a convex polytope decreases
// along edges to its minimum). Cost: proportional to the vertices visited.
class CircleCounter {
 public:
  explicit CircleCounter(const Mesh& delaunay);
  uint32_t count(uint32_t a, uint32_t b, uint32_t c, uint32_t limit);
  // The vertices found inside by the last count (at most limit + 1).
  const std::vector<uint32_t>& inside() const { return inside_; }

 private:
  const Mesh& mesh_;
  std::vector<int32_t> vertex_edge_;
  std::vector<uint32_t> mark_;  // visit stamp per vertex
  uint32_t stamp_ = 0;
  std::vector<uint32_t> queue_, inside_;
};

}  // namespace hodt
