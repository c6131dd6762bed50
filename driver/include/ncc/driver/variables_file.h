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

// The largest variables file read: a controller keeps at most a few thousand variables, a few
// hundred KiB of TOML; a bigger file is not one (docs/cli.md, NCC0019).
inline constexpr uint64_t kMaxVariablesFileBytes = uint64_t{16} << 20;

// Why `path` cannot be read as a variables file: not a regular file (a device such as
// /dev/zero, a FIFO, a folder), larger than kMaxVariablesFileBytes, or not readable. nullopt
// when it can, and when it does not exist (the first run creates it). Checks without reading:
// a FIFO is never opened for reading (that would wait for a writer).
std::optional<std::string> variablesFileProblem(const std::filesystem::path& path);

// The file's variables; a file that does not exist yet is empty (the first run creates it).
// nullopt after reporting NCC0017 (unreadable, not a regular file, over the size limit, not
// TOML, a key that is not `#n`, a value that is not a finite number). Reads at most
// kMaxVariablesFileBytes, whatever the file turns out to be.
std::optional<std::map<int64_t, SavedVariable>> readVariablesFile(
    const std::filesystem::path& path, SourceManager& sources, DiagnosticEngine& diags);

// Writes `values` in the file's format, in variable order.
void writeVariablesFile(std::ostream& out, const std::map<int64_t, double>& values);

// The variables among a run's end state (`#n` -> value) that the session's controller keeps
// through power-off.
std::map<int64_t, double> persistentVariables(
    const Session& session, const std::vector<std::pair<std::string, double>>& variables);

}  // namespace ncc::driver
