// Running a long C++ call from Python without holding the GIL, while Ctrl-C still works.
//
// Python runs signal handlers only on the main thread, and only when that thread executes
// bytecode or calls PyErr_CheckSignals. So the work runs on a helper thread with the GIL released
// while the calling thread wakes every few milliseconds, takes the GIL just long enough to call
// PyErr_CheckSignals, and on a pending KeyboardInterrupt sets the cancel flag the renderers poll.
#pragma once

#include <atomic>
#include <functional>

namespace candela::python {

// Runs work(cancel) with the GIL released (the caller must hold it). If a signal handler raises
// (Ctrl-C), sets `cancel`, waits for work to return and rethrows the Python exception.
// Exceptions thrown by work are rethrown as they are.
void runInterruptible(const std::function<void(const std::atomic<bool>& cancel)>& work);

}  // namespace candela::python
