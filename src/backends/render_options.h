// What every backend takes besides the scene: threads, progress, cancellation, which samples, and
// what the render changes of the scene's view.
#pragma once

#include <atomic>
#include <functional>
#include <string>

#include "render/sample_range.h"
#include "render/view_adjustment.h"

namespace candela {

struct RenderOptions {
  int threads = 0;  // CPU worker threads, 0: all cores (the GPU ignores it)
  // Called with the fraction done, in [0, 1], never concurrently (the CPU calls it from its
  // workers, the GPU from the calling thread between passes).
  std::function<void(double)> progress;
  // When set and true, rendering stops at the next tile or pass; the result is marked cancelled.
  const std::atomic<bool>* cancel = nullptr;
  // Render only these sample indices and return their mean (default: all spp). Throws
  // std::invalid_argument for a range outside [0, spp).
  SampleRange samples;
  // Also record the samples' first hits for render passes (RenderResult::aovs). Off, the
  // integrator runs without any pass code.
  bool aovs = false;
  // What this render changes of the scene's view (the light-path pilot's, and its choice).
  ViewAdjustment adjust;
  std::string sceneLabel;  // the scene file, named in error messages
};

}  // namespace candela
