// The CPU backend: renders a SceneView with oneTBB over 16x16 tiles, all cores by default.
// Each pixel's samples are summed in a fixed order, so the image is bit-identical for any
// thread count. A sample range renders one slice of the samples (render/sample_range.h).
//
// Two ray engines serve it (backends/cpu/cpu_engine.h): Embree where the build has it, and
// candela's own BVH, the CUDA backend's, which --no-bvh's one-level tree also needs. They render
// the same image up to the rounding of hit points.
#pragma once

#include <memory>

#include "backends/cpu/cpu_engine.h"
#include "backends/cpu/tile_renderer.h"
#include "backends/renderer.h"
#include "render/scene_view.h"

namespace candela {

// Renders with candela's own BVH (the scene's nodes), in the widest instruction set the CPU runs
// (backends/cpu/tile_renderer.h).
RenderResult renderCpu(const SceneView& scene, const RenderOptions& options);

class EmbreeScene;

// The Renderer of the CPU backend. With the own BVH it renders the given scene where it lies, so
// a new frame costs nothing to hand over; with Embree a frame whose geometry changed updates
// Embree's copy (a refit when primitives only moved).
class CpuRenderer final : public Renderer {
 public:
  // `engine` must not be Auto: resolveCpuEngine first. `tiles` is the render loop to run, by
  // default the widest the CPU has (tileRenderer, which throws BackendError where
  // CANDELA_CPU_ISA names one the CPU cannot run).
  explicit CpuRenderer(CpuEngine engine, TileRenderer tiles = tileRenderer());
  ~CpuRenderer() override;

  void setScene(const SceneData& scene, SceneChange change) override;
  RenderResult render(const RenderOptions& options) override;
  AccelerationStats acceleration() const override;

 private:
  CpuEngine engine_;
  TileRenderer tiles_;
  SceneView view_;
  std::unique_ptr<EmbreeScene> embree_;
};

}  // namespace candela
