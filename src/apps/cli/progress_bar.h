// A one-line progress bar for terminals: `[##########..........]  42%  ETA 0:13`.
//
// Redrawn in place with '\r' at most about ten times per second and erased by clear(), so the
// final summary starts on a clean line. update() may be called from worker threads as long as
// the calls are serialised (the CPU backend guarantees it); clear() runs after the render.
#pragma once

#include <chrono>
#include <cstdio>

namespace candela::cli {

class ProgressBar {
 public:
  explicit ProgressBar(std::FILE* out);

  // Whether a bar should be shown on stderr: only on a terminal, never with --quiet.
  static bool wanted(bool quiet);

  void update(double fraction);  // fraction of the work done, in [0, 1]
  void clear();

 private:
  using Clock = std::chrono::steady_clock;

  std::FILE* out_;
  Clock::time_point start_;
  Clock::time_point lastDraw_;
  bool drawnOnce_ = false;
  size_t drawnWidth_ = 0;  // characters on the line now, to erase them
};

// "m:ss", or "h:mm:ss" from an hour on.
void formatClock(double seconds, char* buffer, size_t size);

}  // namespace candela::cli
