// Terminal progress bar with an ETA extrapolated from the elapsed time.
#include "apps/cli/progress_bar.h"

#include <algorithm>
#include <cmath>
#include <string>

#if defined(_WIN32)
#include <io.h>
#define CANDELA_ISATTY _isatty
#define CANDELA_FILENO _fileno
#else
#include <unistd.h>
#define CANDELA_ISATTY isatty
#define CANDELA_FILENO fileno
#endif

namespace candela::cli {

namespace {

constexpr int kBarWidth = 30;
constexpr std::chrono::milliseconds kRedrawInterval{100};

}  // namespace

void formatClock(double seconds, char* buffer, size_t size) {
  const long total = long(std::lround(std::max(0.0, seconds)));
  const long h = total / 3600, m = (total / 60) % 60, s = total % 60;
  if (h > 0)
    std::snprintf(buffer, size, "%ld:%02ld:%02ld", h, m, s);
  else
    std::snprintf(buffer, size, "%ld:%02ld", m, s);
}

ProgressBar::ProgressBar(std::FILE* out) : out_(out), start_(Clock::now()), lastDraw_(start_) {}

bool ProgressBar::wanted(bool quiet) { return !quiet && CANDELA_ISATTY(CANDELA_FILENO(stderr)); }

void ProgressBar::startFrame(const std::string& label, unsigned done, unsigned count) {
  label_ = label;
  framesDone_ = done;
  frameCount_ = count;
  drawnOnce_ = false;  // draw the new label at once
}

void ProgressBar::update(double fraction) {
  const Clock::time_point now = Clock::now();
  if (drawnOnce_ && now - lastDraw_ < kRedrawInterval) return;
  lastDraw_ = now;
  drawnOnce_ = true;

  fraction = std::clamp(fraction, 0.0, 1.0);
  const int filled = int(fraction * kBarWidth);
  std::string bar =
      "[" + std::string(size_t(filled), '#') + std::string(size_t(kBarWidth - filled), '.') + "]";

  // The ETA covers all frames: the time so far scaled by the fraction of all frames done.
  const double overall =
      frameCount_ > 0 ? (framesDone_ + fraction) / double(frameCount_) : fraction;
  char eta[32] = "-:--";  // unknown until some work is done
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (overall > 0.0) formatClock(elapsed * (1.0 - overall) / overall, eta, sizeof eta);

  char line[256];
  const int n = std::snprintf(line, sizeof line, "\r%s%s%s %3d%%  ETA %s", label_.c_str(),
                              label_.empty() ? "" : " ", bar.c_str(), int(fraction * 100.0), eta);
  std::fputs(line, out_);
  // Pad over a longer previous line (an ETA that lost its hour digits).
  const size_t width = size_t(std::max(0, n - 1));
  if (width < drawnWidth_) std::fprintf(out_, "%*s", int(drawnWidth_ - width), "");
  drawnWidth_ = std::max(width, drawnWidth_);
  std::fflush(out_);
}

void ProgressBar::clear() {
  if (!drawnOnce_) return;
  std::fprintf(out_, "\r%*s\r", int(drawnWidth_), "");
  std::fflush(out_);
  drawnOnce_ = false;
  drawnWidth_ = 0;
}

}  // namespace candela::cli
