#pragma once
// A problem found while writing, loading or verifying bytecode. Codes NCC70xx (load) and
// NCC71xx (verify) are listed in docs/bytecode.md.
#include <cstdint>
#include <string>

namespace ncc::bytecode {

struct Error {
  std::string code;     // "NCC7001", ...
  std::string message;  // names the section / code offset and what is wrong
};

}  // namespace ncc::bytecode
