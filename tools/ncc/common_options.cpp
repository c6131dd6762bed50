#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iostream>

#include "absl/strings/str_cat.h"
#include "cli.h"
#include "ncc/driver/variables_file.h"

namespace ncc::cli {

void printError(std::string_view code, std::string_view message) {
  std::cerr << "ncc: error[" << code << "]: " << message << '\n';
}

void CommonOptions::addTo(CLI::App& command) {
  command.add_option("--dialect", dialect,
                     "fanuc-m | fanuc-t | mazak-m | siemens-iso-m | siemens-din "
                     "(default: .mpf/.spf -> siemens-din, else fanuc-m)");
  command.add_option("--machine", machine_file, "machine file (TOML); default: 3-axis metric mill");
  command.add_option("--program-dir", program_dir,
                     "where called subprograms are looked up (default: the program's folder)");
  addRunLimitOptions(command, bounds.max_steps, bounds.max_seconds);
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

void addRunLimitOptions(CLI::App& command, uint64_t& max_steps, double& max_time) {
  command
      .add_option("--max-steps", max_steps,
                  "stop with alarm NCC7204 after this many VM instructions (0: no limit); the "
                  "compile stops there too")
      ->check(CLI::Validator(
          [](std::string& text) {
            // The conversion to an unsigned number would take -1 as 2^64-1: no limit at all.
            const std::size_t first = text.find_first_not_of(" \t");
            return first != std::string::npos && text[first] == '-'
                       ? "'" + text + "' is negative: expected a count of VM instructions, "
                                        "0 (no limit) or more"
                       : std::string();
          },
          "N >= 0"))
      ->capture_default_str();
  command
      .add_option("--max-time", max_time,
                  "stop the simulated run with alarm NCC7208 after this many seconds of "
                  "simulated time (0: no limit); also at once when a block cannot end before "
                  "it, and the compile stops there too")
      ->check(CLI::Validator(
          [](std::string& text) {
            // The option's own conversion, then the value: NaN passes any range check.
            double seconds = 0.0;
            if (CLI::detail::lexical_cast(text, seconds) && std::isfinite(seconds) &&
                seconds >= 0.0 && seconds <= 1e12)
              return std::string();
            return absl::StrCat("'", text,
                                "' is no time limit: expected seconds of simulated time, a "
                                "finite number from 0 (no limit) to 1e12");
          },
          "SECONDS >= 0"))
      ->capture_default_str();
}

void printDiagnostics(driver::Session& session) { session.diagnostics().print(std::cerr); }

std::optional<int> openSession(driver::Session& session, const std::filesystem::path& input,
                               const CommonOptions& common) {
  driver::SessionOptions options;
  if (std::optional<std::string> error = common.toSessionOptions(options)) {
    printError("NCC0002", *error);
    return kUsage;
  }
  // Checked before anything is read: /dev/zero would be read until memory runs out, a FIFO
  // waited on forever.
  if (!common.vars_file.empty()) {
    if (std::optional<std::string> why = driver::variablesFileProblem(common.vars_file)) {
      printError("NCC0019", absl::StrCat("cannot read the variables file '", common.vars_file,
                                         "': ", *why));
      return kUsage;
    }
  }
  if (std::optional<driver::SetupError> error = session.open(input, options)) {
    printDiagnostics(session);
    printError(error->code, error->message);
    return kUsage;
  }
  // The standard input is read through stdio, whose read errors (an I/O error, a folder
  // redirected to it) end the stream as if it were empty: an empty program must not run.
  if (input == driver::kStdinName && std::ferror(stdin)) {
    struct stat st {};
    const bool folder = fstat(STDIN_FILENO, &st) == 0 && S_ISDIR(st.st_mode);
    printError("NCC0001", folder ? "cannot read the standard input: it is a folder"
                                 : "cannot read the standard input: a read error");
    return kUsage;
  }
  return std::nullopt;
}

}  // namespace ncc::cli
