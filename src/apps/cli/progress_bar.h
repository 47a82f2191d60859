// A one-line progress bar for terminals: `[##########..........]  42%  ETA 0:13`, or for a frame of
// an animation `frame 3/10 [####......]  42%  ETA 1:05`, where the bar is the frame's and the ETA
// is the whole animation's (extrapolated from the frames rendered so far in this run).
//
// Redrawn in place with '\r' at most about ten times per second and erased by clear(), so the
// final summary starts on a clean line. update() may be called from worker threads as long as
// the calls are serialised (the CPU backend guarantees it); clear() runs after the render.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace candela::cli {

class ProgressBar {
 public:
  explicit ProgressBar(std::FILE* out);

  // Whether a bar should be shown on stderr: only on a terminal, never with --quiet.
  static bool wanted(bool quiet);

  // Starts frame `done` + 1 of `count` frames to render, shown as `label` before the bar.
  void startFrame(const std::string& label, unsigned done, unsigned count);
  void update(double fraction);  // fraction of the image (frame) done, in [0, 1]
  void clear();

 private:
  using Clock = std::chrono::steady_clock;

  std::FILE* out_;
  Clock::time_point start_;
  Clock::time_point lastDraw_;
  bool drawnOnce_ = false;
  size_t drawnWidth_ = 0;  // characters on the line now, to erase them
  std::string label_;      // "frame 3/10", empty for a single image
  unsigned framesDone_ = 0, frameCount_ = 0;  // 0 frames: a single image
};

// "m:ss", or "h:mm:ss" from an hour on.
void formatClock(double seconds, char* buffer, size_t size);

}  // namespace candela::cli
