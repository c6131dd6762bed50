#include "progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "absl/strings/str_format.h"

namespace ncc::cli {

namespace {

constexpr auto kFirstDraw = std::chrono::milliseconds(1000);
constexpr auto kRedraw = std::chrono::milliseconds(250);

uint64_t countLines(driver::Session& session) {
  if (const std::string* text = session.stdinContents())
    return static_cast<uint64_t>(std::count(text->begin(), text->end(), '\n')) + 1;
  std::ifstream in(session.input(), std::ios::binary);
  uint64_t lines = 1;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    lines += static_cast<uint64_t>(std::count(buffer, buffer + in.gcount(), '\n'));
    if (!in) break;
  }
  return lines;
}

}  // namespace

bool stdoutIsTerminal() { return isatty(STDOUT_FILENO) == 1; }

Progress::Progress(const char* verb, driver::Session& session, uint32_t clock_every,
                   uint32_t main_file, bool wanted)
    : verb_(verb),
      enabled_(wanted && isatty(STDERR_FILENO) == 1),
      main_file_(main_file),
      clock_every_(std::max(clock_every, 1u)) {
  if (!enabled_) return;
  if (main_file_ != 0) total_lines_ = countLines(session);
  start_ = std::chrono::steady_clock::now();
  next_draw_ = start_ + kFirstDraw;
}

void Progress::tick(double simulated_seconds) {
  simulated_ = simulated_seconds;
  if (!enabled_ || ++calls_ % clock_every_ != 0) return;
  const auto now = std::chrono::steady_clock::now();
  if (now < next_draw_) return;
  next_draw_ = now + kRedraw;
  draw();
}

void Progress::draw() {
  std::string text = absl::StrFormat("ncc: %s: %d blocks", verb_, blocks_);
  if (simulated_ >= 0.0) text += absl::StrFormat(", %.1f s simulated", simulated_);
  if (total_lines_ > 0 && line_ > 0) {
    const double share = std::min(100.0, 100.0 * static_cast<double>(line_) /
                                             static_cast<double>(total_lines_));
    text += absl::StrFormat(", line %d (%.0f %% of the file)", line_, share);
  }
  // Carriage return and erase to the end of the line: the line is redrawn in place.
  std::fprintf(stderr, "\r%s\x1b[K", text.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::clear() {
  if (!drawn_) return;
  std::fputs("\r\x1b[K", stderr);
  std::fflush(stderr);
  drawn_ = false;
}

CompileProgress::CompileProgress(driver::Session& session, bool wanted)
    : session_(session),
      progress_("compiling", session, /*clock_every=*/256, session.mainFile(), wanted) {
  if (!progress_.enabled()) return;
  session_.setBlockObserver([this](const SourceLocation& where) {
    progress_.block(where.file, where.line);
    progress_.tick(-1.0);
  });
}

CompileProgress::~CompileProgress() { session_.setBlockObserver(nullptr); }

}  // namespace ncc::cli
