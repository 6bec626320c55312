#include "io/file_errors.hpp"

#include <algorithm>

#include "io/quote_input.hpp"

namespace hodt {

std::string file_error_message(const std::string& code, FileAccess access) {
  const bool read = access == FileAccess::Read;
  if (code == "ENOENT") return read ? "no such file" : "no such directory";
  if (code == "EISDIR") return "is a directory";
  if (code == "ENOTDIR") return "a part of the path is not a directory";
  if (code == "EACCES" || code == "EPERM") return "permission denied";
  if (code == "ENOSPC") return "no space left on the device";
  if (code == "EROFS") return "read-only file system";
  if (code == "ENAMETOOLONG") return "file name too long";
  // Anything but a code (E and capitals, or the native "errno N") is the front
  // end's own message (a loader's, which may quote the file: escaped onto one line).
  const bool is_code = code.size() > 1 && code[0] == 'E' &&
                       std::all_of(code.begin(), code.end(), [](char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'); });
  if (!code.empty() && !is_code && code.rfind("errno ", 0) != 0) return escape_input(code);
  std::string reason = read ? "cannot read the file" : "cannot write the file";
  if (!code.empty()) reason += " (" + code + ")";
  return reason;
}

}  // namespace hodt
