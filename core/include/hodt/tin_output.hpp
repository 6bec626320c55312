// What `--output FILE` writes: the format named by the file's extension, and the
// triangulation in the caller's terms (all input points as read, input indices)
// with the per-vertex and per-triangle attributes the mesh formats carry.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hodt/mesh.hpp"
#include "hodt/terrain.hpp"

namespace hodt {

enum class OutputFormat : uint8_t { Json, Obj, Ply, GeoJson, Glb };

// By extension, case-insensitive: .json, .obj, .ply, .geojson, .glb.
std::optional<OutputFormat> output_format_of(std::string_view path);
// "json", "obj", "ply", "geojson", "glb": the extension without the dot, and the
// format name of hodt/export.
const char* format_id(OutputFormat f);
// ".json, .obj, .ply, .geojson or .glb", for messages.
std::string output_extensions();

// A triangulation of a terrain as the mesh writers take it (hodt/export's MeshData).
struct TinData {
  std::vector<double> points;          // x, y, z per input point, as read
  std::vector<uint32_t> triangles;     // three input indices per triangle, counterclockwise
  std::vector<uint8_t> vertex_class;   // per input point: VertexClass, 255 for a dropped duplicate
  std::vector<uint8_t> extremum;       // per input point: Extremum
  std::vector<uint8_t> non_delaunay;   // per triangle: 1 if not a triangle of the Delaunay triangulation
  std::vector<uint8_t> outside;        // per triangle: 1 if outside the domain (empty: no domain)
  std::string comment;                 // one line: what this triangulation is
  std::string crs;                     // the input's CRS (crs.hpp), empty if unknown
};

// mesh: a triangulation of the terrain's vertices (kept indices), e.g. a solution's.
// input_xyz: every input point as read (dropped duplicates included).
TinData tin_data(const Terrain& terrain, const std::vector<double>& input_xyz, const Mesh& mesh, std::string comment,
                 std::string crs = "");

// Per triangle of `triangles`: 1 if it is not a triangle of `delaunay` (both three
// vertex indices per counterclockwise triangle, any rotation and order).
std::vector<uint8_t> non_delaunay_triangles(const std::vector<uint32_t>& triangles, const std::vector<uint32_t>& delaunay);

}  // namespace hodt
