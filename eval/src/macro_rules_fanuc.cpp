// FANUC Custom Macro B (fanuc-m, fanuc-t). The manual ncc has for FANUC is the 30i lathe
// volume (fanuc-30i-lathe.ja.txt), which leaves Custom Macro to the common volume: it states
// only that `#1=2500` then `P#1` is `P2500` (§4.2.8) and the Series 15 M98 format (§6.2).
// The other values are the FANUC limits commonly documented for Custom Macro B; they are
// marked "FANUC common" below. None of the macro alarm numbers (PS0076, PS0112, ...) appear
// in that volume, so every error keeps its NCC code until a manual states the number.
#include "macro_rules_tables.h"

namespace ncc::eval::tables {

namespace {

constexpr VariableRange kCommons[] = {{100, 199}, {500, 999}};  // FANUC common
// FANUC common: #3000 = n (0-200) shows alarm 3000 + n.
constexpr MacroRules::UserAlarmRange kUserAlarms[] = {{0, 200, 3000}};

}  // namespace

constinit const MacroRules kFanucRules{
    .dialect = Dialect::FanucM,
    .alarm_codes = kNccCodes,
    .local_count = 33,
    .commons = kCommons,
    .common_sets = {},
    .persistent_first = 500,    // FANUC common: #100-#199 clear at power-off, #500- are kept
    .max_magnitude = 1e47,      // FANUC common: values from 1e-29 to 1e47 in magnitude
    .max_bracket_depth = 5,     // FANUC common: five levels including function brackets
    .variable_number_rounding = Rounding::Nearest,  // FANUC common: rounded to an integer
    // FANUC common: "a variable's value used at an address is rounded to the address's
    // least significant digit" (M#1 with #1 = 3.5 is M4).
    .address_rounding = Rounding::Nearest,
    .max_do_id = 3,             // FANUC common: DO1-DO3
    .max_do_nesting = 3,
    .max_call_nesting = 15,     // FANUC common (30i): subprogram + macro calls
    .max_macro_nesting = 5,     // FANUC common (30i): macro calls among them
    .goto_search = SequenceSearch::ForwardThenFromStart,
    .return_search = SequenceSearch::ForwardThenFromStart,
    // §6.2: the native format has no L ("本 CNC の指令フォーマットではアドレス L は使用できま
    // せん"): M98 P<count 4><program 4>; L is read only in the Series 15 format (FCV = 1).
    .repeat = RepeatEncoding::HighDigitsOfP,
    .program_number_digits = 4,  // §6.2: program numbers 1-9999
    .user_alarms = kUserAlarms,
    .argument_spec1 = kArgumentSpec1,
    .program_file_names = kIsoProgramFiles,
};

}  // namespace ncc::eval::tables
