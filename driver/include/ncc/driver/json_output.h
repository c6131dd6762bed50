#pragma once
// JSON written by `ncc run --emit=moves|vars` (format in docs/cli.md).
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ncc/bytecode/program.h"
#include "ncc/vm/events.h"

namespace ncc::driver {

// A number as JSON: rounded to 6 decimals (1 nm / 1 µdeg), trailing zeros trimmed but one
// decimal kept ("10.0", "0.125"), -0 written as 0.
std::string jsonNumber(double value);

// One JSON Lines object for a motion primitive:
// {"line": 12, "file": "part.nc", "kind": "line", "to": {"X": 10.0, ...}, "feed": 100.0}
void writeMoveJson(std::ostream& out, const vm::MotionPrimitive& motion,
                   const bytecode::Program& program);

// The run's last line when it stopped on an alarm:
// {"kind": "alarm", "code": "NCC7207", "line": 3, "file": "part.nc", "message": "..."}
void writeAlarmJson(std::ostream& out, const vm::Alarm& alarm, const bytecode::Program& program);

// The name of the program's source file `index` (its string pool entry) without folders, as
// every output shows it; "" when the program does not name it.
std::string sourceFileName(const bytecode::Program& program, uint32_t index);

// `text` as a JSON string, quotes included: '"', '\\', control characters and DEL escaped,
// valid UTF-8 kept, every byte that is not part of valid UTF-8 written as \ufffd.
std::string jsonString(std::string_view text);

// {"#100": 3.0, "#101": 1.5}
void writeVariablesJson(std::ostream& out, const std::vector<std::pair<std::string, double>>& vars);

}  // namespace ncc::driver
