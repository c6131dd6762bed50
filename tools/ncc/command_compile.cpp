// `ncc compile IN -o OUT.ncb [--emit=ast|ir|bytecode]` and `ncc check IN`.
#include <iostream>

#include "cli.h"
#include "pending_output.h"
#include "ncc/driver/compile.h"

namespace ncc::cli {

namespace {

struct CompileArgs {
  CommonOptions common;
  std::string input;
  std::string output;
  std::string emit = "bytecode";
};

int runCompile(const CompileArgs& args) {
  driver::Session session;
  if (std::optional<int> failed = openSession(session, args.input, args.common)) return *failed;
  bool ok = false;
  if (args.emit == "bytecode") {
    std::filesystem::path out = args.output;
    if (out.empty()) out = std::filesystem::path(args.input).replace_extension(".ncb");
    driver::CompileFileResult result = driver::compileToFile(session, out);
    if (result.status == driver::CompileFileResult::OutputError) {
      printDiagnostics(session);
      std::cerr << "ncc: error: " << result.output_error << '\n';
      return kUsage;
    }
    ok = result.status == driver::CompileFileResult::Ok;
  } else {
    // Text forms stream to -o FILE or stdout; a failed compile leaves no file behind.
    PendingOutput output;
    if (!output.open(args.output)) return kUsage;
    ok = args.emit == "ast" ? driver::emitAst(session, output.stream())
                            : driver::emitIr(session, output.stream());
    if (ok && !output.commit()) return kUsage;
  }
  printDiagnostics(session);
  return ok ? kOk : kProgramError;
}

}  // namespace

void addCompileCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CompileArgs>();
  CLI::App* cmd = app.add_subcommand("compile", "compile a program to bytecode (.ncb)");
  cmd->add_option("input", args->input, "program source")->required();
  cmd->add_option("-o,--output", args->output, "output file (default: IN with .ncb)");
  cmd->add_option("--emit", args->emit, "what to write: bytecode (default), ast or ir")
      ->check(CLI::IsMember({"bytecode", "ast", "ir"}));
  args->common.addTo(*cmd);
  cmd->callback([args, &exit_code] { exit_code = runCompile(*args); });
}

void addCheckCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CompileArgs>();
  CLI::App* cmd = app.add_subcommand("check", "compile a program and report diagnostics only");
  cmd->add_option("input", args->input, "program source")->required();
  args->common.addTo(*cmd);
  cmd->callback([args, &exit_code] {
    driver::Session session;
    if (std::optional<int> failed = openSession(session, args->input, args->common)) {
      exit_code = *failed;
      return;
    }
    bool ok = driver::check(session);
    printDiagnostics(session);
    exit_code = ok ? kOk : kProgramError;
  });
}

}  // namespace ncc::cli
