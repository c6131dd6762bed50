#pragma once
// Reading a machine file (TOML, via toml++). Accepted tables: [machine] (axes, diameter_axes,
// [machine.offsets], [machine.work], [machine.params], [machine.axis.<NAME>] limits) and
// [start] (position). Any other key is an error naming the key, with the file's line and
// column (code NCC0301..; see docs/machine-file.md).
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "ncc/machine/machine_config.h"
#include "ncc/support/diagnostics.h"
#include "ncc/support/source_manager.h"

namespace ncc {

std::optional<MachineConfig> loadMachineFile(const std::filesystem::path& path,
                                             SourceManager& sources, DiagnosticEngine& diags);

// Same, from text already in memory (tests, the conformance runner's extracted tables).
std::optional<MachineConfig> parseMachineFile(std::string_view toml_text, std::string display_name,
                                              SourceManager& sources, DiagnosticEngine& diags);

}  // namespace ncc
