// `ncc trace FILE.nct [-o FILE.csv]`: a binary run trace converted to its CSV, the same bytes
// that `ncc run --emit=trace -o FILE.csv` writes for the run (docs/trace.md).
#include <fstream>
#include <iostream>
#include <string>

#include "cli.h"
#include "ncc/driver/trace.h"
#include "pending_output.h"

namespace ncc::cli {

namespace {

int runTrace(const std::string& input, const std::string& output_path) {
  std::ifstream in(input, std::ios::binary);
  if (!in) {
    std::cerr << "ncc: error: cannot read '" << input << "'\n";
    return kUsage;
  }
  PendingOutput output;
  if (!output.open(output_path, {{input, "the run trace"}})) return kUsage;
  driver::TraceReader reader(in);
  if (reader.open()) {
    std::unique_ptr<driver::TraceWriter> csv =
        driver::makeCsvTraceWriter(output.stream(), reader.header());
    driver::TraceRow row;
    while (reader.next(row)) csv->write(row);
    csv->finish();
  }
  if (const std::optional<driver::TraceError>& error = reader.error()) {
    output.discard();
    std::cerr << input << ": error[" << error->code << "]: " << error->message << " (at byte "
              << error->offset << ")\n";
    return kProgramError;
  }
  return output.commit() ? kOk : kUsage;
}

}  // namespace

void addTraceCommand(CLI::App& app, int& exit_code) {
  auto input = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand(
      "trace", "convert a binary run trace (.nct, from ncc run --emit=trace) to CSV");
  cmd->add_option("input", *input, "binary trace file")->required();
  cmd->add_option("-o,--output", *output, "write the CSV here (default: stdout)");
  cmd->callback([input, output, &exit_code] { exit_code = runTrace(*input, *output); });
}

}  // namespace ncc::cli
