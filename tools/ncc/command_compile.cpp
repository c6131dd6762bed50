// `ncc compile IN -o OUT.ncb [--emit=ast|ir|bytecode]` and `ncc check IN`.
#include <iostream>
#include <sstream>

#include "cli.h"
#include "pending_output.h"
#include "progress.h"
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
  std::string out = args.output;
  if (args.emit == "bytecode" && out.empty()) {
    if (session.stdinContents()) {
      printError("NCC0008", "the program comes from stdin: name the output with -o FILE (-o - for stdout)");
      return kUsage;
    }
    out = std::filesystem::path(args.input).replace_extension(".ncb").string();
  }
  // Every form streams to -o FILE (a temporary file renamed when the compile succeeded: a
  // failed compile leaves no file behind, an existing one untouched) or stdout.
  PendingOutput output;
  if (!output.open(out, session.inputFiles())) return kUsage;
  bool ok = false;
  {
    // Not while text streams to the terminal the line would be drawn on.
    CompileProgress progress(session, !(output.toStdout() && args.emit != "bytecode" && stdoutIsTerminal()));
    if (args.emit == "bytecode" && output.toStdout()) {
      // The writer patches its section table at the end: stdout cannot seek, so the bytes
      // are collected first.
      std::stringstream bytes;
      ok = driver::emitBytecode(session, bytes);
      if (ok) output.stream() << bytes.rdbuf();
    } else if (args.emit == "bytecode") {
      ok = driver::emitBytecode(session, output.stream());
    } else {
      ok = args.emit == "ast" ? driver::emitAst(session, output.stream())
                              : driver::emitIr(session, output.stream());
    }
  }
  output.addInputs(session.inputFiles());  // the subprograms the compile read
  printDiagnostics(session);
  if (!ok) return kProgramError;
  return output.commit() ? kOk : kUsage;
}

}  // namespace

void addCompileCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CompileArgs>();
  CLI::App* cmd = app.add_subcommand("compile", "compile a program to bytecode (.ncb)");
  cmd->add_option("input", args->input, "program source (-: the standard input)")->required();
  cmd->add_option("-o,--output", args->output, "output file (default: IN with .ncb; -: stdout)");
  cmd->add_option("--emit", args->emit, "what to write: bytecode (default), ast or ir")
      ->check(CLI::IsMember({"bytecode", "ast", "ir"}));
  args->common.addTo(*cmd);
  cmd->callback([args, &exit_code] { exit_code = runCompile(*args); });
}

void addCheckCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CompileArgs>();
  CLI::App* cmd = app.add_subcommand("check", "compile a program and report diagnostics only");
  cmd->add_option("input", args->input, "program source (-: the standard input)")->required();
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
