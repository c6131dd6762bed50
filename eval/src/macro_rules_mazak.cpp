// Mazak FUSION 640M EIA/ISO (mazak-fusion640m-eia-iso.fr.txt; notes §4.7, §4.8, §6).
#include <limits>

#include "macro_rules_tables.h"

namespace ncc::eval::tables {

namespace {

constexpr std::array<std::string_view, kNccCodes.size()> alarms() {
  auto a = kNccCodes;
  auto set = [&a](EvalError e, std::string_view code) { a[static_cast<size_t>(e)] = code; };
  // §13-9-5 table row 20: "#103 = LN[-5] -> Alarme 860 CALCUL IMPOSSIBLE". The manual names
  // no other alarm for an impossible calculation; a division by zero is one (inferred).
  set(EvalError::Domain, "860");
  set(EvalError::DivisionByZero, "860");
  set(EvalError::GotoTarget, "843");       // §13-9-6: "NUMERO DE SOUS-PROGR. NON TR."
  set(EvalError::ProgramNotFound, "844");  // §13-4: "SOUS-PROGRAMME NON TROUVE"
  set(EvalError::CallNesting, "842");      // §13-4: "DEPASS. EMBOIT. SOUS-PROGRAM."
  set(EvalError::ModalCallCancel, "857");  // §13-9-2: "OPER. ERRONEE DU MACRO G67"
  set(EvalError::AddressValue, "809");     // §6: "number: >8 digits" (notes §6)
  set(EvalError::FigureRotationNested, "849");        // §13-7 note 3: "DEPASS. EMBOIT. ROTAT. FIGURE"
  set(EvalError::FigureRotationWithRotation, "850");  // §13-7 note 4: "COMMANDE G68 AVEC M98"
  // Unnumbered in the manual (NCC codes): a negative variable number (§13-6 "provoque une
  // erreur"), #0 on the left (§13-9-3), [ ] deeper than 5, unpaired WHILE/END ("alarm at
  // M99"), DO nesting and identifiers, the 4-level macro nesting (§13-9-2 7.).
  return a;
}
constexpr auto kAlarms = alarms();

// §13-6 B table: type A #100-149 + #500-549 (standard), B #100-199 + #500-599, C #100-199 +
// #500-699, D (option) #100-199 + #500-999. The machine file's common_variables defaults to A.
constexpr VariableRange kSetA[] = {{100, 149}, {500, 549}};
constexpr VariableRange kSetB[] = {{100, 199}, {500, 599}};
constexpr VariableRange kSetC[] = {{100, 199}, {500, 699}};
constexpr VariableRange kSetD[] = {{100, 199}, {500, 999}};
constexpr MacroRules::CommonSet kSets[] = {
    {"A", kSetA}, {"B", kSetB}, {"C", kSetC}, {"D", kSetD}};

// §13-9-4 7.: #3000 = 1..20 shows alarm n + 979 (980-999), 21..6999 shows n + 3000.
constexpr MacroRules::UserAlarmRange kUserAlarms[] = {{1, 20, 979}, {21, 6999, 3000}};

}  // namespace

constinit const MacroRules kMazakRules{
    .dialect = Dialect::MazakM,
    .alarm_codes = kAlarms,
    .local_count = 33,       // §13-9-4 2.: #1-#33 (the table lists #27-#33 without address)
    .commons = kSetA,
    .common_sets = kSets,
    .persistent_first = 100,  // §13-6 B, note 1: common variables survive power-off
    // §13-6: "specify values within 0 to +-99999999; larger values risk incorrect operation"
    // is about the values written, with no alarm; §13-9-5 4. computes with 2345678988888.888.
    // So only an overflow of the number itself is refused.
    .max_magnitude = std::numeric_limits<double>::max(),
    .max_bracket_depth = 5,  // §13-6 and §13-9-5 2.: "jusqu'à cinq fois y compris les fonctions"
    // §13-9-3 example 2: with #10 = 5, #[#10/2] is #2 (2.5 -> 2).
    .variable_number_rounding = Rounding::TowardZero,
    // §2-3 note 6: at D H L M N O S T "the digits after the point are ignored".
    .address_rounding = Rounding::TowardZero,
    .max_do_id = 127,        // §13-9-6 2.: DO1 .. DO127
    .max_do_nesting = 27,    // §13-9-6 2.: "l'emboîtement peut s'effectuer jusqu'à 27 fois"
    .max_call_nesting = 8,   // §13-4: 8 levels counting M98, G65, G66, G66.1 (842)
    .max_macro_nesting = 4,  // §13-9-2 7.: G65/G66/G66.1 "jusqu'à quatre fois"
    // §13-9-6 note: "from the block after IF to the end (%), then from the head of the
    // program up to the block before IF".
    .goto_search = SequenceSearch::ForwardThenFromStart,
    .return_search = SequenceSearch::ForwardThenFromStart,  // M99 P: not stated, as GOTO
    .repeat = RepeatEncoding::LAddress,  // §13-4: M98 P H L, L 1-9999, L0 = skip
    .program_number_digits = 8,          // §13-4: P up to 8 digits
    .figure_rotation = true,             // §13-7: M98 P H I J K L
    .user_alarms = kUserAlarms,
    .argument_spec1 = kArgumentSpec1,    // §13-9-4 table (G L N P only in G66.1, O never)
    .program_file_names = kIsoProgramFiles,
};

}  // namespace ncc::eval::tables
