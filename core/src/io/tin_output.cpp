#include "hodt/tin_output.hpp"

#include <algorithm>
#include <array>
#include <cctype>

#include "hodt/domain.hpp"
#include "hodt/measures.hpp"

namespace hodt {
namespace {

constexpr std::array<OutputFormat, 5> kFormats = {OutputFormat::Json, OutputFormat::Obj, OutputFormat::Ply,
                                                  OutputFormat::GeoJson, OutputFormat::Glb};

// A counterclockwise triangle rotated to start at its smallest vertex: equal
// triangles listed from different corners compare equal.
std::array<uint32_t, 3> canonical(const uint32_t* t) {
  const int k = t[0] < t[1] ? (t[0] < t[2] ? 0 : 2) : (t[1] < t[2] ? 1 : 2);
  return {t[k], t[(k + 1) % 3], t[(k + 2) % 3]};
}

}  // namespace

const char* format_id(OutputFormat f) {
  switch (f) {
    case OutputFormat::Json: return "json";
    case OutputFormat::Obj: return "obj";
    case OutputFormat::Ply: return "ply";
    case OutputFormat::GeoJson: return "geojson";
    case OutputFormat::Glb: return "glb";
  }
  return "";
}

std::optional<OutputFormat> output_format_of(std::string_view path) {
  const size_t slash = path.find_last_of("/\\");
  const size_t dot = path.rfind('.');
  if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) return std::nullopt;
  std::string ext(path.substr(dot + 1));
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (OutputFormat f : kFormats)
    if (ext == format_id(f)) return f;
  return std::nullopt;
}

std::string output_extensions() {
  std::string s;
  for (size_t k = 0; k < kFormats.size(); ++k)
    s += std::string(k == 0 ? "." : k + 1 == kFormats.size() ? " or ." : ", .") + format_id(kFormats[k]);
  return s;
}

std::vector<uint8_t> non_delaunay_triangles(const std::vector<uint32_t>& triangles, const std::vector<uint32_t>& delaunay) {
  std::vector<std::array<uint32_t, 3>> known;
  known.reserve(delaunay.size() / 3);
  for (size_t t = 0; t + 2 < delaunay.size(); t += 3) known.push_back(canonical(&delaunay[t]));
  std::sort(known.begin(), known.end());
  std::vector<uint8_t> out(triangles.size() / 3);
  for (size_t t = 0; t < out.size(); ++t)
    out[t] = !std::binary_search(known.begin(), known.end(), canonical(&triangles[3 * t]));
  return out;
}

TinData tin_data(const Terrain& terrain, const std::vector<double>& input_xyz, const Mesh& mesh, std::string comment,
                 std::string crs) {
  TinData d;
  d.points = input_xyz;
  d.triangles = terrain.to_input(mesh.triangles);
  d.non_delaunay = non_delaunay_triangles(mesh.triangles, terrain.delaunay_mesh().triangles);
  const Measures m = measure(mesh);
  const size_t n = input_xyz.size() / 3;
  d.vertex_class.assign(n, 255);  // VertexClass.Dropped of the JS API: not a vertex
  d.extremum.assign(n, kNotExtremum);
  for (uint32_t v = 0; v < mesh.num_vertices(); ++v) {
    d.vertex_class[terrain.to_input(v)] = m.vertex_class[v];
    d.extremum[terrain.to_input(v)] = m.extremum[v];
  }
  if (has_domain(mesh))
    for (uint8_t in : m.inside) d.outside.push_back(!in);
  d.comment = std::move(comment);
  d.crs = std::move(crs);
  return d;
}

}  // namespace hodt
