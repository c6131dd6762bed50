#pragma once
// What a pipeline of passes is built with (PassManager): the machine's shape, which passes
// run, and the debugging controls of `ncc compile --emit=ir` (--print-after, --stop-after,
// --verify-each; docs/cli.md "Passes").
#include <string>
#include <vector>

#include "ncc/machine/dialect.h"
#include "ncc/machine/machine_config.h"

namespace ncc::passes {

class PassPrinter;

struct PipelineOptions {
  int axis_count = 3;
  bool to_machine_space = true;  // false: stop in work space (debug printing)
  // Run the IR verifier before the final sink: in every build but Release (NCC_VERIFY_IR),
  // where it cost about a tenth of a plain program's compile; --verify-each asks for it in any
  // build, after every pass.
#ifdef NCC_VERIFY_IR
  bool verify = true;
#else
  bool verify = false;
#endif
  // Run the IR verifier after every pass instead (tests, `--verify-each`): a pass that breaks
  // an invariant is named in the NCC9001 error rather than found passes later.
  bool verify_each = false;
  // Check motion targets against this machine's travel limits (`ncc check`; needs
  // to_machine_space), reporting with the dialect's alarm numbers.
  const MachineConfig* travel_limits = nullptr;
  Dialect dialect = Dialect::FanucM;
  // false: the compensation pass drops the G41/G42 requests and keeps the programmed path
  // (`ncc plot` draws it beside the compensated one).
  bool compensate = true;
  // `--print-after`: the IR as it leaves each of these passes goes to `printer` (needed when
  // the list is not empty). Names are checked by the caller (driver::checkPassControl); a name
  // that is no pass of this pipeline prints nothing.
  std::vector<std::string> print_after;
  PassPrinter* printer = nullptr;
  // `--stop-after`: the passes after this one are not built, the final sink receives the IR
  // as it leaves it. Empty, or no pass of this pipeline: every pass runs.
  std::string stop_after;
};

}  // namespace ncc::passes
