#pragma once
// Bytes -> Program. Checks the container: magic, version, header fields, axis table, that the
// sections tile the file exactly (code, lines, strings, units, nothing after), and that the
// string pool, line table and unit table parse. Instructions are checked by verifier.h.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>

#include "ncc/bytecode/error.h"
#include "ncc/bytecode/program.h"

namespace ncc::bytecode {

// On success fills `program` and returns nullopt; otherwise returns the first problem.
std::optional<Error> load(std::span<const uint8_t> bytes, Program& program);
std::optional<Error> loadFile(const std::filesystem::path& path, Program& program);

}  // namespace ncc::bytecode
