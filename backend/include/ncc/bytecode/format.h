#pragma once
// Bytecode v2: the constants of the file format (docs/bytecode.md describes every byte).
// All integers are little-endian with explicit widths; doubles are IEEE-754 binary64 bit
// patterns, so a file is byte-identical across hosts and compilers.
#include <array>
#include <cstdint>
#include <span>
#include <string_view>

namespace ncc::bytecode {

inline constexpr char kMagic[4] = {'N', 'C', 'C', 'B'};
// 2.0 added the file checksum (checksum.h) and the value bounds below; 1.x files are refused.
// 2.1 added SKIP (G31); 2.2 added PREPARE and the block store after the unit table; 2.3 the
// variable names after the units (DIN's R10, COUNT). Older minors load unchanged.
inline constexpr uint16_t kVersionMajor = 2;
inline constexpr uint16_t kVersionMinor = 3;
inline constexpr uint16_t kFirstMinorWithBlocks = 2;
inline constexpr uint16_t kFirstMinorWithNames = 3;

// Fixed part of the header; the axis table (kAxisEntrySize bytes per axis) follows it and the
// code section starts right after the axis table.
inline constexpr uint32_t kFixedHeaderSize = 64;
inline constexpr uint32_t kChecksumOffset = 56;  // u64, the last field of the fixed header
inline constexpr uint32_t kAxisEntrySize = 16;
inline constexpr uint32_t kMaxAxisNameLength = 14;
inline constexpr uint32_t kLineEntrySize = 16;  // code offset, file, line, column (u32 each)
inline constexpr uint32_t kUnitEntrySize = 8;   // entry offset, name string (u32 each)
inline constexpr uint32_t kVariableNameEntrySize = 8;  // variable number, name string (u32 each)

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

// The opcode bytes. Their operands, stack effects and listings are in the opcode table
// (format.cpp, OpcodeInfo below); docs/bytecode.md describes each.
enum class Opcode : uint8_t {
  End = 0x01,              // end of code; the program finishes here
  // Motion: the target is the full vector of every configured axis, machine coordinates.
  Rapid = 0x10,
  Line = 0x11,
  Arc = 0x12,
  Dwell = 0x13,            // seconds, or revolutions with kFlagRevolutions
  Skip = 0x14,             // G31: a LINE that ends where the skip signal comes on (since 2.1)
  // Machine functions.
  SpindleSpeed = 0x20,     // S
  SpindleCW = 0x21,        // M03
  SpindleCCW = 0x22,       // M04
  SpindleStop = 0x23,      // M05
  SpindleOrient = 0x24,    // M19
  ToolSelect = 0x25,       // T
  ToolChange = 0x26,       // M06
  CoolantOn = 0x27,        // M08
  CoolantOff = 0x28,       // M09
  ProgramStop = 0x29,      // M00
  OptionalStop = 0x2A,     // M01
  ProgramEnd = 0x2B,       // M02: the program finishes here
  ProgramEndRewind = 0x2C, // M30: the program finishes here
  MCode = 0x2D,            // any other M, passed through
  RefCheck = 0x30,         // G27
  // Values: a stack of doubles where "vacant" (#0, never assigned) is a distinct state.
  Push = 0x40,
  PushVacant = 0x41,
  Load = 0x42,
  Store = 0x43,
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
  Jump = 0x60,
  JumpIfFalse = 0x61,      // pops the condition
  // The rest of the program is prepared while it runs, from the block store (since 2.2).
  Prepare = 0x70,
};

// Flag bits of the motion instructions (one flags byte each; unused bits must be zero).
inline constexpr uint8_t kFlagFeedPerRev = 0x01;  // LINE, ARC: feed in mm/rev (G95)
inline constexpr uint8_t kFlagExactStop = 0x02;   // RAPID, LINE, ARC: stop at the end (G09/G61)
inline constexpr uint8_t kFlagPerAxis = 0x04;     // RAPID: axes move independently (non-linear G00)
inline constexpr uint8_t kFlagClockwise = 0x08;   // ARC: G02
inline constexpr uint8_t kFlagRevolutions = 0x10; // DWELL: amount in spindle revolutions
inline constexpr uint8_t kFlagFixedOverride = 0x20; // LINE, ARC, SKIP: feed override fixed at 100 % (G63, G31)
inline constexpr uint8_t kFlagInch = 0x40;        // SKIP: the skip position variables hold inches (G20)

enum class ArcPlane : uint8_t { XY = 0, ZX = 1, YZ = 2 };  // G17 G18 G19

// The operand kinds an instruction can have. Each kind has one byte encoding, one field of
// bytecode::Instruction, one verifier check and one disassembler rendering (docs/bytecode.md,
// "Operand kinds"); an opcode is described by the kinds of its operands, in byte order.
enum class Operand : uint8_t {
  Flags,      // u8: kFlag* bits, only those in OpcodeInfo::allowed_flags       -> flags
  Plane,      // u8: ArcPlane                                                   -> plane
  PlaneAxes,  // 2 x u8: axis-table indices of the plane's two axes, distinct   -> axis1, axis2
  Turns,      // u32: full circles beyond the first, at most kMaxExtraTurns    -> turns
  Feed,       // f64 > 0: mm/min, or mm/rev with kFlagFeedPerRev                -> value
  Amount,     // f64 in [0, kMaxDwell]: seconds, or revolutions with kFlagRevolutions -> value
  Speed,      // f64 >= 0: spindle rev/min                                     -> value
  Constant,   // f64: a finite value pushed on the stack                       -> value
  Target,     // N x f64: every configured axis, |v| <= kMaxCoordinate         -> axes
  Centre,     // 2 x f64: the arc centre on the PlaneAxes, |v| <= kMaxCoordinate -> center1, center2
  Mask,       // u16: axes selected, at least one, all below N                 -> mask
  Reference,  // u8: reference point 1..kMaxReference                          -> reference
  Position,   // N x f64 like Target; listed for the Mask's axes only          -> axes
  Variable,   // u32: variable number below the header's variable count        -> variable
  Assigned,   // u32: like Variable, but not #0 (it is always vacant)          -> variable
  JumpTarget, // u32: code offset of an instruction start                      -> target
  Code,       // i64 in 0..kMaxFunctionCode: a T or M number                   -> code
  Results,    // u32: 0, or the first of N variables (one per axis) below the count -> variable
  Origin,     // N x f64 like Target: machine coordinates of the work zero     -> origin
};
inline constexpr int kMaxOperands = 8;

// Where execution goes after an instruction.
enum class Flow : uint8_t {
  Next,    // to the next instruction
  Branch,  // to the next instruction or to its JumpTarget
  Jump,    // to its JumpTarget
  Stop,    // nowhere: the program ends (END, M02, M30) or goes on in the block store (PREPARE)
};

// Static facts about one opcode: one row of the opcode table (format.cpp), from which
// encoding, decoding, sizes, the verifier's operand checks, its stack and flow analysis and the
// disassembler's listing are all derived.
struct OpcodeInfo {
  const char* mnemonic;        // as printed by the disassembler
  std::array<Operand, kMaxOperands> operand_kinds;  // the first operand_count are used
  uint8_t operand_count;
  // How the disassembler lists the operands: text with {name} placeholders, one per operand
  // (named as operandName() says) or flag (FlagInfo::name; {flags}: every other flag set), and
  // [optional parts], dropped when their placeholders all print nothing.
  const char* listing;
  uint8_t allowed_flags;       // flag bits this opcode accepts
  int8_t pops;                 // value-stack effect
  int8_t pushes;
  Flow flow;

  constexpr std::span<const Operand> operands() const {
    return {operand_kinds.data(), operand_count};
  }
  bool hasOperand(Operand kind) const;
};

// nullptr if `byte` is not an opcode of this version.
const OpcodeInfo* opcodeInfo(uint8_t byte);
const OpcodeInfo& opcodeInfo(Opcode op);  // `op` must be an opcode of this version
// The name of an operand kind in listing templates and messages ("target", "feed", ...).
const char* operandName(Operand kind);
// Encoded length of one operand of this kind.
uint32_t operandSize(Operand kind, int axis_count);

// One flag bit: its name in listing templates and the words the disassembler prints for it.
struct FlagInfo {
  uint8_t bit;
  const char* name;        // {clockwise} in a listing
  const char* when_set;    // "CW", "exact-stop"
  const char* when_clear;  // "CCW", or "" (nothing)
};
// Every flag bit, in the order the disassembler lists them under {flags}.
std::span<const FlagInfo> flagTable();

// Encoded length of an instruction with this opcode (including the opcode byte).
uint32_t instructionSize(Opcode op, int axis_count);
// Largest instruction of any kind: ARC with kMaxAxes axes.
uint32_t maxInstructionSize();

}  // namespace ncc::bytecode
