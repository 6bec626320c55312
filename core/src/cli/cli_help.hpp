// The CLI's own texts: `hodt --help` and `hodt --version`.
#pragma once
#include <string>

#include "hodt/objectives.hpp"

namespace hodt {

// The package version (package.json), e.g. "0.1.0".
const char* version();
// Usage, every option, and every objective with its meaning and unit.
std::string cli_help();

}  // namespace hodt
