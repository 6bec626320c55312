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
// (ESRI .prj files name none). nullopt: not WKT (a CRS keyword such as PROJCS or
// GEOGCRS, then balanced brackets).
std::optional<std::string> crs_of_wkt(std::string_view wkt);

// A CRS given on the command line, as far as it can be recognised: an EPSG code
// in its usual spellings (EPSG:N in any case, EPSG::N, urn:ogc:def:crs:EPSG::N,
// http://www.opengis.net/def/crs/EPSG/0/N, or N alone) as "EPSG:N"; WKT as
// above; a PROJ string (+proj=... +key=value ...) on one line. nullopt for
// anything else, for empty text and for more than kMaxCrsChars.
std::optional<std::string> crs_of_text(std::string_view text);
constexpr size_t kMaxCrsChars = 16384;

// The ESRI sidecar of a data file: dem.asc -> dem.prj (a name without an
// extension gets .prj appended).
std::string prj_path(const std::string& file);

}  // namespace hodt
