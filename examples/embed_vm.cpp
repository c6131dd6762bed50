// Embedding the ncc VM in a controller loop: load a compiled program (.ncb) and, optionally, a
// machine file, then run the real-time loop: Controller::tick() at the start of each IPO cycle
// (the setpoint, quickly), Controller::prepare() in the rest of the cycle (the look-ahead). A
// real controller would send `out.commanded` to its drives; this example prints every 100th
// tick and the statistics.
//
//   example_embed_vm part.ncb [machine.toml]
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "ncc/machine/machine_file.h"
#include "ncc/vm/controller.h"

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: %s PROGRAM.ncb [MACHINE.toml]\n", argv[0]);
    return 2;
  }

  // The machine: the built-in 3-axis mill, or a machine file (errors printed like compile
  // diagnostics).
  ncc::MachineConfig machine = ncc::defaultMachine();
  if (argc == 3) {
    ncc::SourceManager sources;
    ncc::DiagnosticEngine diags(&sources);
    std::optional<ncc::MachineConfig> read = ncc::loadMachineFile(argv[2], sources, diags);
    if (!read) {
      diags.print(std::cerr);
      return 1;
    }
    machine = *read;
  }

  // Load + verify; everything the run needs is allocated here, none of it in the loop.
  ncc::bytecode::Error error;
  ncc::vm::ControllerOptions options;
  options.prepare_in_tick = false;  // this loop calls prepare() itself, after each tick
  std::unique_ptr<ncc::vm::Controller> ctl =
      ncc::vm::Controller::loadFile(argv[1], machine, error, options);
  if (!ctl) {
    std::fprintf(stderr, "%s: error[%s]: %s\n", argv[1], error.code.c_str(), error.message.c_str());
    return 1;
  }

  // The real-time loop: one tick per IPO cycle. The setpoint first (bounded, short), then the
  // preparation, which may take longer and only has to be done before the next cycle.
  const int axes = ctl->axisCount();
  ncc::vm::TickOutput out;
  ctl->prepare();  // fill the look-ahead before the machine moves
  while (ctl->tick(out) == ncc::vm::TickStatus::Running) {
    ctl->prepare();
    if (out.tick % 100 != 0) continue;
    std::printf("t=%8.3f s  line %5u ", out.time, out.where.line);
    for (int i = 0; i < axes; ++i)
      std::printf(" %s %9.4f", machine.axes[i].name.c_str(), out.commanded[i]);
    std::printf("  F %8.1f mm/min\n", out.path_velocity * 60.0);
  }

  const ncc::vm::RunStatistics s = ctl->statistics();
  std::printf("program time        %.3f s\n", s.program_time);
  std::printf("path length         %.3f mm (%.3f feed, %.3f rapid)\n", s.path_length,
              s.feed_length, s.rapid_length);
  std::printf("max following error");
  for (int i = 0; i < axes; ++i)
    std::printf(" %s %.4f", machine.axes[i].name.c_str(), s.max_following_error[i]);
  std::printf(" mm\nmax contour error   %.4f mm (t = %.3f s)\n", s.max_contour_error,
              static_cast<double>(s.max_contour_error_tick) * ctl->cycleSeconds());
  std::printf("limit violations    %lld\n", static_cast<long long>(s.limit_violations));
  if (const ncc::vm::Alarm* alarm = ctl->alarm()) {
    std::printf("alarm %s at line %u: %s\n", alarm->code.c_str(), alarm->where.line,
                alarm->message.c_str());
    return 3;
  }
  return 0;
}
