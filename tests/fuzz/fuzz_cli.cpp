// The CLI contract on any file: an answer with finite numbers (exit 0), or one
// line naming what is wrong (exit 2) or the limit hit (exit 3). Never a crash,
// a sanitizer finding, a non-finite number or an unbounded run.
#include <cstdio>
#include <string>

#include "hodt/cli.hpp"
#include "hodt/objectives.hpp"

using namespace hodt;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  const uint8_t mode = data[0], pick = data[1];
  const std::string file(reinterpret_cast<const char*>(data) + 2, size - 2);
  std::vector<std::string> args;
  if (mode % 3 == 0) args = {"stats", "in.txt", "--dedupe", "first"};
  else {
    args = {"solve", "in.txt", "--objective", std::string(objectives()[pick % kNumObjectives].id), "--dedupe", "first"};
    if (mode % 3 == 2) args.insert(args.end(), {"--order", std::to_string(2 + (pick >> 4) % 2)});
  }
  if (mode & 8) args.insert(args.end(), {"--max-edge", "3"});
  if (mode & 16) args.insert(args.end(), {"--nodata", "-9999"});
  const CliResult r = run_cli(args, [&](const std::string& path, std::string& error) -> std::optional<std::string> {
    if (path == "in.txt") return file;
    error = "ENOENT";  // (a .prj sidecar: none)
    return std::nullopt;
  });
  // One printable line: no control character before the final newline (file content is quoted escaped).
  bool one_line = !r.err.empty() && r.err.back() == '\n';
  for (size_t i = 0; one_line && i + 1 < r.err.size(); ++i)
    one_line = static_cast<unsigned char>(r.err[i]) >= 0x20 && r.err[i] != 0x7f;
  if (r.exit_code == 0) {
    for (const char* bad : {"nan", "NaN", "inf", "Infinity"})
      if (r.out.find(bad) != std::string::npos) {
        std::fprintf(stderr, "fuzz_cli: '%s' in %s\n", bad, r.out.c_str());
        __builtin_trap();
      }
  } else if ((r.exit_code != 2 && r.exit_code != 3) || r.err.rfind("hodt: ", 0) != 0 || !one_line) {
    std::fprintf(stderr, "fuzz_cli: exit %d, stderr '%s'\n", r.exit_code, r.err.c_str());
    __builtin_trap();
  }
  return 0;
}
