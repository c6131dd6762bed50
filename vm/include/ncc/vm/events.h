#pragma once
// What the executor produces, in execution order: motion primitives in machine coordinates
// (the planner / interpolator / servo consume these) and machine-function events. Plain
// structs without heap members, so producing them allocates nothing.
#include <cstdint>
#include <string>

#include "ncc/machine/axes.h"
#include "ncc/support/source_location.h"

namespace ncc::vm {

// Where an event comes from. `file` indexes the program's string pool, which the compiler
// fills with its source file names in file-id order.
using SourcePosition = SourceLocation;

enum class Plane : uint8_t { XY, ZX, YZ };  // G17 G18 G19

struct MotionPrimitive {
  enum class Kind : uint8_t { Rapid, Line, Arc, Dwell };
  Kind kind = Kind::Rapid;
  AxisValues from{};          // machine position before the move
  AxisValues to{};            // after it (Dwell: equal to from)
  // Arc: the centre on the two plane axes (indices axis1, axis2); other entries are zero.
  AxisValues center{};
  Plane plane = Plane::XY;
  uint8_t axis1 = 0;
  uint8_t axis2 = 1;
  bool cw = false;
  uint32_t extra_turns = 0;
  double feed = 0.0;          // Line/Arc: mm/min, or mm/rev when feed_per_rev
  bool feed_per_rev = false;
  bool exact_stop = false;    // decelerate to a stop at the end (G09 / G61)
  bool fixed_override = false;  // Line/Arc: the feed override does not apply (G63 tapping)
  bool per_axis = false;      // Rapid: axes move independently (non-linear G00)
  double seconds = 0.0;       // Dwell: seconds, or spindle revolutions when `revolutions`
  bool revolutions = false;
  SourcePosition where;
};

struct MachineEvent {
  enum class Kind : uint8_t {
    SpindleSpeed,      // value = S (rev/min)
    SpindleCW,         // M03
    SpindleCCW,        // M04
    SpindleStop,       // M05
    SpindleOrient,     // M19
    ToolSelect,        // code = T
    ToolChange,        // M06
    CoolantOn,         // M08
    CoolantOff,        // M09
    ProgramStop,       // M00: the run continues (as if cycle start were pressed)
    OptionalStop,      // M01: likewise
    ProgramEnd,        // M02: the last event of the run
    ProgramEndRewind,  // M30: the last event of the run
    MCode,             // any other M: code
  };
  Kind kind = Kind::MCode;
  int64_t code = 0;   // the M number (T number for ToolSelect)
  double value = 0.0; // SpindleSpeed: rev/min
  SourcePosition where;
};

struct Event {
  enum class Kind : uint8_t { Motion, Machine };
  Kind kind = Kind::Motion;
  MotionPrimitive motion;  // valid when kind == Motion
  MachineEvent machine;    // valid when kind == Machine
};

// A run-time alarm stops the run. Codes NCC72xx are listed in docs/bytecode.md.
struct Alarm {
  std::string code;
  std::string message;
  SourcePosition where;
};

}  // namespace ncc::vm
