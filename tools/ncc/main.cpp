// ncc: compiles CNC part programs to motion bytecode and runs them in the VM.
#include <iostream>

#include "cli.h"

int main(int argc, char** argv) {
  using namespace ncc::cli;
  CLI::App app{"ncc: a compiler from CNC controller languages to motion bytecode, and its VM"};
  app.name("ncc");
  app.require_subcommand(1);
  int exit_code = kOk;
  addCompileCommand(app, exit_code);
  addCheckCommand(app, exit_code);
  addDisCommand(app, exit_code);
  addRunCommand(app, exit_code);
  addTraceCommand(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kUsage;
  }
  return exit_code;
}
