// ncc: compiles CNC part programs to motion bytecode and runs them in the VM.
#include <iostream>

#include "cli.h"
#include "ncc/support/source_read_error.h"

#ifndef NCC_VERSION
#define NCC_VERSION "unknown"
#endif

int main(int argc, char** argv) {
  using namespace ncc::cli;
  CLI::App app{"ncc: a compiler from CNC controller languages to motion bytecode, and its VM"};
  app.name("ncc");
  app.set_version_flag("--version", "ncc " NCC_VERSION, "print the version and exit");
  app.require_subcommand(1);
  int exit_code = kOk;
  addCompileCommand(app, exit_code);
  addCheckCommand(app, exit_code);
  addDisCommand(app, exit_code);
  addRunCommand(app, exit_code);
  addTraceCommand(app, exit_code);
  addPlotCommand(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --help-all, --version
    return app.exit(e);
  } catch (const ncc::SourceReadError& e) {
    // A program or subprogram whose read failed part way: what was read is not the program.
    // Outputs are discarded on the way here (PendingOutput's destructor).
    printError("NCC0001", e.what());
    return kUsage;
  } catch (const CLI::ParseError& e) {
    printError("NCC0010", e.what());
    std::cerr << "Run with --help for more information.\n";
    return kUsage;
  }
  return exit_code;
}
