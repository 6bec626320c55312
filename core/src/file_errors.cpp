#include "hodt/file_errors.hpp"

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
  std::string reason = read ? "cannot read the file" : "cannot write the file";
  if (!code.empty()) reason += " (" + code + ")";
  return reason;
}

}  // namespace hodt
