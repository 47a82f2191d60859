// SIGINT handler that sets a lock-free atomic flag (the only thing a handler may safely touch).
#include "apps/cli/interrupt.h"

#include <csignal>

namespace candela::cli {

namespace {

std::atomic<bool> gInterrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "a signal handler needs a lock-free flag");

extern "C" void onInterrupt(int) {
  gInterrupted.store(true);
  std::signal(SIGINT, SIG_DFL);  // the next Ctrl-C ends the process
}

}  // namespace

InterruptGuard::InterruptGuard() {
  gInterrupted.store(false);
  previous_ = std::signal(SIGINT, onInterrupt);
}

InterruptGuard::~InterruptGuard() {
  std::signal(SIGINT, previous_ == SIG_ERR ? SIG_DFL : previous_);
}

const std::atomic<bool>& InterruptGuard::flag() const { return gInterrupted; }

}  // namespace candela::cli
