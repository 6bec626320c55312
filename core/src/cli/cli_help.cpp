#include "cli/cli_help.hpp"

#ifndef HODT_VERSION
#error "HODT_VERSION (package.json's version) is defined by CMakeLists.txt"
#endif

namespace hodt {

const char* version() { return HODT_VERSION; }

std::string cli_help() {
  std::string s =
      "usage: hodt stats FILE [--order K] [--dedupe first] [--nodata V] [--classes C]\n"
      "                  [--max-edge L|none] [--crs CRS] [--output OUT]...\n"
      "                  [--drainage NET.geojson]\n"
      "       hodt solve FILE --objective ID [--method brute-force|exact|approx|auto]\n"
      "                  [--epsilon E] [--order K] [--triangles] [--trace] [--dedupe first]\n"
      "                  [--nodata V] [--classes C] [--max-edge L|none] [--crs CRS]\n"
      "                  [--output OUT]... [--drainage NET.geojson]\n"
      "                  [--quiet | --progress]\n"
      "       hodt --help | --version\n"
      "\n"
      "FILE: CSV/TSV/whitespace 'x y z' lines (optional header), JSON [[x,y,z],...],\n"
      "      or an ESRI ASCII grid (.asc); UTF-8 (with or without a byte order mark)\n"
      "      or UTF-16, any line endings; '-' reads standard input. Fields are split\n"
      "      at ';' (numbers may then have decimal commas: 1,5;2,25;3), else at ',',\n"
      "      else at blanks; more than 3 columns need a header naming x, y and z\n"
      "      (id,x,y,z; easting, northing, elevation also do). The npm CLI\n"
      "      (npx hodt) also reads GeoTIFF DEMs (a point per cell with data, at its\n"
      "      centre) and LAS/LAZ point clouds.\n"
      "\n"
      "Options:\n"
      "  --objective ID    what to optimise (below)\n"
      "  --method M        auto (default): exact when it fits, else approx\n"
      "  --epsilon E       approximation schemes, 0 < E < 1: within a factor (1 - E)\n"
      "                    (min-mixed-vertices: of the most vertices that are not mixed)\n"
      "  --order K         k-th order Delaunay triangulations, K from 1 to 16 (default 1)\n"
      "  --triangles       add the triangles (input point indices) to the printed JSON\n"
      "  --trace           min-max objectives: add the thresholds the search tested;\n"
      "                    order K >= 2: the phases that ran, each with its time\n"
      "  --dedupe first    keep the first of points with the same (x, y) (default: error;\n"
      "                    LAS/LAZ: first)\n"
      "  --nodata V        drop points whose z is V (text formats; grids and GeoTIFF\n"
      "                    name their own NODATA)\n"
      "  --classes C       LAS/LAZ: ground (class 2, the default) or all\n"
      "  --max-edge L      the domain: a triangle with an edge longer than L (plane\n"
      "                    units) is outside and not measured; the triangulations are\n"
      "                    the same. Rasters with NODATA cells (.asc, GeoTIFF) default to\n"
      "                    3 cells (a bridge over a gap of up to two cells stays inside);\n"
      "                    'none' measures every triangle\n"
      "  --crs CRS         the coordinate system of x and y (EPSG:N, an OGC URN or URL\n"
      "                    naming an EPSG code, WKT, or a PROJ string), written to\n"
      "                    the outputs that have a place for it; default: FILE's .prj\n"
      "                    sidecar (dem.asc: dem.prj), GeoTIFF keys, LAS VLRs.\n"
      "                    Coordinates are never reprojected\n"
      "  --output OUT      also write the triangulation to OUT; repeatable. By extension:\n"
      "                    .json (the printed JSON plus the triangles), .obj, .ply (binary,\n"
      "                    vertex class and extremum, non-Delaunay triangles), .geojson\n"
      "                    (one polygon per triangle), .glb (binary glTF); the native\n"
      "                    build writes .json only (the others: npx hodt)\n"
      "  --drainage NET.geojson\n"
      "                    write the drainage network of the triangulation (stats: the\n"
      "                    Delaunay one; solve: the result): each point drains along its\n"
      "                    steepest strictly descending edge, decided exactly. A\n"
      "                    LineString per edge (from, to: point indices; accumulation:\n"
      "                    points draining through from), a Point per pit (interior,\n"
      "                    drains nowhere) and per outlet (on the hull or the domain's\n"
      "                    edge) with its basinSize. The printed JSON always counts them:\n"
      "                    \"drainage\": {\"pits\", \"outlets\"}\n"
      "  --quiet           nothing on stderr but errors (no progress, no warnings)\n"
      "  --progress        show progress on stderr even when it is not a terminal\n"
      "\n"
      "Objectives (--objective ID), each with the unit of its value:\n";
  for (const auto& o : objectives())
    s += "  " + std::string(o.id) + " [" + o.unit + "]\n      " + o.summary + "\n";
  s +=
      "\n"
      "Prints JSON on stdout. Exit codes: 0 ok, 2 bad input or usage, 3 refused (a limit).\n"
      "Plane units are those of x and y; angles are in radians.\n";
  return s;
}

}  // namespace hodt
