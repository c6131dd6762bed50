#include "ncc/prepare/block_loop.h"

#include <cctype>
#include <charconv>
#include <map>
#include <string>
#include <utility>

#include "absl/strings/str_cat.h"
#include "ncc/bytecode/format.h"
#include "ncc/passes/dialect_table.h"

namespace ncc::prepare {

namespace {

passes::LoweringOptions loweringOptions(const Settings& settings) {
  passes::LoweringOptions options;
  options.dialect = settings.dialect;
  options.machine = settings.machine;
  options.program_dir = settings.program_dir;
  options.run_time = settings.run_time;
  return options;
}

}  // namespace

std::map<std::string, std::string> codeMacros(const MachineConfig& machine) {
  std::map<std::string, std::string> out;
  for (const char* param : {"g_code_macros", "m_code_macros"})
    if (const ParamStringTable* t = machine.params.getStringTable(param))
      for (const auto& [code, program] : t->by_key) {
        int64_t n = 0;
        std::from_chars(code.data() + 1, code.data() + code.size(), n);
        out[absl::StrCat(std::string(1, static_cast<char>(std::toupper(
                                            static_cast<unsigned char>(code[0])))),
                         n)] = program;
      }
  return out;
}

eval::RepeatEncoding repeatEncoding(const eval::MacroRules& rules, const MachineConfig& machine) {
  return machine.params.getBool("eight_digit_program_numbers", false)
             ? eval::RepeatEncoding::LAddress
             : rules.repeat;
}

std::vector<eval::VariableRange> commonVariables(const eval::MacroRules& rules,
                                                 const MachineConfig& machine) {
  std::span<const eval::VariableRange> ranges = rules.commons;
  if (const eval::MacroRules::CommonSet* set =
          rules.commonSet(machine.params.getString("common_variables", "")))
    ranges = set->ranges;
  return std::vector<eval::VariableRange>(ranges.begin(), ranges.end());
}

BlockLoop::BlockLoop(const Settings& settings, eval::ProgramStore& store, uint32_t main_file,
                     DiagnosticEngine& diags, ir::BlockSink& out)
    : progress_(out),
      lowering_(loweringOptions(settings), diags, progress_),
      variables_(eval::macroRules(settings.dialect),
                 commonVariables(eval::macroRules(settings.dialect), *settings.machine),
                 &lowering_.systemVariables()) {
  const eval::MacroRules& rules = eval::macroRules(settings.dialect);
  // Writes between two lowered blocks reach the IR as one block holding each variable's last
  // value: a loop of assignments that runs a million turns adds nothing per turn.
  variables_.on_write = [this](int64_t n, const eval::Value& v, SourceLocation loc) {
    if (n <= 0 || n > eval::NamedVariables::kLastNumber) return;
    const uint32_t number = static_cast<uint32_t>(n);
    auto [it, added] = write_index_.try_emplace(number, writes_.size());
    if (added) {
      ir::SetVariable& write = writes_.emplace_back();
      write.number = number;
      // A DIN variable's name, looked up once per block of writes.
      if (number >= bytecode::kDefaultVariableCount) {
        write.name = variables_.named().nameOf(number);
        if (write.name.empty()) {
          writes_.pop_back();
          write_index_.erase(it);
          return;
        }
      }
    }
    writes_loc_ = loc;
    ir::SetVariable& write = writes_[it->second];
    write.value = v.vacant ? 0.0 : v.number;
    write.vacant = v.vacant;
  };
  const MachineConfig& machine = *settings.machine;
  eval::EvaluatorOptions options;
  options.rules = &rules;
  options.repeat = repeatEncoding(rules, machine);
  options.limits = settings.limits;
  options.skipped = [this](const ast::Block& b) { return lowering_.skips(b); };
  options.is_axis = [&machine](std::string_view a) {
    return machine.axisIndex(std::string(a)) >= 0;
  };
  options.argument_value = [this](const ast::Word& w) { return lowering_.argumentValue(w); };
  options.real_increment = [this] { return lowering_.leastIncrement(); };
  options.address_digits = lowering_.addressDigits();
  options.code_macros = codeMacros(machine);
  options.language_switch = passes::languageTables(settings.dialect).din != nullptr;
  options.figure_rotation.begin = [this](const std::array<std::optional<double>, 3>& ijk) {
    return lowering_.figureRotationBegin(ijk);
  };
  options.figure_rotation.run = [this](int64_t run) { lowering_.figureRotationRun(run); };
  options.figure_rotation.end = [this] { lowering_.figureRotationEnd(); };
  evaluator_ = std::make_unique<eval::Evaluator>(std::move(options), store,
                                                 store.open(main_file), variables_, diags);
}

BlockLoop::~BlockLoop() = default;

eval::Variables& BlockLoop::variables() { return variables_; }

void BlockLoop::flushWrites() {
  if (writes_.empty()) return;
  write_index_.clear();
  lowering_.variablesWritten(writes_loc_, std::exchange(writes_, {}));
}

void BlockLoop::ProgressTap::accept(ir::Block&& block) {
  for (const ir::Operation& op : block.ops) moved |= advances(op);
  next.accept(std::move(block));
}

// A move to where the tool already is takes no time: a loop of such moves (a macro run with
// vacant arguments) is as endless as one without moves.
bool BlockLoop::ProgressTap::advances(const ir::Operation& op) {
  if (const auto* d = std::get_if<ir::Dwell>(&op)) return d->seconds > 0.0;
  if (std::holds_alternative<ir::HoleCycle>(op)) return true;
  const AxisValues* to = nullptr;
  const ir::Arc* arc = std::get_if<ir::Arc>(&op);
  if (const auto* r = std::get_if<ir::Rapid>(&op)) to = &r->to;
  if (const auto* l = std::get_if<ir::Linear>(&op)) to = &l->to;
  if (const auto* s = std::get_if<ir::Skip>(&op)) to = &s->to;
  if (arc) to = &arc->to;
  if (!to) return false;
  const bool same = *to == at;
  at = *to;
  return !same || (arc && arc->center != *to);  // an arc back to its start: a full circle
}

Step BlockLoop::step() {
  const ast::Block* block = evaluator_->next();
  if (!block) {
    if (evaluator_->end() == eval::ProgramEnd::RunTime) {
      // The writes of the block that stopped: it is evaluated again where it runs.
      writes_.clear();
      write_index_.clear();
      run_time_reason_ = evaluator_->runTimeReason();
      return Step::RunTime;
    }
    flushWrites();
    return Step::End;
  }
  flushWrites();
  if (evaluator_->rejectedBlocks() != unreadable_) {
    unreadable_ = evaluator_->rejectedBlocks();
    lowering_.blockUnreadable();
  }
  if (on_block) on_block(*block);
  passes::LowerResult result = lowering_.lower(*block);
  if (progress_.moved) {
    progress_.moved = false;
    evaluator_->madeProgress();
  }
  if (result.needs_run_time) {
    run_time_reason_ = std::move(*result.needs_run_time);
    return Step::RunTime;
  }
  ++steps_;
  if (result.program_end) {
    evaluator_->programEndCode();
    return Step::End;
  }
  return Step::Block;
}

void BlockLoop::finish() {
  flushWrites();
  lowering_.finish();
}

}  // namespace ncc::prepare
