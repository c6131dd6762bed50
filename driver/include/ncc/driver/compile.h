#pragma once
// The compile pipeline: frontend (block by block) -> lowering -> passes -> a final IR sink.
// Everything streams: memory does not grow with program length.
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "ncc/driver/session.h"
#include "ncc/ir/ir.h"

namespace ncc::driver {

// The debugging controls of the pass pipeline (docs/cli.md "Passes"): `--print-after`,
// `--stop-after`, `--verify-each`. Names are those of pipelineStages().
struct PassControl {
  std::vector<std::string> print_after;  // print the IR as it leaves each of these passes
  std::string stop_after;                // empty: every pass runs
  bool verify_each = false;              // the IR verifier after every pass, not only at the end
};

// Whose pipeline: `ncc compile` (lower, work-to-machine) or `ncc check` (the same, then the
// travel check).
enum class Pipeline { Compile, Check };

// The names of the passes `pipeline` runs, in order: the stages before lowering (on AST
// blocks), `lower`, then the IR passes.
std::vector<std::string> pipelineStages(Pipeline pipeline);
// Why `control` does not fit `pipeline` (an unknown name, a pass it does not run, one not
// built yet, a print after the stop), or nullopt. The CLI reports it as NCC0015.
std::optional<std::string> checkPassControl(const PassControl& control, Pipeline pipeline);

// Runs frontend, lowering and passes, delivering machine-space IR blocks to `sink`.
// Returns true when no error was reported.
bool compileToSink(Session& session, ir::BlockSink& sink);

// `ncc check`: the whole pipeline up to the backend, keeping only the diagnostics. With
// `control.print_after`, the IR after those passes goes to `print_out`.
bool check(Session& session, const PassControl& control = {}, std::ostream* print_out = nullptr);

// `ncc compile --emit=ast`: the parsed blocks printed back, one per line.
bool emitAst(Session& session, std::ostream& out);
// `ncc compile --emit=ir`: the IR after all passes (after `control.stop_after`), as text; with
// `control.print_after`, instead the IR as it leaves each of those passes, under
// `; after PASS` lines.
bool emitIr(Session& session, std::ostream& out, const PassControl& control = {});
// Bytecode into a stream (seekable: the section table is patched at the end). Of `control`
// only verify_each applies (the backend needs every pass).
bool emitBytecode(Session& session, std::ostream& out, const PassControl& control = {});

}  // namespace ncc::driver
