// What `--drainage FILE.geojson` writes: a terrain's drainage network (drainage.hpp)
// as a GeoJSON FeatureCollection, with the points and the CRS as the TIN writers
// take them (tin_output.hpp): every input point as read, input indices.
#pragma once
#include <string>
#include <vector>

#include "hodt/drainage.hpp"

namespace hodt {

// drainage: in input indices (drainage(terrain, mesh)); input_xyz: every input
// point as read. One feature per line: a LineString per drainage edge [from, to]
// with properties "from", "to" (point indices) and "accumulation" (of from), then a
// Point per pit and per outlet with "point", "kind" ("pit" or "outlet") and
// "basinSize". Coordinates [x, y, z], each the shortest decimal that reads back to
// the same double; an EPSG CRS as GeoJSON's named "crs" member, as the TIN's
// GeoJSON has it.
std::string drainage_geojson(const Drainage& drainage, const std::vector<double>& input_xyz, const std::string& crs);

}  // namespace hodt
