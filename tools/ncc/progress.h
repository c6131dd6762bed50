#pragma once
// Progress of a long compile or run on an interactive terminal: after about a second, one
// line on stderr, redrawn in place (blocks, simulated time, share of the main file read),
// erased when the command ends. Never shown when stderr is not a terminal (pipes, CI logs).
// Cheap: callers count blocks; the clock is read only every N calls of tick().
#include <chrono>
#include <cstdint>
#include <string>

#include "ncc/driver/session.h"

namespace ncc::cli {

// True when stdout is a terminal: output streamed there would break the progress line.
bool stdoutIsTerminal();

class Progress {
 public:
  // `verb` names the stage ("compiling", "running"); the clock is read every `clock_every`
  // calls of tick(). Counts the main file's lines (for the percentage) only when the display
  // is enabled.
  // `main_file`: the source id whose lines give the percentage (0: none shown). `wanted`
  // false: never shown (the command streams its output to the same terminal).
  Progress(const char* verb, driver::Session& session, uint32_t clock_every, uint32_t main_file,
           bool wanted = true);
  ~Progress() { clear(); }
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  bool enabled() const { return enabled_; }
  // A block (`file` its source id, `line` its line) was reached.
  void block(uint32_t file, uint32_t line) {
    ++blocks_;
    if (file == main_file_ && line > line_) line_ = line;
  }
  // Simulated seconds so far (runs only); also the moment to look at the clock.
  void tick(double simulated_seconds);
  // Erases the line if one was drawn.
  void clear();

 private:
  void draw();

  const char* verb_;
  bool enabled_ = false;
  bool drawn_ = false;
  uint32_t main_file_ = 0;
  uint64_t total_lines_ = 0;  // 0: unknown
  uint64_t blocks_ = 0;
  uint32_t line_ = 0;
  double simulated_ = -1.0;  // < 0: not a run
  uint32_t clock_every_;
  uint32_t calls_ = 0;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point next_draw_;
};

// Hooks a compile's progress (Session::setBlockObserver) for the lifetime of this object.
class CompileProgress {
 public:
  CompileProgress(driver::Session& session, bool wanted = true);
  ~CompileProgress();

 private:
  driver::Session& session_;
  Progress progress_;
};

}  // namespace ncc::cli
