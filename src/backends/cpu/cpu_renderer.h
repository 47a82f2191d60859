// The CPU backend: renders a SceneView with oneTBB over 16x16 tiles, all cores by default.
// Each pixel's samples are summed in a fixed order, so the image is bit-identical for any
// thread count. A sample range renders one slice of the samples (render/sample_range.h).
#pragma once

#include <atomic>
#include <functional>

#include "render/render_result.h"
#include "render/sample_range.h"
#include "scene/scene_view.h"

namespace candela {

struct CpuRenderOptions {
  int threads = 0;  // 0: all cores
  // Called from worker threads (serialised) with the fraction of pixels done, in [0, 1].
  std::function<void(double)> progress;
  // When set and true, workers stop at the next tile; the result is then marked cancelled.
  const std::atomic<bool>* cancel = nullptr;
  // Render only these sample indices and return their mean (default: all spp). Throws
  // std::invalid_argument for a range outside [0, spp).
  SampleRange samples;
};

RenderResult renderCpu(const SceneView& scene, const CpuRenderOptions& options);

}  // namespace candela
