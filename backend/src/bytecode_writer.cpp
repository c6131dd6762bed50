#include "ncc/backend/bytecode_writer.h"

#include <cmath>
#include <utility>
#include <variant>
#include <filesystem>

#include "absl/strings/str_cat.h"
#include "ncc/backend/encode.h"
#include "ncc/ir/verifier.h"

namespace ncc::backend {

namespace {

bytecode::Header headerFor(const MachineConfig& machine, Dialect dialect) {
  bytecode::Header header;
  header.dialect = dialect;
  header.config_hash = machine.configHash();
  for (const AxisConfig& axis : machine.axes) header.axes.push_back({axis.name, axis.kind});
  return header;
}

}  // namespace

BytecodeWriter::BytecodeWriter(std::ostream& out, const MachineConfig& machine, Dialect dialect,
                               const SourceManager& sources, DiagnosticEngine* diags)
    : machine_(machine),
      sources_(sources),
      diags_(diags),
      writer_(out, headerFor(machine, dialect)) {
  if (writer_.error()) error(writer_.error()->code, {}, writer_.error()->message);
}

void BytecodeWriter::error(std::string code, SourceLocation where, std::string message) {
  ok_ = false;
  if (diags_ != nullptr) diags_->error(std::move(code), where, std::move(message));
}

void BytecodeWriter::accept(ir::Block&& block) {
  if (!ok_ || finished_) return;
#ifdef NCC_VERIFY_IR
  std::vector<std::string> problems =
      ir::verify(block, ir::VerifyOptions{machine_.axisCount(), /*require_machine_space=*/true});
  if (!problems.empty()) {
    for (const std::string& p : problems)
      error("NCC9001", block.loc, absl::StrCat("internal error: invalid IR: ", p));
    return;
  }
#endif
  if (block.ops.empty()) return;
  if (block.loc.file > sources_.fileCount()) {
    error("NCC9001", block.loc,
          absl::StrCat("internal error: block from unknown source file ", block.loc.file));
    return;
  }
  if (!main_file_) main_file_ = block.loc.file;
  writer_.addLine(block.loc.file, block.loc.line, block.loc.column);
  for (const ir::Operation& op : block.ops) encode(op, block);
  if (writer_.error()) error(writer_.error()->code, block.loc, writer_.error()->message);
}

void BytecodeWriter::encode(const ir::Operation& op, const ir::Block& block) {
  if (const auto* prepare = std::get_if<ir::Prepare>(&op)) blocks_ = prepare->store;
  if (const auto* set = std::get_if<ir::SetVariable>(&op); set && !set->name.empty())
    variable_names_.try_emplace(set->number, set->name.str());
  const EncodedOperation code = encodeOperation(op, block, machine_);
  if (code.error) {
    error(code.error->first, block.loc, code.error->second);
    return;
  }
  for (int i = 0; i < code.count; ++i) {
    if (std::optional<std::string> beyond = outOfBounds(code.instructions[i], machine_)) {
      error("NCC7017", block.loc, *beyond);
      return;
    }
  }
  for (int i = 0; i < code.count; ++i) writer_.emit(code.instructions[i]);
}

void BytecodeWriter::finish() {
  if (finished_) return;
  finished_ = true;
  if (!ok_) return;
  bytecode::Instruction end;
  end.op = bytecode::Opcode::End;
  writer_.emit(end);
  // String i is the name of source file i, so line-table file indices are the compiler's ids.
  // Only the file's own name: the file then does not depend on how its path was spelled
  // (a.nc, ./a.nc, /abs/a.nc), and it is the name the moves JSON prints.
  std::vector<std::string> strings;
  for (uint32_t file = 0; file <= sources_.fileCount(); ++file)
    strings.push_back(file == 0 ? std::string()
                                : std::filesystem::path(sources_.displayName(file))
                                      .filename()
                                      .string());
  uint32_t main = main_file_.value_or(sources_.fileCount() >= 1 ? 1 : 0);
  if (main >= strings.size()) main = 0;
  std::span<const uint8_t> blocks;
  if (blocks_) blocks = *blocks_;
  // Named variables (DIN): their names follow the file names in the pool.
  std::vector<bytecode::VariableName> names;
  for (const auto& [number, name] : variable_names_) {
    names.push_back({number, static_cast<uint32_t>(strings.size())});
    strings.push_back(name);
  }
  if (std::optional<bytecode::Error> e =
          writer_.finish(strings, {bytecode::Unit{0, main}}, blocks, names))
    error(e->code, {}, e->message);
}

}  // namespace ncc::backend
