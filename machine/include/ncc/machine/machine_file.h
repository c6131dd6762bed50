#pragma once
// Reading a machine file (TOML, via toml++). Accepted tables: [machine] (axes, diameter_axes,
// ipo_cycle, [machine.offsets], [machine.work], [machine.params], [machine.axis.<NAME>]
// limits) and [start] (position). Any other key is an error naming the key, with the file's
// line and column (codes NCC0300..NCC0306; see docs/machine-file.md). Never throws.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "ncc/machine/machine_config.h"
#include "ncc/support/diagnostics.h"
#include "ncc/support/source_manager.h"

namespace ncc {

struct MachineFileOptions {
  // Read only [machine] and [start] and ignore every other top-level key: lets a conformance
  // case.toml (title, [expect], ...) be loaded as it is, with its own line numbers.
  bool ignore_other_top_level_keys = false;
  // The dialect the programs are read in: `dialect` (the command line's --dialect) when set,
  // else the file's [machine] dialect, else `default_dialect` (from the program's file name).
  // When one is known, a [machine.params] key that has no effect in it (paramApplies) is
  // warning NCC0307 naming the key, at its value.
  std::optional<Dialect> dialect;
  std::optional<Dialect> default_dialect;
};

// Returns the machine, or nullopt after reporting every error found to `diags`.
std::optional<MachineConfig> loadMachineFile(const std::filesystem::path& path,
                                             SourceManager& sources, DiagnosticEngine& diags,
                                             const MachineFileOptions& options = {});

// Same, from text already in memory (tests, the conformance runner's extracted tables).
// The text is registered in `sources` under `display_name`.
std::optional<MachineConfig> parseMachineFile(std::string_view toml_text, std::string display_name,
                                              SourceManager& sources, DiagnosticEngine& diags,
                                              const MachineFileOptions& options = {});

}  // namespace ncc
