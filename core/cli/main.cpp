// Native `hodt` binary: the shared CLI with the real file system.
#include <fstream>
#include <iostream>
#include <sstream>

#include "hodt/cli.hpp"

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  const hodt::CliResult r = hodt::run_cli(args, [](const std::string& path, std::string& error) -> std::optional<std::string> {
    std::stringstream ss;
    if (path == "-") {
      ss << std::cin.rdbuf();
      return ss.str();
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      error = "cannot open the file";
      return std::nullopt;
    }
    ss << in.rdbuf();
    return ss.str();
  });
  std::cout << r.out;
  std::cerr << r.err;
  return r.exit_code;
}
