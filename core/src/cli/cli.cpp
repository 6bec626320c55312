#include "hodt/cli.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "hodt/domain.hpp"
#include "hodt/drainage.hpp"
#include "hodt/error.hpp"
#include "hodt/format.hpp"
#include "hodt/read_points.hpp"
#include "hodt/report.hpp"
#include "hodt/solve.hpp"
#include "hodt/solve_options.hpp"
#include "hodt/terrain.hpp"
#include "cli/cli_help.hpp"
#include "cli/cli_progress.hpp"
#include "higher_order/k_order.hpp"
#include "io/drainage_geojson.hpp"
#include "io/file_errors.hpp"
#include "io/quote_input.hpp"
#include "terrain/crs.hpp"

namespace hodt {
namespace {

struct Usage : InputError {
  using InputError::InputError;
};

// An argument in a message, whole, escaped onto one line.
std::string quoted(std::string_view arg) { return quote_input(arg, arg.size()); }

// Any number strtod reads (NaN and infinities too: the option's own check then
// names them, as it does for every front end).
double parse_number(const std::string& flag, const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size())
    throw Usage(flag + " expects a number, got " + quoted(text));
  return v;
}

struct Output {
  std::string path;
  OutputFormat format;
};

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// The one line the mesh formats carry about what they hold.
std::string describe(const Solution& s, const std::string& source) {
  std::string d = std::string("hodt ") + version() + ": " + info(s.objective).id + " = " + format_number(s.value) +
                  " (Delaunay " + format_number(s.delaunay_value) + "), " + (s.optimal ? "optimal" : "not proven optimal") +
                  ", method " + s.method;
  if (s.order > 1) d += ", order " + std::to_string(s.order);
  return d + ", from " + source;
}

// --nodata V: points whose height is V are gaps, not terrain.
void drop_nodata(ParsedPoints& p, double nodata, const std::string& name) {
  size_t kept = 0;
  for (size_t i = 0; i < p.lines.size(); ++i) {
    if (p.xyz[3 * i + 2] == nodata) continue;
    std::copy_n(p.xyz.begin() + static_cast<std::ptrdiff_t>(3 * i), 3, p.xyz.begin() + static_cast<std::ptrdiff_t>(3 * kept));
    p.lines[kept++] = p.lines[i];
  }
  if (kept == 0) throw InputError(name + ": every point has the height --nodata " + format_number(nodata));
  p.xyz.resize(3 * kept);
  p.lines.resize(kept);
}

// x and y that look like longitude and latitude (within +-180 and +-90, spanning
// at most a few degrees) under heights spanning far more: angles, slopes and
// areas then mix degrees with metres.
std::optional<std::string> degrees_warning(const std::vector<double>& xyz) {
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (size_t i = 0; i < xyz.size(); ++i) lo[i % 3] = std::min(lo[i % 3], xyz[i]), hi[i % 3] = std::max(hi[i % 3], xyz[i]);
  const double span = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  if (lo[0] < -180 || hi[0] > 180 || lo[1] < -90 || hi[1] > 90 || span > 10 || hi[2] - lo[2] <= 100 * span) return std::nullopt;
  return "x and y look like degrees (longitude, latitude) while z spans " + format_number(hi[2] - lo[2]) +
         ": angles, slopes and areas mix units; reproject to a projected CRS in metres";
}

// The CRS of FILE's .prj sidecar (ESRI's habit for grids), if there is one; one
// that is not WKT is named in a warning and ignored.
std::optional<std::string> read_prj(const FileReader& read, const std::string& file, std::string* warnings) {
  const std::string prj = prj_path(file);
  if (prj == file) return std::nullopt;
  std::string error;
  const std::optional<std::string> text = read(prj, error);
  if (!text) return std::nullopt;  // (no sidecar: the usual case)
  std::optional<std::string> crs = text->size() <= kMaxCrsChars ? crs_of_wkt(*text) : std::nullopt;
  if (warnings)
    *warnings += crs ? "hodt: " + escape_input(file) + ": coordinates in " + (crs->rfind("EPSG:", 0) == 0 ? *crs : "the CRS") +
                           " of " + escape_input(prj) + ", kept as read\n"
                     : "hodt: warning: " + escape_input(prj) + ": not a WKT coordinate system (ignored)\n";
  return crs;
}

// The CRS as the last member of a JSON document, when there is one.
std::string with_crs_json(std::string document, const std::optional<std::string>& crs) {
  if (!crs) return document;
  document.pop_back();  // the closing brace
  return document + ", \"crs\": " + json_string(*crs) + "}";
}

}  // namespace

CliResult run_cli(const std::vector<std::string>& args, const FileReader& read) {
  CliHost host;
  host.read = read;
  return run_cli(args, host);
}

CliResult run_cli(const std::vector<std::string>& args, const CliHost& host) {
  CliResult r;
  try {
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
      r.out = cli_help();
      r.exit_code = args.empty() ? 2 : 0;
      return r;
    }
    if (args[0] == "--version" || args[0] == "version") {
      r.out = std::string("hodt ") + version() + "\n";
      return r;
    }
    const std::string& command = args[0];
    if (command != "stats" && command != "solve")
      throw Usage("unknown command " + quoted(command) + "; expected stats or solve (hodt --help)");
    std::string file, objective_id;
    bool have_file = false, triangles = false, quiet = false, force_progress = false;
    std::vector<Output> outputs;
    std::optional<std::string> drainage_path;  // --drainage FILE.geojson
    SolveOptions options;
    Dedupe dedupe = Dedupe::Error;
    bool have_order = false;
    std::optional<double> nodata, max_edge;  // max_edge: infinity for none
    std::optional<std::string> crs;           // as given (--crs), else FILE's .prj sidecar
    for (size_t i = 1; i < args.size(); ++i) {
      const std::string& a = args[i];
      auto value = [&]() -> const std::string& {
        if (i + 1 >= args.size()) throw Usage(a + " needs a value");
        return args[++i];
      };
      if (a == "--objective") objective_id = value();
      else if (a == "--method") {
        const std::string& m = value();
        const auto parsed = parse_method(m);
        if (!parsed) throw Usage("unknown method " + quoted(m) + "; valid methods: " + method_ids());
        options.method = *parsed;
      } else if (a == "--epsilon") options.epsilon = parse_number(a, value());
      else if (a == "--order") {
        const std::string& k = value();
        try {
          options.order = order_from_number(parse_number(a, k));
        } catch (const InputError&) {
          throw Usage("--order expects an integer from " + std::to_string(kMinOrder) + " to " +
                      std::to_string(kMaxOrder) + ", got " + quoted(k));
        }
        have_order = true;
      } else if (a == "--triangles") triangles = true;
      else if (a == "--trace") options.trace = true;
      else if (a == "--dedupe") {
        const std::string& d = value();
        if (d != "first" && d != "error") throw Usage("--dedupe expects 'first' or 'error', got " + quoted(d));
        dedupe = d == "first" ? Dedupe::KeepFirst : Dedupe::Error;
      } else if (a == "--output") {
        const std::string& path = value();
        const auto format = output_format_of(path);
        if (!format) throw Usage("--output " + quoted(path) + ": unknown format; name the file " + output_extensions());
        if (!host.write) throw Usage("--output " + quoted(path) + ": this front end writes no files");
        if (*format != OutputFormat::Json && !host.write_mesh)
          throw Usage("--output " + quoted(path) + ": this build of hodt writes .json only; for ." + format_id(*format) +
                      " use the npm CLI: npx hodt");
        outputs.push_back({path, *format});
      } else if (a == "--drainage") {
        const std::string& path = value();
        if (output_format_of(path) != OutputFormat::GeoJson)
          throw Usage("--drainage " + quoted(path) + ": the drainage network is GeoJSON; name the file .geojson");
        if (!host.write) throw Usage("--drainage " + quoted(path) + ": this front end writes no files");
        drainage_path = path;
      } else if (a == "--max-edge") {
        const std::string& v = value();
        max_edge = v == "none" ? INFINITY : parse_number(a, v);
        if (!(*max_edge > 0)) throw Usage("--max-edge expects a positive length or 'none', got " + quoted(v));
      } else if (a == "--nodata") {
        nodata = parse_number(a, value());
      } else if (a == "--classes") {
        const std::string& c = value();  // (read by the npm CLI's LAS/LAZ loader)
        if (c != "ground" && c != "all") throw Usage("--classes expects 'ground' or 'all', got " + quoted(c));
      } else if (a == "--crs") {
        const std::string& c = value();
        if (c.size() > kMaxCrsChars)
          throw Usage("--crs is " + std::to_string(c.size()) + " characters long, expected at most " + std::to_string(kMaxCrsChars));
        crs = crs_of_text(c);
        if (!crs)
          throw Usage("--crs expects an EPSG code (EPSG:32633), a WKT definition or a PROJ string (+proj=...), got " +
                      quote_input(c));
      } else if (a == "--quiet") quiet = true;
      else if (a == "--progress") force_progress = true;
      else if (a.size() > 1 && a[0] == '-' && a != "-") throw Usage("unknown option " + quoted(a) + " (hodt --help)");
      else if (!have_file) file = a, have_file = true;
      else throw Usage("unexpected argument " + quoted(a));
    }
    if (!have_file) throw Usage(command + ": missing FILE (hodt --help)");
    if (quiet && force_progress) throw Usage("--quiet and --progress exclude each other");
    check_options(options);  // before reading the file: the same check at every order
    std::optional<Objective> objective;
    if (command == "solve") {
      if (objective_id.empty()) throw Usage("solve needs --objective ID; valid objectives: " + objective_ids());
      objective = parse_objective(objective_id);
      if (!objective) throw Usage("unknown objective " + quoted(objective_id) + "; valid objectives: " + objective_ids());
    }

    CliProgress progress(quiet ? nullptr : host.show_progress, host.stderr_is_terminal, force_progress);
    PhaseTimes times;
    auto started = Clock::now();
    const std::string name = file == "-" ? "stdin" : escape_input(file);
    progress.step(Phase::Reading, name);
    std::string error;
    const std::optional<std::string> text = host.read(file, error);
    if (!text) throw InputError(name + ": " + file_error_message(error, FileAccess::Read));
    ParsedPoints parsed = read_points(*text, name);
    if (nodata) drop_nodata(parsed, *nodata, name);
    if (!crs && file != "-") crs = read_prj(host.read, file, quiet ? nullptr : &r.err);
    times.read_ms = ms_since(started);

    started = Clock::now();
    progress.step(Phase::Triangulating, std::to_string(parsed.lines.size()) + " points");
    PointLabels labels;
    labels.lines = parsed.lines;
    Terrain terrain;
    try {
      terrain = Terrain::from_points(parsed.xyz, dedupe, labels);
    } catch (const InputError& e) {
      throw InputError(name + ": " + e.what());
    }
    // The domain: as asked, else for a raster with NODATA cells its default.
    if (!max_edge && parsed.max_edge < INFINITY) {
      max_edge = parsed.max_edge;
      if (!quiet)
        r.err += "hodt: note: " + name + ": " + std::to_string(parsed.nodata_cells) +
                 " NODATA cells; triangles with an edge longer than " + format_number(*max_edge) +
                 " (" + format_number(kRasterMaxEdgeCells) + " cells) are outside the domain and not measured (--max-edge L to change, --max-edge none to "
                 "measure every triangle)\n";
    }
    if (max_edge) terrain.set_max_edge(*max_edge);
    times.build_ms = ms_since(started);
    if (!quiet)
      if (const auto w = degrees_warning(parsed.xyz)) r.err += "hodt: warning: " + name + ": " + *w + "\n";
    if (!quiet)
      if (const auto w = empty_domain_warning(terrain.structure().base)) r.err += "hodt: warning: " + name + ": " + *w + "\n";
    const uint32_t dropped = terrain.num_input_points() - terrain.structure().base.num_vertices();
    if (dropped > 0 && !quiet)
      r.err += "hodt: warning: " + name + ": dropped " + std::to_string(dropped) + " point" + (dropped == 1 ? "" : "s") +
               " at the same (x, y) as an earlier one (--dedupe first)\n";
    // The input is accepted: its notes now, not after the solve (a refused input
    // never reaches here, so its notes are never shown).
    if (host.show_notes && !quiet) {
      progress.clear_line();
      host.show_notes(r.err);
      r.err.clear();
    }

    // The document printed, the one written to .json (with the triangles), and the
    // triangulation the mesh formats get.
    const bool json_output =
        std::any_of(outputs.begin(), outputs.end(), [](const Output& o) { return o.format == OutputFormat::Json; });
    std::string printed, written;
    std::optional<Mesh> solved;
    std::string comment;
    std::optional<Drainage> network;  // (of the printed triangulation: the JSON's counts and --drainage)
    if (command == "stats") {
      network = drainage(terrain, terrain.delaunay_mesh());
      printed = with_crs_json(stats_json(terrain, have_order ? options.order : 0, &*network), crs);
      // ("triangles" is already the count)
      if (json_output)
        written = with_triangles_json(printed, terrain.to_input(terrain.delaunay_mesh().triangles), "delaunayTriangles");
      comment = std::string("hodt ") + version() + ": the Delaunay triangulation of " + name;
    } else {
      started = Clock::now();
      progress.solving(objective_id + (options.order > 1 ? ", order " + std::to_string(options.order) : ""));
      options.progress = progress.solve_progress();
      Solution s = solve(terrain.structure(), *objective, options);
      s.delaunay_value = terrain.delaunay_value(*objective);
      times.solve_ms = ms_since(started);
      solved = s.mesh ? std::move(*s.mesh) : triangulate(terrain.structure(), s.choice);
      network = drainage(terrain, *solved);
      const std::string document = solution_json(terrain, s, *solved, *network, options.trace, &times);
      const auto with_triangles = [&] { return with_triangles_json(document, terrain.to_input(solved->triangles)); };
      printed = with_crs_json(triangles ? with_triangles() : document, crs);
      if (json_output) written = triangles ? printed : with_crs_json(with_triangles(), crs);
      comment = describe(s, name);
    }

    std::optional<TinData> tin;  // made once, for the first mesh format
    for (const Output& o : outputs) {
      progress.step(Phase::Writing, o.path);
      bool ok;
      if (o.format == OutputFormat::Json) {
        ok = host.write(o.path, written + "\n", error);
      } else {
        if (!tin) tin = tin_data(terrain, parsed.xyz, solved ? *solved : terrain.delaunay_mesh(), comment, crs.value_or(""));
        ok = host.write_mesh(o.path, o.format, *tin, error);
      }
      if (!ok) throw InputError("cannot write " + escape_input(o.path) + ": " + file_error_message(error, FileAccess::Write));
    }
    if (drainage_path) {
      progress.step(Phase::Writing, *drainage_path);
      if (!host.write(*drainage_path, drainage_geojson(*network, parsed.xyz, crs.value_or("")), error))
        throw InputError("cannot write " + escape_input(*drainage_path) + ": " + file_error_message(error, FileAccess::Write));
    }
    r.out = printed + "\n";
  } catch (const InputError& e) {
    r.exit_code = 2;
    r.err = std::string("hodt: ") + e.what() + "\n";
  } catch (const LimitError& e) {
    r.exit_code = 3;
    r.err = std::string("hodt: ") + e.what() + "\n";
  } catch (const std::bad_alloc&) {
    r.exit_code = 3;
    r.err = "hodt: out of memory\n";
  } catch (const std::exception& e) {
    r.exit_code = 4;
    r.err = std::string("hodt: internal error: ") + e.what() + "\n";
  }
  return r;
}

}  // namespace hodt
