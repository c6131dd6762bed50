#pragma once
// The language a block is read in: a Siemens ISO-mode program switches to DIN after G290 and
// back after G291 (block_reader.h). Its own header so that the stages after the parser
// (evaluation, lowering) name it without the parser.
#include <cstdint>

namespace ncc::frontend {

enum class Language : uint8_t { Iso, Din };

// The G codes that switch: G290 to DIN, G291 back to ISO (siemens-840di-iso-milling-gcode.ja
// §4.1), from the next block. The reader switches on them as written (language_switch.h); a
// value computed for G cannot be one (the evaluator refuses it).
inline constexpr double kSwitchToDin = 290.0;
inline constexpr double kSwitchToIso = 291.0;

}  // namespace ncc::frontend
