// The names of the pipeline's passes and the checks of --print-after / --stop-after
// (driver::PassControl), and the stages before lowering (ast_stages.h).
#include <algorithm>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "ast_stages.h"
#include "ncc/driver/compile.h"
#include "ncc/frontend/block_reader.h"
#include "ncc/passes/pass_manager.h"

namespace ncc::driver {

namespace {

constexpr AstStage kAstStages[] = {
    {"evaluate", "Macro B evaluation: variables, expressions, control flow, calls", /*built=*/true},
};

const char* commandName(Pipeline pipeline) {
  return pipeline == Pipeline::Check ? "ncc check" : "ncc compile";
}

// The IR passes of a command's pipeline; the machine is a stand-in, only its presence counts.
std::vector<std::string_view> irPasses(Pipeline pipeline) {
  static const MachineConfig any_machine;
  passes::PipelineOptions options;
  if (pipeline == Pipeline::Check) options.travel_limits = &any_machine;
  return passes::PassManager::passNames(options);
}

bool contains(const std::vector<std::string>& names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// Why `name` (given to `option`) is not a pass of `pipeline`, or "".
std::string unknownPass(const std::string& option, const std::string& name, Pipeline pipeline,
                        const std::vector<std::string>& stages) {
  if (contains(stages, name)) return "";
  std::string listed = absl::StrCat("; the passes of ", commandName(pipeline), ": ",
                                    absl::StrJoin(stages, ", "));
  if (const AstStage* stage = findAstStage(name); stage && !stage->built)
    return absl::StrCat(option, ": pass '", name, "' (", std::string(stage->summary),
                        ") is not built yet", listed);
  Pipeline other = pipeline == Pipeline::Check ? Pipeline::Compile : Pipeline::Check;
  if (contains(pipelineStages(other), name))
    return absl::StrCat(option, ": pass '", name, "' does not run in ", commandName(pipeline),
                        " (only in ", commandName(other), ")", listed);
  return absl::StrCat(option, ": no pass is named '", name, "'", listed);
}

}  // namespace

std::span<const AstStage> astStages() { return kAstStages; }

const AstStage* findAstStage(std::string_view name) {
  for (const AstStage& stage : kAstStages)
    if (stage.name == name) return &stage;
  return nullptr;
}

bool AstStageTap::after(std::string_view stage, const ast::Block& block) {
  if (printer_ && contains(control_.print_after, stage))
    printer_->printLine(stage, frontend::printBlock(block));
  if (control_.stop_after != stage) return true;
  // The command's output when it prints nothing else (as --emit=ir writes the last IR).
  if (stop_out_ && control_.print_after.empty()) *stop_out_ << frontend::printBlock(block) << '\n';
  return false;
}

void AstStageTap::finish() {
  if (!printer_) return;
  for (const AstStage& stage : kAstStages)
    if (contains(control_.print_after, stage.name)) printer_->finish(stage.name);
}

std::vector<std::string> pipelineStages(Pipeline pipeline) {
  std::vector<std::string> names;
  for (const AstStage& stage : kAstStages)
    if (stage.built) names.emplace_back(stage.name);
  for (std::string_view pass : irPasses(pipeline)) names.emplace_back(pass);
  return names;
}

std::optional<std::string> checkPassControl(const PassControl& control, Pipeline pipeline) {
  std::vector<std::string> stages = pipelineStages(pipeline);
  if (!control.stop_after.empty()) {
    std::string why = unknownPass("--stop-after", control.stop_after, pipeline, stages);
    if (!why.empty()) return why;
  }
  for (const std::string& name : control.print_after) {
    std::string why = unknownPass("--print-after", name, pipeline, stages);
    if (!why.empty()) return why;
    if (control.stop_after.empty()) continue;
    auto at = [&](std::string_view n) { return std::find(stages.begin(), stages.end(), n); };
    if (at(name) > at(control.stop_after))
      return absl::StrCat("--print-after: pass '", name,
                          "' does not run: the pipeline stops after '", control.stop_after,
                          "' (--stop-after)");
  }
  return std::nullopt;
}

}  // namespace ncc::driver
