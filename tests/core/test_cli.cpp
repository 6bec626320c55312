// The CLI contract through a fake front end: files in memory, progress recorded.
#include <doctest/doctest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "hodt/cli.hpp"
#include "hodt/terrain.hpp"
#include "hodt/tin_output.hpp"
#include "cli/cli_help.hpp"
#include "generators.hpp"
#include "io/file_errors.hpp"

using namespace hodt;
using hodt::test::uniform_points;

namespace {

// A front end whose files live in a map; mesh files record the TinData they got.
struct FakeHost {
  std::map<std::string, std::string> files;
  std::map<std::string, std::pair<OutputFormat, TinData>> meshes;
  std::string progress;
  bool terminal = false;
  bool notes = false;  // notes shown at once, into progress (marked), as the CLIs do

  CliHost host(bool with_mesh_writer = true) {
    CliHost h;
    h.read = [this](const std::string& path, std::string& error) -> std::optional<std::string> {
      const auto it = files.find(path);
      if (it == files.end()) {
        error = "ENOENT";
        return std::nullopt;
      }
      return it->second;
    };
    h.write = [this](const std::string& path, std::string_view bytes, std::string& error) {
      if (path.rfind("/readonly/", 0) == 0) return error = "EACCES", false;
      files[path] = std::string(bytes);
      return true;
    };
    if (with_mesh_writer)
      h.write_mesh = [this](const std::string& path, OutputFormat f, const TinData& tin, std::string&) {
        meshes.insert_or_assign(path, std::make_pair(f, tin));
        return true;
      };
    h.show_progress = [this](const std::string& text) { progress += text; };
    if (notes) h.show_notes = [this](const std::string& text) { progress += "[notes]" + text; };
    h.stderr_is_terminal = terminal;
    return h;
  }
};

// Five points: a square with a high point off the centre, and a duplicate.
const std::string kPoints = "x y z\n0 0 0\n4 0 1\n4 4 0\n0 4 1\n1.5 2.5 9\n4 0 7\n";

}  // namespace

TEST_CASE("output formats by extension") {
  CHECK(output_format_of("a/b/tin.JSON") == OutputFormat::Json);
  CHECK(output_format_of("tin.obj") == OutputFormat::Obj);
  CHECK(output_format_of("tin.Ply") == OutputFormat::Ply);
  CHECK(output_format_of("tin.geojson") == OutputFormat::GeoJson);
  CHECK(output_format_of("tin.glb") == OutputFormat::Glb);
  CHECK(!output_format_of("tin.gltf"));
  CHECK(!output_format_of("tin"));
  CHECK(!output_format_of("dir.obj/tin"));
  CHECK(output_extensions() == ".json, .obj, .ply, .geojson or .glb");
}

TEST_CASE("non-Delaunay triangles: by their corners, any rotation") {
  const std::vector<uint32_t> delaunay = {0, 1, 2, 0, 2, 3};
  CHECK(non_delaunay_triangles({1, 2, 0, 3, 0, 2}, delaunay) == std::vector<uint8_t>{0, 0});
  CHECK(non_delaunay_triangles({0, 1, 3, 1, 2, 3}, delaunay) == std::vector<uint8_t>{1, 1});
}

TEST_CASE("--output writes .json itself and hands the mesh formats to the front end") {
  FakeHost fake;
  fake.files["p.txt"] = kPoints;
  const CliResult r = run_cli({"solve", "p.txt", "--objective", "min-local-minima", "--dedupe", "first", "--output",
                               "out.json", "--output", "out.PLY", "--output", "out.glb"},
                              fake.host());
  REQUIRE(r.exit_code == 0);
  CHECK(r.err == "hodt: warning: p.txt: dropped 1 point at the same (x, y) as an earlier one (--dedupe first)\n");
  const std::string& json = fake.files["out.json"];
  CHECK(json.rfind("{\"objective\": \"min-local-minima\"", 0) == 0);
  CHECK(json.find("\"times\": {\"readMs\": ") != std::string::npos);
  CHECK(json.find(", \"triangles\": [[") != std::string::npos);
  CHECK(r.out.find("\"triangles\"") == std::string::npos);  // printed without, as before
  REQUIRE(fake.meshes.size() == 2);
  const auto& [format, tin] = fake.meshes.at("out.PLY");
  CHECK(format == OutputFormat::Ply);
  CHECK(fake.meshes.at("out.glb").first == OutputFormat::Glb);
  // Every input point as read, the duplicate too, which is no vertex (class 255).
  CHECK(tin.points == std::vector<double>{0, 0, 0, 4, 0, 1, 4, 4, 0, 0, 4, 1, 1.5, 2.5, 9, 4, 0, 7});
  CHECK(tin.triangles.size() == 3 * 4);
  CHECK(tin.vertex_class.size() == 6);
  CHECK(tin.vertex_class[5] == 255);
  CHECK(tin.vertex_class[0] == 4);  // a hull vertex: boundary
  CHECK(tin.extremum[4] == 2);      // the high point in the middle is a peak
  CHECK(tin.non_delaunay.size() == 4);
  CHECK(tin.comment.rfind(std::string("hodt ") + version() + ": min-local-minima = ", 0) == 0);
}

TEST_CASE("stats --output writes the Delaunay triangulation") {
  FakeHost fake;
  fake.files["p.txt"] = kPoints;
  const CliResult r = run_cli({"stats", "p.txt", "--dedupe", "first", "--quiet", "--output", "d.json", "--output", "d.obj"},
                              fake.host());
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.empty());  // --quiet: no warning
  CHECK(fake.files["d.json"].find("\"triangles\": 4, ") != std::string::npos);
  CHECK(fake.files["d.json"].find("\"delaunayTriangles\": [[") != std::string::npos);
  const TinData& tin = fake.meshes.at("d.obj").second;
  CHECK(tin.non_delaunay == std::vector<uint8_t>(4, 0));
  CHECK(tin.comment == std::string("hodt ") + version() + ": the Delaunay triangulation of p.txt");
}

TEST_CASE("--output refusals and failures: one line each") {
  FakeHost fake;
  fake.files["p.txt"] = kPoints;
  auto err = [&](std::vector<std::string> args, bool mesh_writer = true) {
    const CliResult r = run_cli(args, fake.host(mesh_writer));
    CHECK(r.exit_code == 2);
    CHECK(r.out.empty());
    return r.err;
  };
  CHECK(err({"stats", "p.txt", "--output", "t.stl"}) ==
        "hodt: --output 't.stl': unknown format; name the file .json, .obj, .ply, .geojson or .glb\n");
  CHECK(err({"stats", "p.txt", "--output", "t.obj"}, false) ==
        "hodt: --output 't.obj': this build of hodt writes .json only; for .obj use the npm CLI: npx hodt\n");
  CHECK(err({"stats", "p.txt", "--dedupe", "first", "--output", "/readonly/t.json"}) ==
        "hodt: cannot write /readonly/t.json: permission denied\n");
  CHECK(err({"stats", "missing.txt"}) == "hodt: missing.txt: no such file\n");
  CHECK(err({"stats", "p.txt", "--quiet", "--progress"}) == "hodt: --quiet and --progress exclude each other\n");
  // run_cli(args, read): no writer at all.
  const CliResult r = run_cli({"stats", "p.txt", "--output", "t.json"}, fake.host().read);
  CHECK(r.err == "hodt: --output 't.json': this front end writes no files\n");
}

TEST_CASE("file errors in the same words for every front end") {
  CHECK(file_error_message("ENOENT", FileAccess::Read) == "no such file");
  CHECK(file_error_message("ENOENT", FileAccess::Write) == "no such directory");
  CHECK(file_error_message("EISDIR", FileAccess::Write) == "is a directory");
  CHECK(file_error_message("EBUSY", FileAccess::Read) == "cannot read the file (EBUSY)");
  CHECK(file_error_message("errno 5", FileAccess::Write) == "cannot write the file (errno 5)");
  CHECK(file_error_message("", FileAccess::Read) == "cannot read the file");
  CHECK(file_error_message("the server said no", FileAccess::Read) == "the server said no");
}

TEST_CASE("progress: steps with --progress; nothing on a terminal for a short run; the line cleared") {
  FakeHost fake;
  fake.files["p.txt"] = kPoints;
  const std::vector<std::string> args = {"solve", "p.txt", "--objective", "max-convex-edges", "--dedupe", "first"};
  run_cli(args, fake.host());
  CHECK(fake.progress.empty());  // not a terminal, not asked for
  std::vector<std::string> forced = args;
  forced.push_back("--progress");
  run_cli(forced, fake.host());
  // (A run this short shows no phase of the solve's own as a plain line: they come
  // at least 0.2 s apart.)
  CHECK(fake.progress == "hodt: reading p.txt\nhodt: triangulating 6 points\nhodt: solving (max-convex-edges)\n");
  fake.progress.clear();
  fake.terminal = true;
  run_cli(args, fake.host());
  CHECK(fake.progress.empty());  // under a second
  run_cli(forced, fake.host());
  // (On a terminal each new phase is drawn at once.)
  CHECK(fake.progress ==
        "\r\x1b[Khodt: reading p.txt\r\x1b[Khodt: triangulating 6 points\r\x1b[Khodt: solving (max-convex-edges)"
        "\r\x1b[Khodt: solving exactly (max-convex-edges)\r\x1b[Khodt: measuring (max-convex-edges)\r\x1b[K");
}

TEST_CASE("progress: a real solve's phases by name, each one's percentage never going back") {
  // Brute force over 2^16 triangulations: long enough for a few redraws
  // on a terminal (every 0.1 s), a phase that knows its size (so percentages).
  const std::vector<double> p = uniform_points(36, 4);
  std::ostringstream text;
  text.precision(17);
  for (size_t i = 0; i < p.size(); i += 3) text << p[i] << " " << p[i + 1] << " " << p[i + 2] << "\n";
  FakeHost fake;
  fake.files["u.txt"] = text.str();
  REQUIRE(Terrain::from_points(p).structure().num_quads() == 16);
  fake.terminal = true;
  const CliResult r =
      run_cli({"solve", "u.txt", "--objective", "min-mixed-vertices", "--method", "brute-force", "--progress"}, fake.host());
  REQUIRE(r.exit_code == 0);
  std::vector<std::string> lines;  // the lines drawn in place, each after "\r\x1b[K"
  for (size_t at = 0; (at = fake.progress.find("\r\x1b[K", at)) != std::string::npos;) {
    at += 4;
    lines.push_back(fake.progress.substr(at, fake.progress.find('\r', at) - at));
  }
  CAPTURE(fake.progress);
  const std::string solving = "hodt: solving exactly (min-mixed-vertices): ";
  int last = -1, shown = 0;
  for (const std::string& line : lines) {
    if (line.rfind(solving, 0) != 0) continue;
    const int percent = std::stoi(line.substr(solving.size()));
    CHECK(percent >= last);
    CHECK(percent <= 100);
    last = percent, ++shown;
  }
  CHECK(shown >= 2);
  CHECK(lines.front() == "hodt: reading u.txt");
  CHECK(lines.at(2) == "hodt: solving (min-mixed-vertices)");
  CHECK(lines.back().empty());  // cleared at the end
}

TEST_CASE("--version and --help") {
  FakeHost fake;
  const CliResult v = run_cli({"--version"}, fake.host());
  CHECK(v.exit_code == 0);
  CHECK(v.out == std::string("hodt ") + version() + "\n");
  const CliResult h = run_cli({"--help"}, fake.host());
  CHECK(h.exit_code == 0);
  for (const auto& o : objectives())
    CHECK(h.out.find("  " + std::string(o.id) + " [" + o.unit + "]\n      " + o.summary + "\n") !=
          std::string::npos);
  CHECK(std::string(info(Objective::MinmaxEdgeNormalAngle).unit).rfind("radians", 0) == 0);
  CHECK(std::string(info(Objective::MinmaxTriangleArea).unit) == "squared plane units");
}

namespace {
std::string fixture_text(const std::string& name) {
  std::ifstream in(std::string(HODT_FIXTURES) + "/" + name, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST_CASE("text that is not what it seems: the CLI reads decimal commas, refuses the rest in one line") {
  FakeHost f;
  f.files["eu.csv"] = fixture_text("semicolon-decimal-comma.csv");
  f.files["point.txt"] = "0 0 1.5\n10.25 0 2.25\n10.25 9.5 0.75\n0 9.5 3\n4.5 4.75 8.125\n";
  const CliResult eu = run_cli({"solve", "eu.csv", "--objective", "min-total-edge-length"}, f.host());
  const CliResult point = run_cli({"solve", "point.txt", "--objective", "min-total-edge-length"}, f.host());
  REQUIRE(eu.exit_code == 0);
  CHECK(eu.out.substr(0, eu.out.find("\"timeMs\"")) == point.out.substr(0, point.out.find("\"timeMs\"")));
  CHECK(eu.err.empty());

  const std::pair<const char*, const char*> refused[] = {
      {"bad-mixed-delimiters.csv", "line 2: expected 3 numbers x y z separated by ';' as on line 1, got 1 field '4,5,6'"},
      {"bad-mixed-decimal-marks.csv", "line 2: x is '2.5' with a decimal point, but line 1 has decimal commas: one decimal mark per file"},
      {"bad-id-column-no-header.csv", "line 1: 4 columns (',') and no header naming x, y and z; add a first line naming the columns, "
                                      "such as 'id,x,y,z' (or easting, northing, elevation)"},
      {"bad-json-key-newlines.json", "line 1: point 0: unexpected key 'y\\n\\n\\n', expected x, y, z"},
      {"bad-control-characters.csv", "line 2: y is '\\x1b[31m\\x07\\x00', not a number"},
  };
  for (const auto& entry : refused) {
    const std::string name = entry.first, what = entry.second;  // (CAPTURE cannot take a structured binding in clang 14)
    f.files[name] = fixture_text(name);
    const CliResult r = run_cli({"stats", name}, f.host());
    CAPTURE(name);
    CHECK(r.exit_code == 2);
    CHECK(r.out.empty());
    CHECK(r.err == "hodt: " + name + ": " + what + "\n");
  }
  // A file name that holds a line break is named on one line too.
  f.files["two\nlines.csv"] = "0 0 0\n1 x 1\n";
  CHECK(run_cli({"stats", "two\nlines.csv"}, f.host()).err == "hodt: two\\nlines.csv: line 2: y is 'x', not a number\n");
  CHECK(run_cli({"stats", "eu.csv", "--dedupe", "a\nb"}, f.host()).err == "hodt: --dedupe expects 'first' or 'error', got 'a\\nb'\n");
  // A front end's reader (the npm CLI's GeoTIFF and LAS loaders) may quote the file in its reason.
  CliHost loader = f.host();
  loader.read = [](const std::string&, std::string& error) -> std::optional<std::string> {
    error = "LAS: system identifier 'a\r\nb\x1b'";
    return std::nullopt;
  };
  CHECK(run_cli({"stats", "x.las"}, loader).err == "hodt: x.las: LAS: system identifier 'a\\r\\nb\\x1b'\n");
}

TEST_CASE("a domain that leaves every triangle outside: a warning with the count and the spacing") {
  FakeHost fake;
  fake.files["p.txt"] = "0 0 0\n10 0 1\n10 10 0\n0 10 1\n4 6 9\n";
  const CliResult r = run_cli({"solve", "p.txt", "--objective", "min-local-minima", "--max-edge", "2"}, fake.host());
  CHECK(r.exit_code == 0);
  CHECK(r.err.find("hodt: warning: p.txt: the domain (maxEdge 2) leaves 0 of 4 triangles inside to be measured") !=
        std::string::npos);
  CHECK(r.err.find("median Delaunay edge length") != std::string::npos);
  const CliResult fine = run_cli({"solve", "p.txt", "--objective", "min-local-minima", "--max-edge", "20"}, fake.host());
  CHECK(fine.err.find("warning") == std::string::npos);
  const CliResult quiet = run_cli({"solve", "p.txt", "--objective", "min-local-minima", "--max-edge", "2", "--quiet"}, fake.host());
  CHECK(quiet.err.empty());
}

TEST_CASE("the input's notes: shown once it is accepted, before the solve; never for a refused input") {
  FakeHost fake;
  fake.notes = true;
  fake.files["p.txt"] = kPoints;  // a duplicate (x, y): refused without --dedupe
  fake.files["p.prj"] = "GEOGCS[\"WGS 84\",AUTHORITY[\"EPSG\",\"4326\"]]";
  const std::vector<std::string> args = {"solve", "p.txt", "--objective", "min-local-minima", "--progress"};
  const CliResult refused = run_cli(args, fake.host());
  CHECK(refused.exit_code == 2);
  CHECK(fake.progress.find("[notes]") == std::string::npos);
  CHECK(refused.err.find("EPSG:4326") == std::string::npos);  // (the .prj's note: the input was refused)
  fake.progress.clear();
  std::vector<std::string> deduped = args;
  deduped.insert(deduped.end(), {"--dedupe", "first"});
  const CliResult r = run_cli(deduped, fake.host());
  CHECK(r.exit_code == 0);
  const size_t notes = fake.progress.find("[notes]"), solving = fake.progress.find("hodt: solving");
  REQUIRE(notes != std::string::npos);
  CHECK(notes < solving);
  CHECK(fake.progress.find("dropped 1 point", notes) < solving);
  CHECK(fake.progress.find("EPSG:4326", notes) < solving);
  CHECK(r.err.empty());  // (all shown already)
}
