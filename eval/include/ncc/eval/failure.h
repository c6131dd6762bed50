#pragma once
// Why evaluation stopped. Each kind maps to the dialect's alarm number through MacroRules
// (macro_rules.h); the evaluator never names an alarm number itself.
#include <cstdint>
#include <string>

#include "ncc/support/source_location.h"

namespace ncc::eval {

enum class EvalError : uint8_t {
  VariableNumber,        // #n with n out of every range (negative, beyond the last system variable)
  VariableReadOnly,      // assignment to #0, or to a system variable that cannot be written
  DivisionByZero,        // a / 0, a MOD 0
  Domain,                // LN of x <= 0, SQRT of x < 0, ASIN/ACOS outside [-1, 1], POW ...
  ValueRange,            // a result beyond the controller's value range
  BracketNesting,        // brackets deeper than the stated depth
  AddressValue,          // a value that an address cannot take (G#1 with #1 = 1.5, P too long)
  EndWithoutDo,          // END m without its WHILE ... DO m
  DoNesting,             // WHILE ... DO nested deeper than the limit
  DoNumber,              // DO m / END m with m outside the allowed identifiers
  LoopNotClosed,         // DO m without END m before the program (or subprogram) ends
  GotoTarget,            // GOTO n: no block starts with N n (or n out of range)
  ProgramNotFound,       // M98 P / G65 P / a macro call: no such program
  CallNesting,           // subprogram + macro calls deeper than the limit
  MacroNesting,          // macro calls (G65, G66, ...) deeper than their own limit
  UserAlarm,             // #3000 = n (message): the program raised an alarm
  UserStop,              // #3006 = n (message): a stop with a message (reported as a warning)
  ModalCallCancel,       // G67 without G66
  ArgumentBeforeCall,    // an argument written before G65 / G66 (Siemens)
  StepLimit,             // a loop that does not end: the configured step limit was reached
  NotSupported,          // a word of a call ncc does not build yet
  FigureRotationNested,  // M98 with I J K inside a figure rotation (Mazak 849)
  FigureRotationWithRotation,  // figure rotation while G68 is in force (Mazak 850)
  // A value known only when the program runs (where a G31 stopped, an interface signal): not
  // an error; the compiler leaves the rest of the program to the VM (docs/runtime.md).
  RunTimeValue,
  // DIN (docs/din.md): a name no DEF declared, an array index outside the array, a jump whose
  // label or block number is not in the program, a type that does not take the value.
  UndefinedName,
  ArrayIndex,
  JumpTarget,
  TypeMismatch,
  // DIN control structures: an ENDIF, ELSE, ENDWHILE ... without its opening, an opening
  // without its end; nested deeper than kMaxStructures.
  StructureNesting,
  StructureDepth,
  // DIN subprograms: more arguments than the PROC has parameters; a VAR parameter given no
  // variable; a PROC that is not the first block of its program.
  TooManyArguments,
  ArgumentNotVariable,
  ProcPlacement,
  // DIN: DEF of a name the program (or subprogram) has declared already; SET or REP with more
  // values than the array has elements left.
  NameDefinedTwice,
  TooManyValues,
  kCount,
};

struct Failure {
  EvalError error = EvalError::VariableNumber;
  SourceLocation loc;
  std::string message;
  // UserAlarm: the alarm number the program raised (#3000 = n maps to it per dialect).
  int64_t user_code = 0;
};

}  // namespace ncc::eval
