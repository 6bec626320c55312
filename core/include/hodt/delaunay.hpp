// The Delaunay triangulation (CGAL, exact predicates, symbolically perturbed so
// that it is unique for cocircular input) as a flat Mesh in canonical order.
#pragma once
#include <vector>

#include "hodt/mesh.hpp"

namespace hodt {

// xyz must be validated (validate_points): finite, distinct (x, y), not all collinear.
// spatially_ordered: the points already follow spatial_order() (skips that sort).
Mesh delaunay(std::vector<double> xyz, bool spatially_ordered = false);

}  // namespace hodt
