// Sinumerik 840Di ISO mode (siemens-840di-iso-milling-gcode.ja.txt; notes §4.9, §4.11, §6).
// The manual has no `#` macro language ("the manual does not define variable ranges,
// null/vacant values, precision, operators, IF/WHILE"): where it is silent the FANUC values
// apply (macro_rules_fanuc.cpp). What it states: calls, files, repeat counts, M99 P.
#include "macro_rules_tables.h"

namespace ncc::eval::tables {

namespace {

constexpr VariableRange kCommons[] = {{100, 199}, {500, 999}};
constexpr MacroRules::UserAlarmRange kUserAlarms[] = {{0, 200, 3000}};
// §2 / §4.11: "M98 P21 searches 21.mpf; in zero-pad mode P20012 is 0012.mpf"; subprograms
// are .spf files (conformance: 1234.spf, 0010.spf).
constexpr std::string_view kFiles[] = {"{:04}.spf", "{}.spf", "{:04}.mpf", "{}.mpf"};

// The DIN text of the same control (G290, or the siemens-din dialect) raises the Sinumerik NCK
// alarms (Diagnostics Manual; the cycles notes §6 cite the 12xxx range): 12550 "name not
// defined", 17020 "illegal array index", 14080 "jump destination not found", 12150 "operation
// not compatible with data type", 12170 "name defined several times", 12260 "too many
// initialization values", 12640 "invalid nesting of control structures", 12641
// "nesting depth of control structures too large", 12320 "parameter is not a variable", 12340
// "number of parameters too high". The ISO-mode errors keep the NCC codes
// (§6 numbers none).
constexpr std::array<std::string_view, kNccCodes.size()> alarms() {
  auto a = kNccCodes;
  a[static_cast<size_t>(EvalError::UndefinedName)] = "12550";
  a[static_cast<size_t>(EvalError::ArrayIndex)] = "17020";
  a[static_cast<size_t>(EvalError::JumpTarget)] = "14080";
  a[static_cast<size_t>(EvalError::TypeMismatch)] = "12150";
  a[static_cast<size_t>(EvalError::NameDefinedTwice)] = "12170";
  a[static_cast<size_t>(EvalError::TooManyValues)] = "12260";
  a[static_cast<size_t>(EvalError::StructureNesting)] = "12640";
  a[static_cast<size_t>(EvalError::StructureDepth)] = "12641";
  a[static_cast<size_t>(EvalError::ArgumentNotVariable)] = "12320";
  a[static_cast<size_t>(EvalError::TooManyArguments)] = "12340";
  return a;
}
constexpr auto kAlarms = alarms();

}  // namespace

constinit const MacroRules kSiemensIsoRules{
    .dialect = Dialect::SiemensIsoM,
    .alarm_codes = kAlarms,  // §6: subprogram not found and nesting > 4 have no number
    .local_count = 33,
    .commons = kCommons,
    .common_sets = {},
    .persistent_first = 500,
    .max_magnitude = 1e47,
    .max_bracket_depth = 5,
    .variable_number_rounding = Rounding::Nearest,
    .address_rounding = Rounding::Nearest,
    .max_do_id = 3,
    .max_do_nesting = 3,
    .max_call_nesting = 4,   // §4.3: "nesting is limited to 4 levels, more is an error"
    .max_macro_nesting = 4,  // G65/G66 are among the 4 (no separate limit stated)
    // DIN: 16 program levels, the main program one of them (Programming Manual
    // Fundamentals, subprogram technique: nesting depth).
    .max_named_call_nesting = 15,
    .goto_search = SequenceSearch::ForwardThenFromStart,
    // §4.3: M99 P n searches "forward from the call block to the end, then from the start".
    .return_search = SequenceSearch::ForwardThenFromStart,
    // §4.3: M98 P<count up to 3 digits><program 4 digits> (EXTERN_FUNCTION_MASK bit6 = 0;
    // with bit6 = 1 P is the program and L the count: the caller reads that parameter).
    .repeat = RepeatEncoding::HighDigitsOfP,
    .program_number_digits = 4,
    .user_alarms = kUserAlarms,
    .argument_spec1 = kArgumentSpec1,  // §4.10 type I: G L N O P are not arguments
    .program_file_names = kFiles,
};

}  // namespace ncc::eval::tables
