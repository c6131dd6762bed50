// `ncc compile IN -o OUT.ncb [--emit=ast|ir|bytecode]` and `ncc check IN`, with the pass
// pipeline's controls --print-after, --stop-after, --verify-each (docs/cli.md "Passes").
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
  driver::PassControl passes;
};

void addPassOptions(CLI::App& cmd, driver::PassControl& passes, const char* print_where) {
  cmd.add_option("--print-after", passes.print_after,
                 std::string("write the IR as it leaves PASS ") + print_where +
                     "; repeatable, or PASS,PASS")
      ->delimiter(',')
      ->type_name("PASS");
  cmd.add_option("--stop-after", passes.stop_after, "run the passes up to PASS only")
      ->type_name("PASS");
  cmd.add_flag("--verify-each", passes.verify_each, "verify the IR after every pass");
}

// Usage errors of the pass options, before anything is opened or written.
std::optional<int> checkPassOptions(const driver::PassControl& passes, driver::Pipeline pipeline) {
  if (std::optional<std::string> why = driver::checkPassControl(passes, pipeline)) {
    printError("NCC0015", *why);
    return kUsage;
  }
  return std::nullopt;
}

int runCompile(const CompileArgs& args) {
  // Usage errors first: nothing is read or written before them.
  const driver::PassControl& passes = args.passes;
  if ((!passes.print_after.empty() || !passes.stop_after.empty()) && args.emit != "ir") {
    printError("NCC0016", "--print-after and --stop-after write IR: use them with --emit=ir (not --emit=" +
                              args.emit + ")");
    return kUsage;
  }
  if (std::optional<int> failed = checkPassOptions(passes, driver::Pipeline::Compile)) return *failed;
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
    if (args.emit == "bytecode" && output.isStream()) {
      // The writer patches its section table at the end: stdout, a FIFO or a device cannot
      // seek, so the bytes are collected first.
      std::stringstream bytes;
      ok = driver::emitBytecode(session, bytes, args.passes);
      if (ok) output.stream() << bytes.rdbuf();
    } else if (args.emit == "bytecode") {
      ok = driver::emitBytecode(session, output.stream(), args.passes);
    } else {
      ok = args.emit == "ast" ? driver::emitAst(session, output.stream())
                              : driver::emitIr(session, output.stream(), args.passes);
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
  addPassOptions(*cmd, args->passes, "(with --emit=ir)");
  args->common.addTo(*cmd);
  cmd->callback([args, &exit_code] { exit_code = runCompile(*args); });
}

void addCheckCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CompileArgs>();
  CLI::App* cmd = app.add_subcommand("check", "compile a program and report diagnostics only");
  cmd->add_option("input", args->input, "program source (-: the standard input)")->required();
  addPassOptions(*cmd, args->passes, "on stdout");
  args->common.addTo(*cmd);
  cmd->callback([args, &exit_code] {
    if (std::optional<int> failed = checkPassOptions(args->passes, driver::Pipeline::Check)) {
      exit_code = *failed;
      return;
    }
    driver::Session session;
    if (std::optional<int> failed = openSession(session, args->input, args->common)) {
      exit_code = *failed;
      return;
    }
    bool ok = driver::check(session, args->passes,
                            args->passes.print_after.empty() ? nullptr : &std::cout);
    printDiagnostics(session);
    exit_code = ok ? kOk : kProgramError;
  });
}

}  // namespace ncc::cli
