#include "backends/cpu/cpu_renderer.h"

#include "backends/cpu/tile_renderer.h"

#if defined(CANDELA_HAS_EMBREE)
#include "backends/cpu/embree_scene.h"
#endif

namespace candela {

RenderResult renderCpu(const SceneView& scene, const RenderOptions& options) {
  return tileRenderer().withBvh(scene, BvhTracer{&scene}, options);
}

#if !defined(CANDELA_HAS_EMBREE)
// Declared only so that unique_ptr<EmbreeScene> can be destroyed in a build without Embree.
class EmbreeScene {};
#endif

CpuRenderer::CpuRenderer(CpuEngine engine, TileRenderer tiles) : engine_(engine), tiles_(tiles) {}
CpuRenderer::~CpuRenderer() = default;

void CpuRenderer::setScene(const SceneData& scene, SceneChange change) {
  view_ = scene.view();
#if defined(CANDELA_HAS_EMBREE)
  if (engine_ == CpuEngine::Embree) {
    if (!embree_) {
      embree_ = std::make_unique<EmbreeScene>();
      change = SceneChange::Structure;
    }
    embree_->update(scene, change);
  }
#else
  (void)change;
#endif
}

AccelerationStats CpuRenderer::acceleration() const {
  AccelerationStats stats;
  stats.isa = tiles_.isa;
#if defined(CANDELA_HAS_EMBREE)
  if (engine_ == CpuEngine::Embree && embree_) {
    stats.engine = "embree";
    stats.buildSeconds = embree_->buildSeconds();
    stats.bytes = embree_->bytes();
  }
#endif
  return stats;
}

RenderResult CpuRenderer::render(const RenderOptions& options) {
#if defined(CANDELA_HAS_EMBREE)
  if (engine_ == CpuEngine::Embree) return tiles_.withEmbree(view_, embree_->tracer(), options);
#endif
  return tiles_.withBvh(view_, BvhTracer{&view_}, options);
}

}  // namespace candela
