#pragma once
// The backend: machine-space IR blocks -> bytecode (docs/bytecode.md), streamed. Each block's operations are
// encoded as they arrive, straight into the output stream; the line table is spooled to a
// temporary file (bytecode/writer.h), so memory does not grow with program length. finish()
// appends END, the line table, the string pool (the name, without folders, of every source file
// of the SourceManager, indexed by file id) and the unit table, then patches the header.
// A value the verifier would refuse (a coordinate, arc centre, dwell or turn count beyond the
// bounds of bytecode/format.h) is reported here as NCC7017 at its block, so the compiler never
// writes a file the VM will not run.
#include <map>
#include <memory>
#include <optional>
#include <vector>
#include <string>
#include <ostream>

#include "ncc/bytecode/writer.h"
#include "ncc/ir/ir.h"
#include "ncc/machine/dialect.h"
#include "ncc/machine/machine_config.h"
#include "ncc/support/diagnostics.h"
#include "ncc/support/source_manager.h"

namespace ncc::backend {

class BytecodeWriter : public ir::BlockSink {
 public:
  // `diags` receives NCC7017 (a value beyond the format's bounds), internal errors (NCC9001 invalid IR such as a work-space target, NCC9003
  // arc plane without its axes) and write errors (NCC70xx); nullptr keeps only ok().
  BytecodeWriter(std::ostream& out, const MachineConfig& machine, Dialect dialect,
                 const SourceManager& sources, DiagnosticEngine* diags = nullptr);

  void accept(ir::Block&& block) override;
  void finish() override;

  // False once any error was found; the output is then not a valid program.
  bool ok() const { return ok_; }

 private:
  void error(std::string code, SourceLocation where, std::string message);
  void encode(const ir::Operation& op, const ir::Block& block);

  const MachineConfig& machine_;
  const SourceManager& sources_;
  DiagnosticEngine* diags_;
  bytecode::StreamWriter writer_;
  std::optional<uint32_t> main_file_;  // file of the first block: names the main unit
  std::shared_ptr<const std::vector<uint8_t>> blocks_;  // of ir::Prepare: after the units
  std::map<uint32_t, std::string> variable_names_;      // of named ir::SetVariable
  bool ok_ = true;
  bool finished_ = false;
};

}  // namespace ncc::backend
