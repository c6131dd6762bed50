#pragma once
// The variables file of `--vars FILE`: the common variables a controller keeps through
// power-off (#500-#999 on FANUC, every common on Mazak: MacroRules::persistent_first), kept
// from one run to the next. A TOML table of `"#n" = value`:
//
//     "#500" = 12.5
//     "#501" = -3.0
//
// `ncc run --vars F` loads it before compiling and, after a run that ends without an alarm,
// writes it back with the values the program left; `ncc compile`/`ncc check` only load it.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "ncc/driver/session.h"
#include "ncc/eval/macro_rules.h"
#include "ncc/support/diagnostics.h"
#include "ncc/support/source_location.h"

namespace ncc::driver {

struct SavedVariable {
  double value = 0.0;
  SourceLocation where;  // its key in the file, for diagnostics
};

// The file's variables; a file that does not exist yet is empty (the first run creates it).
// nullopt after reporting NCC0017 (unreadable, not TOML, a key that is not `#n`, a value that
// is not a finite number).
std::optional<std::map<int64_t, SavedVariable>> readVariablesFile(
    const std::filesystem::path& path, SourceManager& sources, DiagnosticEngine& diags);

// Writes `values` in the file's format, in variable order.
void writeVariablesFile(std::ostream& out, const std::map<int64_t, double>& values);

// The variables among a run's end state (`#n` -> value) that the session's controller keeps
// through power-off.
std::map<int64_t, double> persistentVariables(
    const Session& session, const std::vector<std::pair<std::string, double>>& variables);

}  // namespace ncc::driver
