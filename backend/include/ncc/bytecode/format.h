#pragma once
// Bytecode v2: the constants of the file format (docs/bytecode.md describes every byte).
// All integers are little-endian with explicit widths; doubles are IEEE-754 binary64 bit
// patterns, so a file is byte-identical across hosts and compilers.
#include <cstdint>
#include <string_view>

namespace ncc::bytecode {

inline constexpr char kMagic[4] = {'N', 'C', 'C', 'B'};
// 2.0 added the file checksum (checksum.h) and the value bounds below; 1.x files are refused.
inline constexpr uint16_t kVersionMajor = 2;
inline constexpr uint16_t kVersionMinor = 0;

// Fixed part of the header; the axis table (kAxisEntrySize bytes per axis) follows it and the
// code section starts right after the axis table.
inline constexpr uint32_t kFixedHeaderSize = 64;
inline constexpr uint32_t kChecksumOffset = 56;  // u64, the last field of the fixed header
inline constexpr uint32_t kAxisEntrySize = 16;
inline constexpr uint32_t kMaxAxisNameLength = 14;
inline constexpr uint32_t kLineEntrySize = 16;  // code offset, file, line, column (u32 each)
inline constexpr uint32_t kUnitEntrySize = 8;   // entry offset, name string (u32 each)

// Limits the verifier enforces and the executor sizes its fixed buffers by.
inline constexpr uint32_t kMaxVariableCount = 100000;   // numbered variables #0..#(count-1)
inline constexpr uint32_t kDefaultVariableCount = 10000;
inline constexpr int kMaxStackDepth = 64;                // value stack slots
inline constexpr int64_t kMaxFunctionCode = 99999999;    // M / T numbers: at most 8 digits
// Bounds on values no valid program holds (docs/bytecode.md, "Value bounds"). A block can
// program at most 99999.999 (8 digits, IS-B) and the controllers' length parameters stop at
// 999999.999 mm: a coordinate or arc centre beyond 1e6 mm (or degrees) comes from no program
// (and a run towards 1e300 would simulate for ever). Dwell: the manuals' G04 range ends at
// 99999.999 s (or revolutions). Extra arc turns: 999, the range of Sinumerik's TURN= (the
// controllers' only word for extra turns); a million turns of a small arc simulate for hours.
inline constexpr double kMaxCoordinate = 1e6;   // |coordinate|, |centre|: mm or degrees
inline constexpr double kMaxDwell = 1e5;        // seconds or spindle revolutions
inline constexpr uint32_t kMaxExtraTurns = 999;
inline constexpr uint8_t kMaxReference = 4;              // G27/G28/G30 reference points 1..4

// Section table order in the header.
enum class Section : uint8_t { Code, Lines, Strings, Units };
inline constexpr int kSectionCount = 4;

enum class Opcode : uint8_t {
  End = 0x01,              // end of code; the program finishes here
  // Motion: the target is the full vector of every configured axis, machine coordinates.
  Rapid = 0x10,            // flags, target[N]
  Line = 0x11,             // flags, feed, target[N]
  Arc = 0x12,              // flags, plane, axis1, axis2, turns u32, feed, target[N], c1, c2
  Dwell = 0x13,            // flags, amount (seconds, or revolutions with kFlagRevolutions)
  // Machine functions.
  SpindleSpeed = 0x20,     // S: f64 rev/min
  SpindleCW = 0x21,        // M03
  SpindleCCW = 0x22,       // M04
  SpindleStop = 0x23,      // M05
  SpindleOrient = 0x24,    // M19
  ToolSelect = 0x25,       // T: i64
  ToolChange = 0x26,       // M06
  CoolantOn = 0x27,        // M08
  CoolantOff = 0x28,       // M09
  ProgramStop = 0x29,      // M00
  OptionalStop = 0x2A,     // M01
  ProgramEnd = 0x2B,       // M02: the program finishes here
  ProgramEndRewind = 0x2C, // M30: the program finishes here
  MCode = 0x2D,            // any other M: i64, passed through
  RefCheck = 0x30,         // G27: mask u16, reference u8, position[N]
  // Values: a stack of doubles where "vacant" (#0, never assigned) is a distinct state.
  Push = 0x40,             // f64 constant
  PushVacant = 0x41,
  Load = 0x42,             // u32 variable number
  Store = 0x43,            // u32 variable number (pops)
  Pop = 0x44,
  Add = 0x50,
  Sub = 0x51,
  Mul = 0x52,
  Div = 0x53,
  Neg = 0x54,
  CmpEq = 0x58,
  CmpNe = 0x59,
  CmpLt = 0x5A,
  CmpLe = 0x5B,
  CmpGt = 0x5C,
  CmpGe = 0x5D,
  Jump = 0x60,             // u32 code offset
  JumpIfFalse = 0x61,      // u32 code offset; pops the condition
};

// Flag bits of the motion instructions (one flags byte each; unused bits must be zero).
inline constexpr uint8_t kFlagFeedPerRev = 0x01;  // LINE, ARC: feed in mm/rev (G95)
inline constexpr uint8_t kFlagExactStop = 0x02;   // RAPID, LINE, ARC: stop at the end (G09/G61)
inline constexpr uint8_t kFlagPerAxis = 0x04;     // RAPID: axes move independently (non-linear G00)
inline constexpr uint8_t kFlagClockwise = 0x08;   // ARC: G02
inline constexpr uint8_t kFlagRevolutions = 0x10; // DWELL: amount in spindle revolutions
inline constexpr uint8_t kFlagFixedOverride = 0x20; // LINE, ARC: feed override fixed at 100 % (G63)

enum class ArcPlane : uint8_t { XY = 0, ZX = 1, YZ = 2 };  // G17 G18 G19

// Static facts about one opcode.
struct OpcodeInfo {
  const char* mnemonic;        // as printed by the disassembler
  uint8_t allowed_flags;       // flag bits this opcode accepts
  int8_t pops;                 // value-stack effect
  int8_t pushes;
  bool falls_through;          // false: END, PROGRAM_END(_REWIND), JUMP
};

// nullptr if `byte` is not an opcode of this version.
const OpcodeInfo* opcodeInfo(uint8_t byte);
// Encoded length of an instruction with this opcode (including the opcode byte).
uint32_t instructionSize(Opcode op, int axis_count);
// Largest instruction of any kind: ARC with kMaxAxes axes.
uint32_t maxInstructionSize();

}  // namespace ncc::bytecode
