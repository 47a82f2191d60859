// Ctrl-C handling: while an InterruptGuard lives, SIGINT (and SIGTERM, which a job control or
// a scheduler sends) sets a flag instead of killing.
//
// The render loop polls the flag and stops at the next tile, so the CLI can exit cleanly without
// writing an image. A second Ctrl-C gets the default behaviour (the process ends at once), for
// the case where the first one is not acted on quickly.
#pragma once

#include <atomic>

namespace candela::cli {

class InterruptGuard {
 public:
  InterruptGuard();   // installs the handler and clears the flag
  ~InterruptGuard();  // restores the previous handler
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  const std::atomic<bool>& flag() const;
  bool interrupted() const { return flag().load(); }

 private:
  void (*previousInt_)(int);
  void (*previousTerm_)(int);
};

}  // namespace candela::cli
