#pragma once
// Bytes -> Program. Checks the container: magic, version, header fields, axis table, that the
// sections tile the file exactly (code, lines, strings, units, nothing after), and that the
// string pool, line table and unit table parse. Instructions are checked by verifier.h.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>

#include "ncc/bytecode/error.h"
#include "ncc/bytecode/program.h"

namespace ncc::bytecode {

// On success fills `program` and returns nullopt; otherwise returns the first problem.
std::optional<Error> load(std::span<const uint8_t> bytes, Program& program);
std::optional<Error> loadFile(const std::filesystem::path& path, Program& program);

// The same checks, streaming: the checksum is computed a window at a time and the code and
// line table stay in the file (Program::paged), so memory does not grow with the program.
// The file must not change while the program is in use (the executor still re-checks each
// instruction it runs; the verifier reads the file again).
std::optional<Error> loadPaged(std::shared_ptr<const ProgramFile> file, Program& program);
std::optional<Error> loadFilePaged(const std::filesystem::path& path, Program& program);

}  // namespace ncc::bytecode
