// Reading point files: CSV / TSV / whitespace "x y z" (optional header), JSON
// [[x, y, z], ...] and ESRI ASCII grids (.asc, NODATA cells skipped).
#pragma once
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hodt {

enum class PointFormat { Auto, Text, Json, AsciiGrid };

struct ParsedPoints {
  std::vector<double> xyz;  // x, y, z per point
  std::vector<int> lines;   // 1-based source line of each point, for messages
  // Rasters (ASCII grids) with NODATA cells: how many, and the default domain
  // that leaves the triangles across them unmeasured (domain.hpp); infinity
  // (no domain) for other input.
  uint64_t nodata_cells = 0;
  double max_edge = INFINITY;
};

// Throws InputError "<name>: line L: <what is wrong>". Auto picks the format from
// the content: '[' starts JSON, an "ncols" header an ASCII grid, anything else text.
// The text may start with a UTF-8 byte order mark or be UTF-16 (with its mark);
// lines end with LF, CR LF or CR; numbers are read correctly rounded, whatever
// their length, with an optional '+' and exponent.
ParsedPoints read_points(std::string_view text, const std::string& name,
                         PointFormat format = PointFormat::Auto);

}  // namespace hodt
