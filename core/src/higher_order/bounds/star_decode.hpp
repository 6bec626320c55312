// A triangulation read off the vertices' fans (fan_trees.hpp): one fan per
// vertex, the fans of every two neighbours agreeing on the triangles of their
// edge. Agreeing stars are a triangulation: each triangle of a fan is then in
// the fans of its other two corners, and every fan winds once round its vertex
// (or from hull edge to hull edge), so the triangles cover the hull once.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "hodt/mesh.hpp"
#include "hodt/skeleton.hpp"
#include "higher_order/bounds/fan_trees.hpp"

namespace hodt {

// Holds the fans and their values (the star bound's reduced values: weight
// plus multipliers). A search over the vertices in sweep order (along an axis,
// ties by index) takes each vertex's fans in the order of their values,
// highest first; each choice removes the neighbours' fans that disagree with
// it, and the search goes back to the last choice when a neighbour has none
// left. When the relaxation is nearly tight (as at order 8 on DEM grids), the
// first fans agree nearly everywhere: a triangulation of about the bound's
// value. Nothing when a vertex has no fan or after max_steps fans tried.
class StarDecoder {
 public:
  StarDecoder(const Mesh& delaunay, FanTrees trees, std::vector<Tri> triangles, std::vector<int64_t> value,
              uint64_t max_steps);
  // One search per sweep direction (four: each leaves other disagreements
  // to the end), the triangulations found.
  std::vector<std::vector<Tri>> sweeps() const;
  // The first sweep with ties going to the fans of `start` (a repair of it:
  // its fans stay wherever the multipliers do not prefer another).
  std::optional<std::vector<Tri>> repair(const Mesh& start) const;

 private:
  std::optional<std::vector<Tri>> search(const std::vector<int64_t>& value, const double axis[2]) const;
  const Mesh& dt_;
  FanTrees t_;
  std::vector<Tri> tris_;  // by id (a corner is 3 id + position)
  std::vector<int64_t> value_;
  std::vector<std::vector<uint32_t>> near_;  // (per vertex: those its fans pass through, and those through it)
  uint64_t max_steps_;
};

}  // namespace hodt
