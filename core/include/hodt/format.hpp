// Shortest round-trip text of a double, as JavaScript prints it (JSON, messages).
#pragma once
#include <string>

namespace hodt {
std::string format_number(double v);
}
