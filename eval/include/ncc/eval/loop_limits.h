#pragma once
#include <cstdint>

namespace ncc::eval {

// What ends an endless loop that neither moves nor dwells (docs/cli.md, Bounds); one that
// moves or dwells is ended by its simulated time (--max-time). Both are checked at a jump back
// (GOTO to an earlier block, END, M99 restarts and repeats), which every endless loop makes:
// past a limit the program stops with NCC2419 at the jump.
struct LoopLimits {
  // Blocks read since the last block that moved or dwelt (Evaluator::madeProgress): far more
  // than a real program's macro loop runs between two moves (--max-idle-blocks).
  uint64_t max_idle_blocks = 100'000'000;
  // Jumps back in all, 0: no limit (--max-back-jumps; for tests and fuzzing, not a default:
  // a surfacing macro jumps back tens of thousands of times).
  uint64_t max_back_jumps = 0;
  friend bool operator==(const LoopLimits&, const LoopLimits&) = default;
};

}  // namespace ncc::eval
