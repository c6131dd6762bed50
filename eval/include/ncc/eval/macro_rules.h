#pragma once
// The data that makes a dialect's macro language: alarm numbers, variable ranges, nesting
// limits, the argument tables of G65/G66 and how subprogram files are named. The evaluator is
// written against this table only (no `if (dialect == ...)`); docs/macro.md lists the values.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ncc/eval/failure.h"
#include "ncc/machine/dialect.h"

namespace ncc::eval {

struct VariableRange {
  int64_t first = 0;
  int64_t last = -1;
  bool contains(int64_t n) const { return n >= first && n <= last; }
};

// How M98 gives a repeat count.
enum class RepeatEncoding : uint8_t {
  LAddress,          // M98 P<program> L<count> (Mazak; FANUC with L)
  HighDigitsOfP,     // M98 P<count><program 4 digits> (FANUC Pnnnnmmmm, Siemens bit6 = 0)
};

// How a value with a fraction becomes a whole number (a variable number, an integer address).
enum class Rounding : uint8_t {
  Nearest,     // half away from zero: 2.5 -> 3, -2.5 -> -3
  TowardZero,  // the fraction is dropped: 2.5 -> 2, -2.5 -> -2
};

// Where GOTO n (and M99 P n) looks for N n.
enum class SequenceSearch : uint8_t {
  ForwardThenFromStart,  // from the block after the GOTO to the end, then from the start
  FromStart,             // from the start of the program
  Forward,               // DIN GOTOF: from the block after the jump to the end
  Backward,              // DIN GOTOB: the nearest before, from the jump's block (included) back
};

struct MacroRules {
  Dialect dialect;
  std::span<const std::string_view> alarm_codes;  // indexed by EvalError
  // Variables.
  int local_count;                          // #1..#local_count, a fresh set per macro call
  std::span<const VariableRange> commons;   // common variables (default set)
  // Other selectable sets of common variables ([machine.params] common_variables "A".."D"
  // on Mazak); empty when the dialect has one set.
  struct CommonSet {
    std::string_view name;
    std::span<const VariableRange> ranges;
  };
  std::span<const CommonSet> common_sets;
  int64_t persistent_first;                 // commons from here on survive a run (--vars)
  double max_magnitude;                     // |value| beyond this is EvalError::ValueRange
  int max_bracket_depth;                    // nesting of [ ] in one expression
  Rounding variable_number_rounding;        // #[#1/2] with #1 = 5: #2 or #3
  // An integer address (M T H D P L N O S) or G given a value with a fraction (M[3.5]).
  Rounding address_rounding;
  // Loops and calls.
  int max_do_id;                            // DO 1 .. DO max_do_id
  int max_do_nesting;
  int max_call_nesting;                     // M98 + G65 + G66 + code calls together
  int max_macro_nesting;                    // G65 / G66 / code calls among them
  // DIN subprograms called by name (siemens-din, and DIN text after G290): 0 where the
  // dialect has no DIN.
  int max_named_call_nesting = 0;
  SequenceSearch goto_search;
  SequenceSearch return_search;             // M99 P n
  RepeatEncoding repeat;
  int program_number_digits;                // the program part of P (4 with HighDigitsOfP)
  // M98 with I J K and L turns each repeat about a centre (Mazak §13-7 figure rotation);
  // false: I J K have no meaning in M98.
  bool figure_rotation = false;
  // #3000 = n: the alarm number shown is n + offset for the first range n lies in.
  struct UserAlarmRange {
    int64_t first, last, offset;
  };
  std::span<const UserAlarmRange> user_alarms;
  // G65 argument specification I: for 'A'..'Z', the local variable it sets (0: not an
  // argument). Specification II (I J K repeated) is derived: #4.. in groups of three.
  std::array<uint8_t, 26> argument_spec1;
  // Subprogram files in the program folder, tried in order; `{}` is the program number,
  // `{:04}` zero-padded to four digits ("O{:04}.nc", "{}.nc", "{:04}.spf").
  std::span<const std::string_view> program_file_names;

  std::string_view alarm(EvalError e) const { return alarm_codes[static_cast<size_t>(e)]; }
  // The alarm number #3000 = n shows (n + offset of its range); nullopt outside every range.
  std::optional<int64_t> userAlarmNumber(int64_t n) const;
  // The file names program `number` may have, in the order of program_file_names, without
  // repeats (1234 -> "O1234.nc", "1234.nc"; 12 -> "O0012.nc", "O12.nc", "0012.nc", "12.nc").
  std::vector<std::string> programFileCandidates(int64_t number) const;
  // The common set named `name` ("A".."D"); nullptr if the dialect has no such set.
  const CommonSet* commonSet(std::string_view name) const;
};

// The rules of a dialect (every dialect has them; those without Macro B use the FANUC values
// until their issue says otherwise).
const MacroRules& macroRules(Dialect dialect);

}  // namespace ncc::eval
