// Every scene the project ships (scenes/, scenes/examples/, the ones README and
// docs/scene-format.md point users to) loads, flattens and renders a sample per pixel without a
// warning, so that no example goes stale as the format grows.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "backends/cpu/cpu_renderer.h"
#include "scene/animation.h"
#include "scene/flatten.h"
#include "scene/read/scene_loader.h"
#include "shipped_scenes.h"

namespace candela {
namespace {

TEST(ExampleScenes, EachLoadsWithoutWarningsAndRenders) {
  const std::vector<std::string> files = test::shippedScenes();
  EXPECT_GE(files.size(), 12u);
  for (const std::string& file : files) {
    SCOPED_TRACE(file);
    const SceneDesc loaded = loadSceneFile(file);
    EXPECT_TRUE(loaded.warnings.empty()) << loaded.warnings.front();
    SceneDesc desc = sceneAtFrame(loaded, 0);
    desc.camera.width = 16;  // a thumbnail, one sample a pixel: the render must only run
    desc.camera.height = 12;
    desc.camera.intrinsics.reset();
    desc.render.spp = 1;
    const SceneData data = flattenScene(desc);
    const RenderResult r = renderCpu(data.view(), RenderOptions{});
    double sum = 0;
    for (float v : r.image.pixels) sum += v;
    EXPECT_GT(sum, 0.0);
  }
}

}  // namespace
}  // namespace candela
