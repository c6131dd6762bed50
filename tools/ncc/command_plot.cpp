// `ncc plot IN [-o OUT.svg] [--view top|front|side|iso|all] [--size WxH] [--from LINE]
// [--to LINE]`: the path the program runs, drawn as SVG (docs/cli.md, "ncc plot").
#include <charconv>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "cli.h"
#include "run_input.h"
#include "pending_output.h"
#include "progress.h"
#include "ncc/driver/json_output.h"
#include "ncc/driver/plot.h"
#include "ncc/driver/run.h"
#include "ncc/driver/simulate.h"

namespace ncc::cli {

namespace {

struct PlotArgs {
  CommonOptions common;
  std::string input;
  std::string output;
  std::string view = "all";
  std::string size = "1200x900";
  uint32_t from_line = 0;  // 0: from the start
  uint32_t to_line = 0;    // 0: to the end
  uint64_t max_steps = driver::kDefaultMaxSteps;
  double max_time = vm::kDefaultMaxRunSeconds;
  RunInput run;  // --probe, --signal
};

constexpr int kMinSize = 200, kMaxSize = 20000;  // px

// "WxH" in pixels, each kMinSize..kMaxSize.
bool parseSize(const std::string& text, int& width, int& height) {
  const std::size_t x = text.find('x');
  if (x == std::string::npos) return false;
  const auto number = [](std::string_view s, int& value) {
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    return ec == std::errc() && ptr == s.data() + s.size() && value >= kMinSize && value <= kMaxSize;
  };
  const std::string_view all(text);
  return number(all.substr(0, x), width) && number(all.substr(x + 1), height);
}

std::vector<driver::PlotView> parseViews(const std::string& view) {
  using driver::PlotView;
  if (view == "top") return {PlotView::Top};
  if (view == "front") return {PlotView::Front};
  if (view == "side") return {PlotView::Side};
  if (view == "iso") return {PlotView::Iso};
  return {PlotView::Top, PlotView::Iso, PlotView::Front, PlotView::Side};
}

int runPlot(const PlotArgs& args) {
  if (args.from_line && args.to_line && args.from_line > args.to_line) {
    printError("NCC0010", absl::StrCat("--from ", args.from_line, " is after --to ", args.to_line));
    return kUsage;
  }
  driver::Session session;
  MachineConfig machine;
  bytecode::Program program;
  if (std::optional<int> failed =
          loadForRun(session, args.input, args.common, args.run, machine, program))
    return *failed;
  // Opened after the compile: the inputs then include the called subprograms (NCC0005).
  PendingOutput output;
  if (!output.open(args.output, session.inputFiles())) return kUsage;

  // The same simulation as ncc run (executor, planner, servo): the same alarms, one verdict.
  driver::PlotRecorder recorder;
  driver::SimulationOptions options;
  options.max_steps = args.max_steps;
  options.max_seconds = args.max_time;
  options.observer = &recorder;
  driver::SimulationResult sim = driver::simulate(program, machine, nullptr, options);
  if (!sim.error.empty()) {
    const std::size_t colon = sim.error.find(": ");
    if (colon == std::string::npos) printError("NCC7100", sim.error);
    else printError(sim.error.substr(0, colon), sim.error.substr(colon + 2));
    return kProgramError;
  }
  std::vector<driver::PlotMove> moves = recorder.finish();
  // --from/--to: the moves of those lines of the main program's file only.
  if (args.from_line || args.to_line) {
    const uint32_t main = program.units.empty() ? 1 : program.units[0].name;
    std::erase_if(moves, [&](const driver::PlotMove& m) {
      const vm::SourcePosition& w = m.motion.where;
      return w.file != main || (args.from_line && w.line < args.from_line) ||
             (args.to_line && w.line > args.to_line);
    });
  }

  driver::PlotOptions plot;
  plot.views = parseViews(args.view);
  parseSize(args.size, plot.width, plot.height);  // checked by the option's validator
  const uint32_t main = program.units.empty() ? 1 : program.units[0].name;
  plot.title = driver::sourceFileName(program, main);
  if (plot.title.empty()) plot.title = session.sources().displayName(session.mainFile());
  if (args.from_line || args.to_line)
    absl::StrAppend(&plot.title, ", lines ", args.from_line ? args.from_line : 1, " to ",
                    args.to_line ? absl::StrCat(args.to_line) : std::string("the end"));
  plot.x_axis = machine.axisIndex("X");
  plot.y_axis = machine.axisIndex("Y");
  plot.z_axis = machine.axisIndex("Z");
  if (auto it = machine.work_offsets.find("G54"); it != machine.work_offsets.end())
    plot.work_zero = it->second;
  plot.start = machine.start_position;
  plot.alarm = sim.alarm;
  plot.file_name = [&program](uint32_t index) { return driver::sourceFileName(program, index); };
  driver::writePlotSvg(output.stream(), moves, plot);
  const bool written = output.commit();
  if (sim.alarm) {
    SourceLocation where{0, sim.alarm->where.line, sim.alarm->where.column};
    if (sim.alarm->where.file < program.strings.size() &&
        !program.strings[sim.alarm->where.file].empty())
      where.file = session.sources().addFile(program.strings[sim.alarm->where.file]);
    session.diagnostics().error(sim.alarm->code, where, sim.alarm->message);
    printDiagnostics(session);
  }
  if (!written) return kUsage;
  return sim.alarm ? kRuntimeAlarm : kOk;
}

}  // namespace

void addPlotCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<PlotArgs>();
  CLI::App* cmd = app.add_subcommand(
      "plot", "draw the path a program runs as SVG: top, front, side and isometric views");
  cmd->add_option("input", args->input, "program source or .ncb file (-: the standard input)")->required();
  cmd->add_option("-o,--output", args->output, "the SVG file (default or -: stdout)");
  cmd->add_option("--view", args->view, "top, front, side, iso, or all (a 2x2 layout)")
      ->check(CLI::IsMember({"top", "front", "side", "iso", "all"}))
      ->capture_default_str();
  cmd->add_option("--size", args->size, "WxH: the drawing's size in pixels, each 200..20000")
      ->check(CLI::Validator(
          [](std::string& text) {
            int w = 0, h = 0;
            return parseSize(text, w, h) ? std::string()
                                         : "expected WxH, each a whole number 200..20000";
          },
          "WxH"))
      ->capture_default_str();
  cmd->add_option("--from", args->from_line,
                  "draw only the moves of this line of the main program's file and after")
      ->check(CLI::Range(uint32_t{1}, uint32_t{4'000'000'000}));
  cmd->add_option("--to", args->to_line,
                  "draw only the moves of this line of the main program's file and before")
      ->check(CLI::Range(uint32_t{1}, uint32_t{4'000'000'000}));
  cmd->add_option("--max-steps", args->max_steps,
                  "stop with alarm NCC7204 after this many VM instructions (0: no limit)")
      ->capture_default_str();
  cmd->add_option("--max-time", args->max_time,
                  "stop with alarm NCC7208 after this many seconds of simulated time (0: no limit)")
      ->check(CLI::Range(0.0, 1e12))
      ->capture_default_str();
  args->run.addTo(*cmd, "AXIS=VALUE: the simulated skip signal of G31, as for ncc run (repeatable)",
                  "N=VALUE: an interface input signal, as for ncc run (repeatable)");
  args->common.addTo(*cmd);
  cmd->callback([args, &exit_code] { exit_code = runPlot(*args); });
}

}  // namespace ncc::cli
