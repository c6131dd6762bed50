#include "ncc/driver/compile.h"

#include "absl/strings/str_cat.h"
#include "ncc/backend/bytecode_writer.h"
#include "ncc/frontend/block_reader.h"
#include "ncc/ir/printer.h"
#include "ncc/passes/lowering.h"
#include "ncc/passes/pass_manager.h"

namespace ncc::driver {

namespace {

frontend::ReaderOptions readerOptionsFor(Dialect dialect) {
  frontend::ReaderOptions options;
  // FANUC and Mazak end a block at ';' (EOB); the Siemens ISO manual uses ';' to start an
  // annotation that runs to the end of the line.
  options.semicolon_ends_block = dialect != Dialect::SiemensIsoM;
  return options;
}

ir::AxisNames axisNames(const MachineConfig& machine) {
  ir::AxisNames names;
  for (const AxisConfig& axis : machine.axes) names.push_back(axis.name);
  return names;
}

// Reads blocks and lowers them until the end of the program. After M02/M30 the rest of the file
// is still read, so its syntax errors are reported (a FANUC file often carries subprograms
// there), but nothing more is lowered. A '%' after the program's first block is the end of the
// record (the tape ends there): nothing after it is read, and text there draws a warning.
void lowerProgram(Session& session, ir::BlockSink& entry) {
  frontend::BlockReader reader(session.sources(), session.mainFile(), session.diagnostics(),
                               readerOptionsFor(session.dialect()));
  passes::LoweringOptions options;
  options.dialect = session.dialect();
  options.machine = &session.machine();
  options.program_dir = session.programDir();
  passes::Lowering lowering(options, session.diagnostics(), entry);
  bool program_ended = false;
  bool seen_content = false;
  while (std::optional<ast::Block> block = reader.next()) {
    if (block->percent && seen_content) {
      while (std::optional<ast::Block> after = reader.next()) {
        if (!after->empty()) {
          session.diagnostics().warning(
              "NCC0020", after->loc,
              "text after the closing '%' is not part of the program and is ignored");
          break;
        }
      }
      break;
    }
    if (session.blockObserver()) session.blockObserver()(block->loc);
    seen_content = seen_content || !block->empty();
    if (program_ended) continue;
    passes::LowerResult result = lowering.lower(*block);
    if (result.switch_language) reader.setLanguage(*result.switch_language);
    program_ended = result.program_end;
  }
  lowering.finish();
}

}  // namespace

bool compileToSink(Session& session, ir::BlockSink& sink) {
  passes::PipelineOptions options;
  options.axis_count = session.machine().axisCount();
  passes::PassManager pipeline(options, session.diagnostics(), sink);
  lowerProgram(session, pipeline.entry());
  return !session.diagnostics().hasErrors();
}

bool check(Session& session) {
  // Discards the IR; every pass and the IR verifier still run, so their diagnostics appear.
  struct DiscardingSink : ir::BlockSink {
    void accept(ir::Block) override {}
    void finish() override {}
  } discard;
  return compileToSink(session, discard);
}

bool emitAst(Session& session, std::ostream& out) {
  frontend::BlockReader reader(session.sources(), session.mainFile(), session.diagnostics(),
                               readerOptionsFor(session.dialect()));
  while (std::optional<ast::Block> block = reader.next()) out << frontend::printBlock(*block) << '\n';
  return !session.diagnostics().hasErrors();
}

bool emitIr(Session& session, std::ostream& out) {
  ir::PrintingSink printer(out, axisNames(session.machine()));
  return compileToSink(session, printer);
}

bool emitBytecode(Session& session, std::ostream& out) {
  backend::BytecodeWriter writer(out, session.machine(), session.dialect(), session.sources(),
                                 &session.diagnostics());
  bool ok = compileToSink(session, writer);
  return ok && writer.ok() && !session.diagnostics().hasErrors();
}

}  // namespace ncc::driver
