#pragma once
// The language a block is read in: a Siemens ISO-mode program switches to DIN after G290 and
// back after G291 (block_reader.h). Its own header so that the stages after the parser
// (evaluation, lowering) name it without the parser.
#include <cstdint>

namespace ncc::frontend {

enum class Language : uint8_t { Iso, Din };

}  // namespace ncc::frontend
