// SIGINT and SIGTERM handler that sets a lock-free atomic flag (the only thing a handler may
// safely touch).
#include "apps/cli/interrupt.h"

#include <csignal>

namespace candela::cli {

namespace {

std::atomic<bool> gInterrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "a signal handler needs a lock-free flag");

extern "C" void onInterrupt(int) {
  gInterrupted.store(true);
  std::signal(SIGINT, SIG_DFL);  // the next Ctrl-C or termination ends the process
  std::signal(SIGTERM, SIG_DFL);
}

}  // namespace

InterruptGuard::InterruptGuard() {
  gInterrupted.store(false);
  // Installed whatever was there before: a job started in the background inherits SIGINT
  // ignored, and must still stop cleanly when interrupted.
  previousInt_ = std::signal(SIGINT, onInterrupt);
  previousTerm_ = std::signal(SIGTERM, onInterrupt);
}

InterruptGuard::~InterruptGuard() {
  std::signal(SIGINT, previousInt_ == SIG_ERR ? SIG_DFL : previousInt_);
  std::signal(SIGTERM, previousTerm_ == SIG_ERR ? SIG_DFL : previousTerm_);
}

const std::atomic<bool>& InterruptGuard::flag() const { return gInterrupted; }

}  // namespace candela::cli
