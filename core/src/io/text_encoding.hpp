// The bytes of a text file as people save them, as UTF-8 without a byte order mark:
// editors and spreadsheets on Windows write a UTF-8 BOM, and "Unicode" means UTF-16.
#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace hodt {

// The text after a UTF-8 byte order mark, if it starts with one.
std::string_view skip_utf8_bom(std::string_view bytes);
// UTF-16 (little or big endian, recognised by its byte order mark) as UTF-8;
// nullopt for anything else.
std::optional<std::string> utf8_from_utf16(std::string_view bytes);

}  // namespace hodt
