#include "block_preparation.h"

#include <utility>

#include "absl/strings/str_cat.h"
#include "ncc/backend/encode.h"
#include "ncc/eval/block_store.h"
#include "ncc/machine/signals.h"
#include "ncc/passes/pass_manager.h"
#include "ncc/passes/run_time_state.h"
#include "ncc/prepare/block_loop.h"

namespace ncc::vm {

struct BlockPreparation::Impl final : passes::RunTimeState, ir::BlockSink {
  Impl(const bytecode::Program& program, const MachineConfig& machine_config,
       RunningMachine running_machine, eval::BlockStore decoded)
      : machine(machine_config),
        running_(std::move(running_machine)),
        store(std::move(decoded)),
        programs(store),
        pipeline(pipelineOptions(program), diags, *this),
        loop(settings(program), programs, store.main_file, diags, pipeline.entry()) {}

  passes::PipelineOptions pipelineOptions(const bytecode::Program& program) const {
    passes::PipelineOptions options;
    options.axis_count = machine.axisCount();
    options.dialect = program.header.dialect;
    return options;
  }
  prepare::Settings settings(const bytecode::Program& program) {
    prepare::Settings s;
    s.dialect = program.header.dialect;
    s.machine = &machine;
    s.limits = store.limits;
    s.run_time = this;
    return s;
  }

  // passes::RunTimeState
  bool running() const override { return !replaying; }
  AxisValues machinePosition() const override { return running_.position(); }
  double seconds() const override { return running_.seconds(); }
  eval::Value skipVariable(int64_t number) const override {
    return number > 0 ? running_.variable(static_cast<uint32_t>(number)) : eval::Value::none();
  }
  std::optional<eval::Value> machineVariable(int64_t number) const override {
    if (number >= kFirstInputSignal && number <= kLastInputSignal)
      return eval::Value::of(inputSignalValue(machine.signals, number));
    return std::nullopt;  // timers, servo lag: not simulated
  }

  // ir::BlockSink: the pipeline's IR, encoded as the backend encodes it ahead of time.
  void accept(ir::Block&& block) override {
    if (replaying) return;
    const SourcePosition where = block.loc;
    for (const ir::Operation& op : block.ops) {
      if (const auto* set = std::get_if<ir::SetVariable>(&op); set && !set->name.empty())
        variable_names.try_emplace(set->number, set->name.str());
      if (std::holds_alternative<ir::Prepare>(op)) {
        fail("NCC9001", where, "internal error: a block prepared at run time asks to be prepared at run time");
        return;
      }
      const backend::EncodedOperation code = backend::encodeOperation(op, block, machine);
      if (code.error) {
        fail(code.error->first, where, code.error->second);
        return;
      }
      for (int i = 0; i < code.count; ++i) {
        if (std::optional<std::string> beyond = backend::outOfBounds(code.instructions[i], machine)) {
          fail("NCC7017", where, *beyond);
          return;
        }
        out->push_back({code.instructions[i], where});
      }
    }
  }
  void finish() override {}

  void fail(std::string code, SourcePosition where, std::string message) {
    diags.error(std::move(code), where, std::move(message));
  }
  // The first error reported since `before` errors, as an alarm.
  std::optional<Alarm> alarmSince(size_t before) const {
    if (diags.errorCount() <= before) return std::nullopt;
    for (const Diagnostic& d : diags.diagnostics())
      if (d.severity == Severity::Error && before-- == 0) return Alarm{d.code, d.message, d.location};
    return Alarm{"NCC7205", "block preparation failed", {}};
  }

  MachineConfig machine;
  RunningMachine running_;
  eval::BlockStore store;
  eval::StoredProgramStore programs;
  DiagnosticEngine diags;
  passes::PassManager pipeline;
  prepare::BlockLoop loop;
  bool replaying = true;
  bool ended = false;
  std::optional<Alarm> pending_alarm;
  std::vector<PreparedInstruction>* out = nullptr;
  std::map<uint32_t, std::string> variable_names;
};

BlockPreparation::BlockPreparation(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
BlockPreparation::~BlockPreparation() = default;

std::unique_ptr<BlockPreparation> BlockPreparation::create(const bytecode::Program& program,
                                                           const MachineConfig& machine,
                                                           RunningMachine running,
                                                           std::string& error) {
  std::optional<eval::BlockStore> store = eval::decodeBlockStore(program.blocks, error);
  if (!store) return nullptr;
  bool has_main = false;
  for (const eval::StoredFile& f : store->files) has_main |= f.id == store->main_file;
  if (!has_main) {
    error = absl::StrCat("the block store has no main program file (", store->main_file, ")");
    return nullptr;
  }
  auto impl = std::make_unique<Impl>(program, machine, std::move(running), std::move(*store));
  // The variables --vars loaded when the program was compiled, as the compiler loaded them
  // (their writes reach the executor with the first block prepared, or were in the code).
  for (const auto& [n, v] : impl->store.saved_variables)
    if (!impl->loop.variables().setPersistent(n, v, SourceLocation{})) {
      error = absl::StrCat("#", n, " of the saved variables is not a persistent variable");
      return nullptr;
    }
  // The blocks before PREPARE: prepared again as the compiler prepared them, so that the
  // controller model and the variables are where the compiler left them.
  std::vector<PreparedInstruction> discarded;
  impl->out = &discarded;
  for (uint64_t i = 0; i < impl->store.ahead_blocks; ++i) {
    if (impl->loop.step() != prepare::Step::Block || impl->diags.hasErrors()) {
      error = absl::StrCat("the block store does not replay the ", impl->store.ahead_blocks,
                           " blocks prepared ahead of time (it stopped after ", i, ")");
      return nullptr;
    }
  }
  impl->replaying = false;
  return std::unique_ptr<BlockPreparation>(new BlockPreparation(std::move(impl)));
}

const std::map<uint32_t, std::string>& BlockPreparation::variableNames() const {
  return impl_->variable_names;
}

void BlockPreparation::boundIdleBlocks(uint64_t max_steps) {
  eval::LoopLimits limits = impl_->store.limits;
  if (max_steps > 0 && (limits.max_idle_blocks == 0 || max_steps < limits.max_idle_blocks))
    limits.max_idle_blocks = max_steps;
  impl_->loop.evaluator().setLimits(limits);
}

bool BlockPreparation::next(std::vector<PreparedInstruction>& out, std::optional<Alarm>& alarm) {
  Impl& p = *impl_;
  out.clear();
  p.out = &out;
  if (p.pending_alarm) {
    alarm = std::exchange(p.pending_alarm, std::nullopt);
    return false;
  }
  while (out.empty() && !p.ended) {
    const size_t errors = p.diags.errorCount();
    const prepare::Step step = p.loop.step();
    if (step != prepare::Step::Block) {
      p.ended = true;
      p.loop.finish();  // the last variable writes
    }
    if (step == prepare::Step::RunTime)
      p.fail("NCC9001", p.loop.runTimeReason().loc,
             absl::StrCat("internal error: a value the VM cannot give: ",
                          p.loop.runTimeReason().message));
    if (std::optional<Alarm> raised = p.alarmSince(errors)) {
      p.ended = true;
      if (out.empty()) {
        alarm = std::move(raised);
        return false;
      }
      p.pending_alarm = std::move(raised);  // after what the block before it prepared
    }
  }
  return !out.empty();
}

}  // namespace ncc::vm
