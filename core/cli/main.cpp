// Native `hodt` binary: the shared CLI with the real file system. It writes
// --output FILE.json; the mesh formats are written by the npm CLI (npx hodt).
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "hodt/cli.hpp"

namespace {

// errno as the code Node reports, so that both CLIs give the same reason.
std::string errno_code(int e) {
  switch (e) {
    case ENOENT: return "ENOENT";
    case EISDIR: return "EISDIR";
    case ENOTDIR: return "ENOTDIR";
    case EACCES: return "EACCES";
    case EPERM: return "EPERM";
    case ENOSPC: return "ENOSPC";
    case EROFS: return "EROFS";
    case ENAMETOOLONG: return "ENAMETOOLONG";
    default: return "errno " + std::to_string(e);
  }
}

std::optional<std::string> read_file(const std::string& path, std::string& error) {
  if (path == "-") {
    std::stringstream ss;
    ss << std::cin.rdbuf();
    return ss.str();
  }
  FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) {
    error = errno_code(errno);
    return std::nullopt;
  }
  std::string text;
  char buf[1 << 16];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, n);
  const bool failed = std::ferror(f);
  const int e = errno;
  std::fclose(f);
  if (failed) {
    error = errno_code(e);  // EISDIR: a directory opens, but does not read
    return std::nullopt;
  }
  return text;
}

bool write_file(const std::string& path, std::string_view bytes, std::string& error) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) {
    error = errno_code(errno);
    return false;
  }
  const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  const int e = errno;
  if (std::fclose(f) != 0 || !ok) {
    error = errno_code(ok ? errno : e);
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  hodt::CliHost host;
  host.read = read_file;
  host.write = write_file;
  host.show_progress = [](const std::string& text) { std::cerr << text << std::flush; };
  host.show_notes = host.show_progress;
  host.stderr_is_terminal = isatty(STDERR_FILENO) != 0;
  const hodt::CliResult r = hodt::run_cli(args, host);
  std::cout << r.out;
  std::cerr << r.err;
  return r.exit_code;
}
