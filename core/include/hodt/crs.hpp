// The coordinate reference system of the input, as far as hodt keeps one: it
// never reprojects, it passes the CRS on to the outputs that have a place for it
// (the JSON documents, GeoJSON's named crs, PLY/OBJ comments, glTF extras).
#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace hodt {

// "EPSG:N" when a WKT definition (WKT1 AUTHORITY["EPSG","N"] or WKT2
// ID["EPSG",N] of the outermost CRS) names one, else the definition on one line
// (ESRI .prj files name none). nullopt: not WKT.
std::optional<std::string> crs_of_wkt(std::string_view wkt);

// A CRS given on the command line: "EPSG:N" (any case), or WKT as above; other
// text is kept as given. nullopt: empty or longer than kMaxCrsChars.
std::optional<std::string> crs_of_text(std::string_view text);
constexpr size_t kMaxCrsChars = 16384;

// The ESRI sidecar of a data file: dem.asc -> dem.prj (a name without an
// extension gets .prj appended).
std::string prj_path(const std::string& file);

}  // namespace hodt
