// The CRS kept from the input: an EPSG code when the definition names one, the
// definition itself otherwise, from --crs or FILE's .prj, into every output.
#include <doctest/doctest.h>

#include <map>

#include "hodt/cli.hpp"
#include "hodt/tin_output.hpp"
#include "terrain/crs.hpp"

using namespace hodt;

namespace {
const char* kUtm17 =
    "PROJCS[\"WGS 84 / UTM zone 17N\",GEOGCS[\"WGS 84\",DATUM[\"WGS_1984\",SPHEROID[\"WGS 84\",6378137,298.257223563,"
    "AUTHORITY[\"EPSG\",\"7030\"]],AUTHORITY[\"EPSG\",\"6326\"]],PRIMEM[\"Greenwich\",0],UNIT[\"degree\",0.0174532925199433],"
    "AUTHORITY[\"EPSG\",\"4326\"]],PROJECTION[\"Transverse_Mercator\"],PARAMETER[\"central_meridian\",-81],"
    "UNIT[\"metre\",1,AUTHORITY[\"EPSG\",\"9001\"]],AUTHORITY[\"EPSG\",\"32617\"]]";
const char* kEsri =
    "PROJCS[\"WGS_1984_UTM_Zone_17N\",GEOGCS[\"GCS_WGS_1984\",DATUM[\"D_WGS_1984\",\n  SPHEROID[\"WGS_1984\",6378137.0,"
    "298.257223563]]],PROJECTION[\"Transverse_Mercator\"],UNIT[\"Meter\",1.0]]\r\n";
}  // namespace

TEST_CASE("crs_of_wkt: the outermost EPSG code, else the definition on one line") {
  CHECK(crs_of_wkt(kUtm17) == "EPSG:32617");  // not the datum's or the unit's code
  CHECK(crs_of_wkt(std::string("\xEF\xBB\xBF") + kUtm17) == "EPSG:32617");  // (a byte order mark is skipped)
  CHECK(crs_of_wkt("PROJCRS[\"ETRS89 / UTM 32N\",BASEGEOGCRS[\"ETRS89\",ID[\"EPSG\",4258]],ID[\"EPSG\",25832]]") ==
        "EPSG:25832");
  CHECK(crs_of_wkt("GEOGCRS[\"x\",ID[\"EPSG\",4326,CITATION[\"c\"]]]") == "EPSG:4326");
  const auto esri = crs_of_wkt(kEsri);
  REQUIRE(esri);
  CHECK(esri->find('\n') == std::string::npos);
  CHECK(esri->rfind("PROJCS[\"WGS_1984_UTM_Zone_17N\"", 0) == 0);
  CHECK(esri->back() == ']');
  for (const char* bad : {"", "garbage", "PROJCS[\"a\"", "PROJCS[\"a\"]]", "[1]", "PROJCS[\"unclosed]", "foo[1]", "LOCAL[\"a\"]"})
    CHECK_MESSAGE(!crs_of_wkt(bad), bad);
  // Bytes that would break a JSON or PLY header are replaced.
  CHECK(crs_of_wkt("LOCAL_CS[\"caf\xC3\xA9\"]") == "LOCAL_CS[\"caf??\"]");
}

TEST_CASE("crs_of_text and prj_path") {
  CHECK(crs_of_text(" epsg:2056 ") == "EPSG:2056");
  CHECK(crs_of_text(kUtm17) == "EPSG:32617");
  CHECK(crs_of_text("+proj=utm +zone=17") == "+proj=utm +zone=17");
  CHECK(!crs_of_text("  "));
  CHECK(!crs_of_text(std::string(kMaxCrsChars + 1, 'a')));
  CHECK(prj_path("dem.asc") == "dem.prj");
  CHECK(prj_path("data/v1.2/dem") == "data/v1.2/dem.prj");
  CHECK(prj_path("a.b/.hidden") == "a.b/.hidden.prj");
  CHECK(prj_path("points.xyz.txt") == "points.xyz.prj");
}

TEST_CASE("the CLI keeps the CRS of --crs or the .prj sidecar in its JSON and meshes") {
  std::map<std::string, std::string> files = {{"dem.asc", "ncols 3\nnrows 3\nxllcorner 500000\nyllcorner 4100000\n"
                                                          "cellsize 10\n1 2 3\n4 9 6\n7 8 9\n"},
                                              {"dem.prj", kUtm17}};
  std::map<std::string, TinData> meshes;
  CliHost host;
  host.read = [&](const std::string& path, std::string& error) -> std::optional<std::string> {
    const auto it = files.find(path);
    if (it == files.end()) return error = "ENOENT", std::nullopt;
    return it->second;
  };
  host.write = [&](const std::string& path, std::string_view bytes, std::string&) {
    files[path] = std::string(bytes);
    return true;
  };
  host.write_mesh = [&](const std::string& path, OutputFormat, const TinData& tin, std::string&) {
    meshes[path] = tin;
    return true;
  };
  CliResult r = run_cli({"solve", "dem.asc", "--objective", "min-local-minima", "--output", "t.json", "--output", "t.ply"}, host);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find(", \"crs\": \"EPSG:32617\"}") != std::string::npos);
  CHECK(files["t.json"].find("\"crs\": \"EPSG:32617\"") != std::string::npos);
  CHECK(meshes["t.ply"].crs == "EPSG:32617");
  CHECK(r.err == "hodt: dem.asc: coordinates in EPSG:32617 of dem.prj, kept as read\n");

  // --crs wins over the sidecar; --quiet says nothing.
  r = run_cli({"stats", "dem.asc", "--crs", "EPSG:2056", "--quiet", "--output", "t.obj"}, host);
  CHECK(r.out.find(", \"crs\": \"EPSG:2056\"}") != std::string::npos);
  CHECK(meshes["t.obj"].crs == "EPSG:2056");
  CHECK(r.err.empty());

  // A sidecar that is not WKT is named and ignored; without one nothing changes.
  files["dem.prj"] = "not a projection";
  r = run_cli({"stats", "dem.asc"}, host);
  CHECK(r.out.find("\"crs\"") == std::string::npos);
  CHECK(r.err == "hodt: warning: dem.prj: not a WKT coordinate system (ignored)\n");
  files.erase("dem.prj");
  r = run_cli({"stats", "dem.asc"}, host);
  CHECK(r.exit_code == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find("\"crs\"") == std::string::npos);
  r = run_cli({"stats", "dem.asc", "--crs", ""}, host);
  CHECK(r.exit_code == 2);
  CHECK(r.err == "hodt: --crs expects an EPSG code (EPSG:32633), a WKT definition or a PROJ string (+proj=...), got ''\n");
  // What is not a CRS is refused in one line, not written into the outputs.
  r = run_cli({"stats", "dem.asc", "--crs", "foo"}, host);
  CHECK(r.exit_code == 2);
  CHECK(r.out.empty());
  CHECK(r.err == "hodt: --crs expects an EPSG code (EPSG:32633), a WKT definition or a PROJ string (+proj=...), got 'foo'\n");
  r = run_cli({"stats", "dem.asc", "--crs", "EPSG:32633\nrm -rf"}, host);
  CHECK(r.err == "hodt: --crs expects an EPSG code (EPSG:32633), a WKT definition or a PROJ string (+proj=...), got "
                 "'EPSG:32633\\nrm -rf'\n");
  r = run_cli({"stats", "dem.asc", "--crs", std::string(kMaxCrsChars + 1, 'a')}, host);
  CHECK(r.err == "hodt: --crs is 16385 characters long, expected at most 16384\n");
  r = run_cli({"stats", "dem.asc", "--crs", "urn:ogc:def:crs:EPSG::25832"}, host);
  CHECK(r.out.find(", \"crs\": \"EPSG:25832\"}") != std::string::npos);
}

TEST_CASE("--crs: EPSG codes in their usual spellings, WKT and PROJ strings; nothing else") {
  for (const char* epsg : {"EPSG:32633", "epsg:32633", " Epsg:32633 ", "EPSG::32633", "urn:ogc:def:crs:EPSG::32633",
                           "urn:ogc:def:crs:EPSG:9.8.15:32633", "URN:OGC:DEF:CRS:EPSG::32633",
                           "http://www.opengis.net/def/crs/EPSG/0/32633", "https://www.opengis.net/def/crs/EPSG/0/32633", "32633",
                           "EPSG:032633"}) {
    CAPTURE(epsg);
    CHECK(crs_of_text(epsg) == "EPSG:32633");
  }
  CHECK(crs_of_text("+proj=utm +zone=33  +datum=WGS84 +units=m +no_defs") == "+proj=utm +zone=33 +datum=WGS84 +units=m +no_defs");
  CHECK(crs_of_text("GEOGCRS[\"WGS 84\",ID[\"EPSG\",4326]]") == "EPSG:4326");
  for (const char* bad : {"foo", "EPSG", "EPSG:", "EPSG:abc", "EPSG:0", "EPSG:1234567890", "ESPG:4326", "EPSG:4326 x", "4326m",
                          "foo[1]", "WGS84", "+proj", "+proj=", "+zone=33", "+proj=utm zone=33", "+proj=utm +zone=33\n+x",
                          "+proj=utm +z\x01=1", "urn:ogc:def:crs:EPSG::", "http://example.com/EPSG/0/4326", "EPSG:32633\nfoo"}) {
    CAPTURE(bad);
    CHECK(!crs_of_text(bad));
  }
}
