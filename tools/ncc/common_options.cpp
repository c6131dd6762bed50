#include <cmath>
#include <iostream>

#include "absl/strings/str_cat.h"
#include "cli.h"

namespace ncc::cli {

void printError(std::string_view code, std::string_view message) {
  std::cerr << "ncc: error[" << code << "]: " << message << '\n';
}

namespace {

// --max-time: a finite number of seconds, not negative (CLI::Range lets NaN through).
CLI::Validator nonNegativeNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double v = 0.0;
        if (!CLI::detail::lexical_cast(text, v) || !std::isfinite(v) || v < 0.0 || v > 1e12)
          return "'" + text + "' is not a number of seconds from 0 to 1e12";
        return {};
      },
      "SECONDS");
}

// --max-steps: digits only (a "-1" would wrap around to the largest count).
CLI::Validator nonNegativeInteger() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
          return "'" + text + "' is not a whole number from 0 up";
        return {};
      },
      "N");
}

}  // namespace

void CommonOptions::addTo(CLI::App& command) {
  command.add_option("--dialect", dialect,
                     "fanuc-m | fanuc-t | mazak-m | siemens-iso-m | siemens-din "
                     "(default: .mpf/.spf -> siemens-din, else fanuc-m)");
  command.add_option("--machine", machine_file, "machine file (TOML); default: 3-axis metric mill");
  command.add_option("--program-dir", program_dir,
                     "where called subprograms are looked up (default: the program's folder)");
  command.add_option("--max-time", bounds.max_seconds,
                     "stop with alarm NCC7208 after this many seconds of simulated time (0: no "
                     "limit; default 360000, 100 h); the compile stops there too, and a block "
                     "that cannot end before it stops the run at once")
      ->check(nonNegativeNumber());
  command.add_option("--max-steps", bounds.max_steps,
                     "stop with alarm NCC7204 after this many VM instructions (0: no limit; "
                     "default 100000000); the compile stops there too")
      ->check(nonNegativeInteger());
  command.add_option("--max-idle-blocks", loop_limits.max_idle_blocks,
                     "blocks run without a move or a dwell before a loop is stopped as endless "
                     "(NCC2419 at its jump back; default 100000000)")
      ->check(CLI::Range(uint64_t{1}, uint64_t{1'000'000'000'000'000}));
  command.add_option("--max-back-jumps", loop_limits.max_back_jumps,
                     "jumps back (GOTO, END, M99) before a program is stopped (NCC2419; "
                     "default: no limit)")
      ->check(CLI::Range(uint64_t{1}, uint64_t{1'000'000'000'000}));
  command.add_option("--vars", vars_file,
                     "variables file: the persistent common variables (#500.. on FANUC) loaded "
                     "before compiling; ncc run writes them back after a run without alarm");
  command.add_flag("--defer", defer,
                   "prepare every block in the VM while the program runs, as it is done from "
                   "the first block that needs a run-time value (docs/runtime.md)");
}

std::optional<std::string> CommonOptions::toSessionOptions(driver::SessionOptions& out) const {
  if (!dialect.empty()) {
    std::optional<Dialect> d = parseDialect(dialect);
    if (!d) {
      return absl::StrCat("unknown dialect '", dialect,
                          "' (expected fanuc-m, fanuc-t, mazak-m, siemens-iso-m or siemens-din)");
    }
    out.dialect = *d;
  }
  if (!machine_file.empty()) out.machine_file = machine_file;
  if (!program_dir.empty()) out.program_dir = program_dir;
  out.loop_limits = loop_limits;
  out.bounds = bounds;
  out.bound_action = bound_action;
  if (!vars_file.empty()) out.variables_file = vars_file;
  out.defer = defer;
  return std::nullopt;
}

void printDiagnostics(driver::Session& session) { session.diagnostics().print(std::cerr); }

std::optional<int> openSession(driver::Session& session, const std::filesystem::path& input,
                               const CommonOptions& common) {
  driver::SessionOptions options;
  if (std::optional<std::string> error = common.toSessionOptions(options)) {
    printError("NCC0002", *error);
    return kUsage;
  }
  if (std::optional<driver::SetupError> error = session.open(input, options)) {
    printDiagnostics(session);
    printError(error->code, error->message);
    return kUsage;
  }
  return std::nullopt;
}

}  // namespace ncc::cli
