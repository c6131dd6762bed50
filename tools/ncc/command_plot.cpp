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
#include "ncc/support/diagnostics.h"

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

// The moves of a simulation of `program`, recorded for the drawing.
struct Drawn {
  std::vector<driver::PlotMove> moves;
  driver::SimulationResult sim;
};

Drawn simulateForPlot(const bytecode::Program& program, const MachineConfig& machine,
                      const PlotArgs& args) {
  driver::PlotRecorder recorder;
  driver::SimulationOptions options;
  options.max_steps = args.max_steps;
  options.max_seconds = args.max_time;
  options.observer = &recorder;
  Drawn drawn;
  drawn.sim = driver::simulate(program, machine, nullptr, options);
  drawn.moves = recorder.finish();
  return drawn;
}

// --from/--to: the moves of those lines of the main program's file only.
void keepLines(std::vector<driver::PlotMove>& moves, const bytecode::Program& program,
               const PlotArgs& args) {
  if (!args.from_line && !args.to_line) return;
  const uint32_t main = program.units.empty() ? 1 : program.units[0].name;
  std::erase_if(moves, [&](const driver::PlotMove& m) {
    const vm::SourcePosition& w = m.motion.where;
    return w.file != main || (args.from_line && w.line < args.from_line) ||
           (args.to_line && w.line > args.to_line);
  });
}

// The programmed path of a program with cutter compensation: the session's program compiled
// again with compensation off, and run (up to its own alarm, if any: the verdict is the
// compensated program's). nullopt when there is none to draw: that compile failed, or it left
// blocks to the VM, whose block preparation compensates them all the same.
std::optional<Drawn> programmedPath(driver::Session& session, const MachineConfig& machine,
                                    const PlotArgs& args, bytecode::Program& program) {
  session.diagnostics().clear();
  session.setCompensate(false);
  const bool loaded = driver::loadProgram(session, program, /*check_machine=*/true,
                                          driver::Residence::Paged);
  session.setCompensate(true);
  // Its warnings were the first compile's, printed already.
  session.diagnostics().clear();
  if (!loaded || session.compileFacts().prepared_at_run_time) return std::nullopt;
  Drawn drawn = simulateForPlot(program, machine, args);
  if (!drawn.sim.error.empty()) return std::nullopt;
  return drawn;
}

// Where a compile alarm at `at` is marked on the programmed path: the end of the first move
// of its line, else of the last move of an earlier line of its file, else the start.
AxisValues alarmPlace(const std::vector<driver::PlotMove>& moves, const SourceLocation& at,
                      const AxisValues& start) {
  AxisValues place = start;
  for (const driver::PlotMove& m : moves) {
    const vm::SourcePosition& w = m.motion.where;
    if (w.file != at.file) continue;
    if (w.line == at.line) return m.motion.to;
    if (w.line < at.line) place = m.motion.to;
  }
  return place;
}

int runPlot(const PlotArgs& args) {
  if (args.from_line && args.to_line && args.from_line > args.to_line) {
    printError("NCC0010", absl::StrCat("--from ", args.from_line, " is after --to ", args.to_line));
    return kUsage;
  }
  driver::Session session;
  MachineConfig machine;
  bytecode::Program program;
  // The compile stopped on this error of a program with cutter compensation (an interference,
  // no intersection): when the program compiles without compensation, its programmed path is
  // drawn with the alarm marked on it, and the verdict stays the compile's.
  std::optional<Diagnostic> compile_alarm;
  if (std::optional<int> failed =
          loadForRun(session, args.input, args.common, args.run, machine, program)) {
    if (*failed != kProgramError || !session.compileFacts().cutter_comp) return *failed;
    for (const Diagnostic& d : session.diagnostics().diagnostics())
      if (d.severity == Severity::Error) {
        compile_alarm = d;
        break;
      }
    if (!compile_alarm) return *failed;
  }
  // Compensation: the programmed path too (not from a .ncb: its source is not at hand).
  bytecode::Program programmed_program;
  std::optional<Drawn> programmed;
  if (compile_alarm || (session.compileFacts().cutter_comp &&
                        !session.compileFacts().prepared_at_run_time)) {
    programmed = programmedPath(session, machine, args, programmed_program);
    if (compile_alarm && !programmed) return kProgramError;  // as without compensation
  }
  // Opened after the compile: the inputs then include the called subprograms (NCC0005).
  PendingOutput output;
  if (!output.open(args.output, session.inputFiles())) return kUsage;

  // The same simulation as ncc run (executor, planner, servo): the same alarms, one verdict.
  Drawn run;
  if (!compile_alarm) {
    run = simulateForPlot(program, machine, args);
    if (!run.sim.error.empty()) {
      const driver::SimulationResult& sim = run.sim;
      const std::size_t colon = sim.error.find(": ");
      if (colon == std::string::npos) printError("NCC7100", sim.error);
      else printError(sim.error.substr(0, colon), sim.error.substr(colon + 2));
      return kProgramError;
    }
  }
  // The drawing's names come from the program run, or the programmed one when none ran.
  const bytecode::Program& named = compile_alarm ? programmed_program : program;
  keepLines(run.moves, named, args);

  driver::PlotOptions plot;
  plot.views = parseViews(args.view);
  parseSize(args.size, plot.width, plot.height);  // checked by the option's validator
  const uint32_t main = named.units.empty() ? 1 : named.units[0].name;
  plot.title = driver::sourceFileName(named, main);
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
  plot.alarm = run.sim.alarm;
  if (programmed) {
    if (compile_alarm) {
      // Source ids are the program's file indices (one session compiled both).
      plot.alarm = vm::Alarm{compile_alarm->code, compile_alarm->message, compile_alarm->location};
      plot.alarm_at = alarmPlace(programmed->moves, compile_alarm->location, plot.start);
    }
    keepLines(programmed->moves, named, args);
    plot.programmed = std::move(programmed->moves);
  }
  plot.file_name = [&named](uint32_t index) { return driver::sourceFileName(named, index); };
  driver::writePlotSvg(output.stream(), run.moves, plot);
  const bool written = output.commit();
  if (compile_alarm) return written ? kProgramError : kUsage;  // its diagnostics are printed
  const std::optional<vm::Alarm>& alarm = run.sim.alarm;
  if (alarm) {
    SourceLocation where{0, alarm->where.line, alarm->where.column};
    if (alarm->where.file < program.strings.size() && !program.strings[alarm->where.file].empty())
      where.file = session.sources().addFile(program.strings[alarm->where.file]);
    session.diagnostics().error(alarm->code, where, alarm->message);
    printDiagnostics(session);
  }
  if (!written) return kUsage;
  return alarm ? kRuntimeAlarm : kOk;
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
  addRunLimitOptions(*cmd, args->max_steps, args->max_time);
  args->run.addTo(*cmd, "AXIS=VALUE: the simulated skip signal of G31, as for ncc run (repeatable)",
                  "N=VALUE: an interface input signal, as for ncc run (repeatable)");
  args->common.addTo(*cmd);
  cmd->callback([args, &exit_code] { exit_code = runPlot(*args); });
}

}  // namespace ncc::cli
