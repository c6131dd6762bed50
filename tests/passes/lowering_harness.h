#pragma once
// Test harness: a machine from TOML text (a conformance case's [machine]/[start] tables),
// program lines parsed with frontend::parseIsoBlock, lowered and moved to machine space, and
// the result flattened into a move list like a conformance case's `moves`.
#include <optional>
#include <string>
#include <vector>

#include "ncc/ir/ir.h"
#include "ncc/machine/machine_config.h"
#include "ncc/machine/dialect.h"
#include "ncc/passes/run_time_state.h"
#include "ncc/eval/failure.h"
#include "ncc/support/diagnostics.h"
#include "ncc/support/source_manager.h"

namespace ncc::passes::test {

struct Move {
  std::string kind;        // rapid | line | arc | dwell
  AxisValues to{};         // machine coordinates
  AxisValues center{};
  bool cw = false;
  double feed = 0.0;
  double seconds = 0.0;
  int line = 0;
};

struct Lowered {
  std::vector<ir::Block> blocks;  // machine space
  std::vector<Move> moves;
  std::vector<Diagnostic> diags;
  bool program_end = false;
  // The first block that needs a value known only at run time (the compiler stops there).
  std::optional<eval::Failure> run_time;

  std::string diagText() const;  // "line:col: error[CODE]: message" per diagnostic
};

// `machine_toml`: [machine] ... [start] ... ; empty -> defaultMachine().
// `run_time`: the running machine, as the VM's block preparation gives it (null: the compiler).
Lowered lower(Dialect dialect, const std::string& program, const std::string& machine_toml = "",
              const RunTimeState* run_time = nullptr);
// The same with the program read by frontend::BlockReader as the compiler reads it for the
// dialect (';' and G290/G291 by the dialect's rules), not line by line.
Lowered lowerRead(Dialect dialect, const std::string& program, const std::string& machine_toml);

// A [machine] table with X Y Z, G54 at zero, and the given [machine.params] lines.
std::string xyzMachine(const std::string& params = "", const std::string& extra = "");

}  // namespace ncc::passes::test
