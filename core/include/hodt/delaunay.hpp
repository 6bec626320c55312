// The Delaunay triangulation (exact predicates, in-circle symbolically perturbed as
// CGAL does, so that it is unique for cocircular input and equal to CGAL's) as a
// flat Mesh in canonical order (mesh.hpp).
#pragma once
#include <vector>

#include "hodt/mesh.hpp"

namespace hodt {

// xyz must be validated (validate_points): finite, distinct (x, y), not all collinear.
// spatially_ordered: the points already follow spatial_order() (skips that sort).
Mesh delaunay(std::vector<double> xyz, bool spatially_ordered = false);

}  // namespace hodt
