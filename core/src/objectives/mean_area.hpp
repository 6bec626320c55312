// Every triangulation of a point set covers its hull with the same number of
// triangles, so its largest triangle is at least the mean: the hull's area over
// that number. minmax-triangle-area reads it as a bound at every order.
#pragma once
#include "hodt/mesh.hpp"

namespace hodt {

// The mean plane area of the triangles of `m` (any triangulation of the
// points), rounded down: the hull's area is summed exactly, so a result equal
// to this double is proven optimal. 0 without triangles.
double mean_triangle_area_below(const Mesh& m);

}  // namespace hodt
