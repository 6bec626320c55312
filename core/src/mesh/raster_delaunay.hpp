// The Delaunay triangulation of a raster in closed form. When the points are the
// nodes of an axis-aligned lattice (x from a set of columns, y from a set of
// rows, every node once, at any spacing: a DEM at any offset and cell size),
// each cell is a rectangle, its corners exactly cocircular, and no other node is
// inside or on its circle. The triangulation splits every cell by one diagonal,
// the one the in-circle's symbolic perturbation keeps, and that choice depends
// only on the corners' lexicographic order, the same in every cell. Linear time,
// no predicate per point; the same mesh as the incremental construction.
#pragma once
#include <optional>
#include <vector>

#include "hodt/mesh.hpp"

namespace hodt {

// When m's points are a full lattice of at least 2 x 2 nodes: its triangles,
// halfedges and hull (counterclockwise from the smallest vertex), in no
// particular triangle order (canonicalize puts them in order); else false and m
// untouched. Fails fast on other input (it stops once both the columns and the
// rows seen outnumber what a lattice of this size can have).
bool raster_delaunay(Mesh& m);

}  // namespace hodt
