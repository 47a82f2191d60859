// The CPU backend's render loop in each instruction set it is built for
// (backends/cpu/tile_renderer.h): the x86-64-v4 loop renders the baseline's image up to rounding
// on every shipped scene, with either ray engine; the choice at run time follows the CPU and
// CANDELA_CPU_ISA.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "backends/backend_error.h"
#include "backends/cpu/cpu_renderer.h"
#include "backends/cpu/tile_renderer.h"
#include "cpu_engines.h"
#include "image_difference.h"
#include "scene/animation.h"
#include "scene/flatten.h"
#include "scene/read/scene_loader.h"
#include "shipped_scenes.h"

namespace candela {
namespace {

// Sets an environment variable for one scope, and puts back what it was.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = getenv(name)) old_ = old, had_ = true;
    setenv(name, value, 1);
  }
  ~ScopedEnv() { had_ ? setenv(name_, old_.c_str(), 1) : unsetenv(name_); }

 private:
  const char* name_;
  std::string old_;
  bool had_ = false;
};

RenderResult renderIn(const TileRenderer& tiles, CpuEngine engine, const SceneData& data,
                      bool aovs = false) {
  CpuRenderer renderer(engine, tiles);
  renderer.setScene(data, SceneChange::Structure);
  RenderOptions options;
  options.aovs = aovs;
  return renderer.render(options);
}

TEST(TileRenderer, TheBaselineRunsEverywhereAndIsNamed) {
  TileRenderer named{};
  const TileRenderer baseline = baselineTileRenderer();
  ASSERT_TRUE(tileRendererByName(baseline.isa, &named));
  EXPECT_EQ(named.withBvh, baseline.withBvh);
  EXPECT_EQ(baseline.withEmbree != nullptr, embreeAvailable());
  EXPECT_FALSE(tileRendererByName("x86-64-v9", &named));
}

TEST(TileRenderer, TheWidestTheCpuRunsIsPickedUnlessTheEnvironmentNamesOne) {
#if defined(CANDELA_X86_64_V4_LOOP)
  const bool v4 = __builtin_cpu_supports("x86-64-v4");
#else
  const bool v4 = false;
#endif
  {
    const ScopedEnv unset("CANDELA_CPU_ISA", "");  // empty: as if unset
    EXPECT_STREQ(tileRenderer().isa, v4 ? "x86-64-v4" : baselineTileRenderer().isa);
  }
  {
    const ScopedEnv env("CANDELA_CPU_ISA", baselineTileRenderer().isa);
    EXPECT_EQ(tileRenderer().withBvh, baselineTileRenderer().withBvh);
    EXPECT_STREQ(CpuRenderer(CpuEngine::Bvh).acceleration().isa, baselineTileRenderer().isa);
  }
  const ScopedEnv env("CANDELA_CPU_ISA", "sse9");
  try {
    tileRenderer();
    FAIL() << "an unknown instruction set was accepted";
  } catch (const BackendError& e) {
    EXPECT_NE(std::string(e.what()).find("CANDELA_CPU_ISA=sse9: expected x86-64"),
              std::string::npos)
        << e.what();
  }
}

// The x86-64-v4 loop fuses multiply-adds, so a path can part from the baseline's where a
// rounding tips a choice (a refraction's total reflection, a light pick): the two images agree
// far below the noise between two seeds, as the two ray engines do (test_embree.cpp).
TEST(TileRenderer, X86_64V4RendersTheBaselinesImageUpToRoundingOnEveryShippedScene) {
  TileRenderer v4{};
  if (!tileRendererByName("x86-64-v4", &v4))
    GTEST_SKIP() << "this CPU (or build) has no x86-64-v4 (AVX-512): nothing to compare";
  const TileRenderer baseline = baselineTileRenderer();
  const std::vector<std::string> files = test::shippedScenes();
  EXPECT_GE(files.size(), 40u);
  double worst = 0;
  for (const std::string& file : files) {
    SceneDesc desc = sceneAtFrame(loadSceneFile(file), 0);
    desc.camera.width = 40;
    desc.camera.height = 30;
    desc.camera.intrinsics.reset();
    desc.render.spp = 8;
    for (CpuEngine engine : test::builtCpuEngines()) {
      SCOPED_TRACE(file + (engine == CpuEngine::Embree ? ", Embree" : ", own BVH"));
      SceneDesc forEngine = desc;
      if (engine == CpuEngine::Embree) forEngine.ownBvh = OwnBvh::None;
      const SceneData data = flattenScene(forEngine);
      const ImageRGB a = renderIn(baseline, engine, data).image;
      forEngine.render.seed += 1;
      const ImageRGB otherSeed = renderIn(baseline, engine, flattenScene(forEngine)).image;
      const double noise = test::relMseAgainst(a.pixels, otherSeed.pixels);
      // Both of each loop's instances: without passes, and with them.
      for (bool aovs : {false, true}) {
        const RenderResult b = renderIn(v4, engine, data, aovs);
        ASSERT_EQ(a.pixels.size(), b.image.pixels.size());
        EXPECT_EQ(b.aovs.size(), aovs ? a.pixels.size() / 3 : 0u);
        const double difference = test::relMseAgainst(a.pixels, b.image.pixels);
        EXPECT_LE(difference, 0.05 * noise) << "noise between seeds " << noise;
        if (noise > 0) worst = std::max(worst, difference / noise);
      }
    }
  }
  std::printf("the largest difference: %.2g of the noise between seeds\n", worst);
}

}  // namespace
}  // namespace candela
