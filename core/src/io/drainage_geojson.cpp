#include "io/drainage_geojson.hpp"

#include <charconv>
#include <cstdint>

#include "hodt/format.hpp"

namespace hodt {
namespace {

void append_uint(std::string& s, uint64_t v) {
  char buf[24];
  s.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

// The named CRS member (the GeoJSON 2008 member RFC 7946 dropped; GDAL and QGIS
// read it), for an EPSG code only: a WKT or PROJ definition has no name there.
std::string crs_member(const std::string& crs) {
  const std::string prefix = "EPSG:";
  if (crs.rfind(prefix, 0) != 0 || crs.size() == prefix.size()) return "";
  for (size_t k = prefix.size(); k < crs.size(); ++k)
    if (crs[k] < '0' || crs[k] > '9') return "";
  return "\"crs\":{\"type\":\"name\",\"properties\":{\"name\":\"urn:ogc:def:crs:EPSG::" + crs.substr(prefix.size()) + "\"}},";
}

}  // namespace

std::string drainage_geojson(const Drainage& d, const std::vector<double>& xyz, const std::string& crs) {
  // Each point's "[x,y,z]" once: an edge names two points, and a point is the end
  // of up to its degree many edges.
  const size_t n = d.downstream.size();
  std::string at;
  std::vector<size_t> from(n + 1, 0);
  for (size_t i = 0; i < n; ++i) {
    from[i] = at.size();
    at += '[' + format_number(xyz[3 * i]) + ',' + format_number(xyz[3 * i + 1]) + ',' + format_number(xyz[3 * i + 2]) + ']';
  }
  from[n] = at.size();
  const auto point = [&](std::string& s, size_t i) { s.append(at, from[i], from[i + 1] - from[i]); };

  std::string s = "{\"type\":\"FeatureCollection\"," + crs_member(crs) + "\"features\":[";
  s.reserve(s.size() + 2 * at.size() + 110 * n);
  bool first = true;
  const auto feature = [&]() {
    s += first ? "\n" : ",\n";
    first = false;
  };
  for (size_t i = 0; i < n; ++i) {
    if (d.downstream[i] < 0) continue;
    const auto to = static_cast<size_t>(d.downstream[i]);
    feature();
    s += "{\"type\":\"Feature\",\"properties\":{\"from\":";
    append_uint(s, i);
    s += ",\"to\":";
    append_uint(s, to);
    s += ",\"accumulation\":";
    append_uint(s, d.accumulation[i]);
    s += "},\"geometry\":{\"type\":\"LineString\",\"coordinates\":[";
    point(s, i);
    s += ',';
    point(s, to);
    s += "]}}";
  }
  for (const auto& [ends, kind] : {std::pair{&d.pits, "pit"}, std::pair{&d.outlets, "outlet"}})
    for (const uint32_t v : *ends) {
      feature();
      s += "{\"type\":\"Feature\",\"properties\":{\"point\":";
      append_uint(s, v);
      s += std::string(",\"kind\":\"") + kind + "\",\"basinSize\":";
      append_uint(s, d.accumulation[v]);
      s += "},\"geometry\":{\"type\":\"Point\",\"coordinates\":";
      point(s, v);
      s += "}}";
    }
  s += "\n]}\n";
  return s;
}

}  // namespace hodt
