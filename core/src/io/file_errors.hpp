// Why a file cannot be read or written, in the same words from every front end:
// the native binary names errno, Node names error codes; both pass the code here.
#pragma once
#include <string>

namespace hodt {

enum class FileAccess { Read, Write };

// A short reason for an error code such as "ENOENT" ("no such file" when reading,
// "no such directory" when writing); an unknown code is named as it is, and a
// front end's own message (not a code) is returned unchanged.
std::string file_error_message(const std::string& code, FileAccess access);

}  // namespace hodt
