// The CPU backend: renders a SceneView with oneTBB over 16x16 tiles, all cores by default.
// Each pixel's samples are summed in a fixed order, so the image is bit-identical for any
// thread count. A sample range renders one slice of the samples (render/sample_range.h).
#pragma once

#include "backends/renderer.h"
#include "render/scene_view.h"

namespace candela {

RenderResult renderCpu(const SceneView& scene, const RenderOptions& options);

// The Renderer of the CPU backend: it renders the given scene where it lies, so a new frame
// costs nothing to hand over.
class CpuRenderer final : public Renderer {
 public:
  void setScene(const SceneData& scene, SceneChange) override { view_ = scene.view(); }
  RenderResult render(const RenderOptions& options) override { return renderCpu(view_, options); }

 private:
  SceneView view_;
};

}  // namespace candela
