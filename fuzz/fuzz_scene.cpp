// See fuzz_scene.h.
#include "fuzz_scene.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <memory>

#include "geometry/bvh_tracer.h"
#include "render/render_pixel.h"
#include "scene/animation.h"
#include "scene/flatten.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"

namespace candela::fuzz {
namespace {

// Two opposite corners and the centre of the image, one sample each, paths cut at a few bounces:
// enough to reach traversal, materials and lights without making slow inputs of long paths.
void traceSomePixels(SceneData& scene) {
  scene.settings.maxDepth = std::min<uint32_t>(scene.settings.maxDepth, 4);
  const SceneView view = scene.view();
  RayCounters counters;
  const uint32_t w = scene.camera.width, h = scene.camera.height;
  const uint32_t pixels[][2] = {{0, 0}, {w / 2, h / 2}, {w - 1, h - 1}};
  for (const auto& p : pixels)
    renderPixelSamples(view, BvhTracer{&view}, p[0], p[1], 0, 1, counters);
}

}  // namespace

void limitToOneThread() {
  static const auto control =
      std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, 1);
}

void loadAndTrace(const std::string& text, const std::string& baseDir) {
  try {
    const SceneDesc desc = parseSceneText(text, "fuzz.json", baseDir);
    const uint32_t frames = desc.animation ? desc.animation->frames : 1;
    for (const uint32_t frame : {0u, frames - 1}) {
      SceneData scene = flattenScene(sceneAtFrame(desc, frame));
      traceSomePixels(scene);
      if (frames == 1) break;
    }
  } catch (const SceneError&) {
  }
}

}  // namespace candela::fuzz
