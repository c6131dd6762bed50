#include "lowering_harness.h"

#include <sstream>
#include <variant>

#include "absl/strings/str_cat.h"
#include "ncc/frontend/block_reader.h"
#include "ncc/machine/machine_file.h"
#include "ncc/passes/dialect_table.h"
#include "ncc/passes/lowering.h"
#include "ncc/passes/pass_manager.h"

namespace ncc::passes::test {

namespace {
class Collect : public ir::BlockSink {
 public:
  explicit Collect(Lowered& run) : run_(run) {}
  void accept(ir::Block&& block) override {
    for (const ir::Operation& op : block.ops) {
      Move m;
      m.line = static_cast<int>(block.loc.line);
      if (auto* r = std::get_if<ir::Rapid>(&op)) {
        m.kind = "rapid";
        m.to = r->to;
      } else if (auto* l = std::get_if<ir::Linear>(&op)) {
        m.kind = "line";
        m.to = l->to;
        m.feed = l->feed;
      } else if (auto* a = std::get_if<ir::Arc>(&op)) {
        m.kind = "arc";
        m.to = a->to;
        m.center = a->center;
        m.cw = a->clockwise;
        m.feed = a->feed;
      } else if (auto* d = std::get_if<ir::Dwell>(&op)) {
        m.kind = "dwell";
        m.seconds = d->seconds;
      } else {
        continue;
      }
      run_.moves.push_back(m);
    }
    run_.blocks.push_back(std::move(block));
  }
  void finish() override {}

 private:
  Lowered& run_;
};
}  // namespace

std::string Lowered::diagText() const {
  std::string out;
  for (const Diagnostic& d : diags)
    absl::StrAppend(&out, d.location.line, ":", d.location.column, ": ",
                    d.severity == Severity::Error ? "error" : "warning", "[", d.code, "]: ",
                    d.message, "\n");
  return out;
}

std::string xyzMachine(const std::string& params, const std::string& extra) {
  return absl::StrCat("[machine]\naxes = [\"X\", \"Y\", \"Z\"]\n", extra,
                      "[machine.work]\nG54 = [0.0, 0.0, 0.0]\n[machine.params]\n", params,
                      "\n[start]\nposition = { X = 0.0, Y = 0.0, Z = 0.0 }\n");
}

namespace {
Lowered lowerWith(Dialect dialect, const std::string& program, const std::string& machine_toml,
                  const RunTimeState* run_time, bool with_reader) {
  Lowered run;
  SourceManager sources;
  DiagnosticEngine diags(&sources);
  MachineConfig machine = defaultMachine();
  if (!machine_toml.empty()) {
    auto parsed = parseMachineFile(machine_toml, "machine.toml", sources, diags);
    if (!parsed) {
      run.diags = diags.diagnostics();
      return run;
    }
    machine = *parsed;
  }
  uint32_t file = sources.addBuffer("test.nc", program);
  Collect collect(run);
  PipelineOptions pipeline;
  pipeline.axis_count = machine.axisCount();
  pipeline.dialect = dialect;
  pipeline.verify_each = true;  // tests verify the IR after every pass
  PassManager passes(pipeline, diags, collect);
  LoweringOptions options;
  options.dialect = dialect;
  options.machine = &machine;
  options.run_time = run_time;
  Lowering lowering(options, diags, passes.entry());
  uint32_t line = 0;
  std::string_view rest = program;
  frontend::ReaderOptions reader_options;
  reader_options.semicolon_ends_block = dialect != Dialect::SiemensIsoM;
  reader_options.language_switch = languageTables(dialect).din != nullptr;
  frontend::BlockReader reader(sources, file, diags, reader_options);
  for (;;) {
    std::optional<ast::Block> block;
    if (with_reader) {
      if (!(block = reader.next())) break;
    } else {
      if (rest.empty()) break;
      size_t eol = rest.find('\n');
      std::string_view text = rest.substr(0, eol);
      rest = eol == std::string_view::npos ? std::string_view() : rest.substr(eol + 1);
      ++line;
      // The end-of-block ';' (FANUC) or the annotation after it (Siemens ISO) is the block
      // reader's business; parseIsoBlock reads one block without it.
      text = text.substr(0, text.find(';'));
      block = frontend::parseIsoBlock(text, file, line, diags);
      if (!block) continue;
    }
    LowerResult r = lowering.lower(*block);
    if (r.needs_run_time) {
      run.run_time = r.needs_run_time;
      break;
    }
    if (r.program_end) {
      run.program_end = true;
      break;
    }
  }
  lowering.finish();
  run.diags = diags.diagnostics();
  return run;
}
}  // namespace

Lowered lower(Dialect dialect, const std::string& program, const std::string& machine_toml,
              const RunTimeState* run_time) {
  return lowerWith(dialect, program, machine_toml, run_time, false);
}

Lowered lowerRead(Dialect dialect, const std::string& program, const std::string& machine_toml) {
  return lowerWith(dialect, program, machine_toml, nullptr, true);
}

}  // namespace ncc::passes::test
