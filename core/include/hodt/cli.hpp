// The command line contract of `hodt` (README, "CLI"), shared by the native
// binary and the npm bin (which runs it in wasm): arguments in, text out.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace hodt {

struct CliResult {
  int exit_code = 0;  // 0 ok, 2 bad input or usage, 3 refused (a limit), 4 internal error
  std::string out;    // stdout
  std::string err;    // stderr: one line
};

// Reads a file ("-" is standard input); returns nullopt with a message in `error`
// if it cannot. Supplied by the front end: the core has no file system.
using FileReader = std::function<std::optional<std::string>(const std::string& path, std::string& error)>;

CliResult run_cli(const std::vector<std::string>& args, const FileReader& read);

}  // namespace hodt
