// The command line contract of `hodt` (README, "CLI"), shared by the native
// binary and the npm bin (which runs it in wasm): arguments in, text out. Files
// and the terminal belong to the front end, which lends them through CliHost.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hodt/tin_output.hpp"

namespace hodt {

struct CliResult {
  int exit_code = 0;  // 0 ok, 2 bad input or usage, 3 refused (a limit), 4 internal error
  std::string out;    // stdout
  std::string err;    // stderr: one line per error or warning
};

// Reads a file ("-" is standard input); returns nullopt with the reason in `error`
// if it cannot (an error code such as "ENOENT" is put in words by
// file_error_message). The bytes are decoded by the core (read_points).
using FileReader = std::function<std::optional<std::string>(const std::string& path, std::string& error)>;
// Writes a whole file; returns false with the reason in `error`, as FileReader.
using FileWriter = std::function<bool(const std::string& path, std::string_view bytes, std::string& error)>;
// Writes a triangulation in a mesh format (obj, ply, geojson, glb); as FileWriter.
using MeshWriter =
    std::function<bool(const std::string& path, OutputFormat format, const TinData& tin, std::string& error)>;

// What the front end lends the core.
struct CliHost {
  FileReader read;
  FileWriter write;           // --output FILE.json; empty: --output is refused
  MeshWriter write_mesh;      // --output FILE.obj/.ply/.geojson/.glb; empty: refused (the native binary)
  std::function<void(const std::string& text)> show_progress;  // stderr, at once; empty: no progress
  // stderr, at once: the input's notes and warnings, once it is accepted (before
  // the solve); empty: they come with the result's err.
  std::function<void(const std::string& text)> show_notes;
  bool stderr_is_terminal = false;
};

CliResult run_cli(const std::vector<std::string>& args, const CliHost& host);
// Without output files or progress.
CliResult run_cli(const std::vector<std::string>& args, const FileReader& read);

}  // namespace hodt
