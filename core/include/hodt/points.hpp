// Input validation of a terrain's points, exactly as DEFINITIONS.md says.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace hodt {

enum class Dedupe { Error, KeepFirst };
// Input: kept points in input order. Spatial: along spatial_order() (what the
// triangulation wants; input_index maps back).
enum class PointOrder { Input, Spatial };

// The points the triangulation uses: validated, duplicates removed if asked.
struct TerrainPoints {
  std::vector<double> xyz;            // x, y, z per kept point
  std::vector<uint32_t> input_index;  // input index of each kept point
};

// How to name point i in messages: "point 7" or, for a file, "point 7 (line 9)".
struct PointLabels {
  std::vector<int> lines;  // source line of each input point, or empty
  std::string describe(size_t i) const;
};

// Throws InputError for: a coordinate count not divisible by 3, NaN or infinite
// coordinates (naming index and coordinate), duplicate (x, y) (naming both indices,
// unless dedupe == KeepFirst), fewer than 3 points, all points collinear.
TerrainPoints validate_points(std::vector<double> xyz, Dedupe dedupe = Dedupe::Error,
                              const PointLabels& labels = {}, PointOrder order = PointOrder::Input);

}  // namespace hodt
