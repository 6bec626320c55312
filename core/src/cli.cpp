#include "hodt/cli.hpp"

#include <cstdlib>

#include "hodt/error.hpp"
#include "hodt/read_points.hpp"
#include "hodt/report.hpp"
#include "hodt/solve.hpp"
#include "hodt/solve_options.hpp"
#include "hodt/terrain.hpp"

namespace hodt {
namespace {

const char* kUsage =
    "usage: hodt stats FILE [--order K] [--dedupe first]\n"
    "       hodt solve FILE --objective ID [--method brute-force|exact|approx|auto]\n"
    "                  [--epsilon E] [--order K] [--triangles] [--trace] [--dedupe first]\n"
    "FILE: CSV/TSV/whitespace 'x y z' lines (optional header), JSON [[x,y,z],...],\n"
    "      or an ESRI ASCII grid (.asc); '-' reads standard input.\n"
    "Prints JSON. Exit codes: 0 ok, 2 bad input or usage, 3 refused (a limit).\n";

struct Usage : InputError {
  using InputError::InputError;
};

// Any number strtod reads (NaN and infinities too: the option's own check then
// names them, as it does for every front end).
double parse_number(const std::string& flag, const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size())
    throw Usage(flag + " expects a number, got '" + text + "'");
  return v;
}

}  // namespace

CliResult run_cli(const std::vector<std::string>& args, const FileReader& read) {
  CliResult r;
  try {
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
      r.out = kUsage;
      r.exit_code = args.empty() ? 2 : 0;
      return r;
    }
    const std::string& command = args[0];
    if (command != "stats" && command != "solve")
      throw Usage("unknown command '" + command + "'; expected stats or solve (hodt --help)");
    std::string file, objective_id;
    bool have_file = false, triangles = false;
    SolveOptions options;
    Dedupe dedupe = Dedupe::Error;
    bool have_order = false;
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
        if (!parsed) throw Usage("unknown method '" + m + "'; valid methods: " + method_ids());
        options.method = *parsed;
      } else if (a == "--epsilon") options.epsilon = parse_number(a, value());
      else if (a == "--order") {
        const std::string& k = value();
        try {
          options.order = order_from_number(parse_number(a, k));
        } catch (const InputError&) {
          throw Usage("--order expects an integer from " + std::to_string(kMinOrder) + " to " +
                      std::to_string(kMaxOrder) + ", got '" + k + "'");
        }
        have_order = true;
      } else if (a == "--triangles") triangles = true;
      else if (a == "--trace") options.trace = true;
      else if (a == "--dedupe") {
        const std::string& d = value();
        if (d != "first" && d != "error") throw Usage("--dedupe expects 'first' or 'error', got '" + d + "'");
        dedupe = d == "first" ? Dedupe::KeepFirst : Dedupe::Error;
      } else if (a.size() > 1 && a[0] == '-' && a != "-") throw Usage("unknown option '" + a + "' (hodt --help)");
      else if (!have_file) file = a, have_file = true;
      else throw Usage("unexpected argument '" + a + "'");
    }
    if (!have_file) throw Usage(command + ": missing FILE (hodt --help)");
    check_options(options);  // before reading the file: the same check at every order
    std::optional<Objective> objective;
    if (command == "solve") {
      if (objective_id.empty()) throw Usage("solve needs --objective ID; valid objectives: " + objective_ids());
      objective = parse_objective(objective_id);
      if (!objective) throw Usage("unknown objective '" + objective_id + "'; valid objectives: " + objective_ids());
    }
    std::string error;
    const std::optional<std::string> text = read(file, error);
    if (!text) throw InputError(file + ": " + error);
    const std::string name = file == "-" ? "stdin" : file;
    const ParsedPoints parsed = read_points(*text, name);
    PointLabels labels;
    labels.lines = parsed.lines;
    Terrain terrain;
    try {
      terrain = Terrain::from_points(parsed.xyz, dedupe, labels);
    } catch (const InputError& e) {
      throw InputError(name + ": " + e.what());
    }
    if (command == "stats") {
      r.out = stats_json(terrain, have_order ? options.order : 0) + "\n";
    } else {
      Solution s = solve(terrain.structure(), *objective, options);
      s.delaunay_value = terrain.delaunay_value(*objective);
      r.out = solution_json(terrain, s, triangles, options.trace) + "\n";
    }
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
