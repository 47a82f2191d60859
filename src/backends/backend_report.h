// What each render backend would run on here, or why it cannot run: `candela devices` and
// candela.devices() print it, so that a user can tell which of their processors a render uses.
#pragma once

#include <string>
#include <vector>

namespace candela {

struct BackendReport {
  const char* backend;  // backendName's: "cpu" or "cuda"
  bool usable;
  std::string summary;  // what it runs on, or why it cannot run
  bool autoPicks;       // whether `auto` renders on it (chooseBackend)
};

// The CPU's report, then the GPU's. `threads`: the CPU threads a render would use, as --threads
// (0: all cores).
std::vector<BackendReport> reportBackends(int threads);

}  // namespace candela
