#pragma once
// The controller languages ncc reads. A dialect is data (G-code table, parameters, alarm
// numbers: see passes/dialect_table.h) plus the grammar that reads its blocks.
#include <cstdint>
#include <optional>
#include <string_view>

namespace ncc {

enum class Dialect : uint8_t { FanucM, FanucT, MazakM, SiemensIsoM, SiemensDin };

std::string_view dialectName(Dialect d);                      // "fanuc-m", ...
std::optional<Dialect> parseDialect(std::string_view name);   // inverse of dialectName
// Default from a file name: `.mpf`/`.spf` -> siemens-din, anything else -> fanuc-m.
Dialect dialectFromFileName(std::string_view file_name);

}  // namespace ncc
