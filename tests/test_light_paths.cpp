// Light-vertex connections (render/light_path.h): which lights start subpaths, and that a room lit
// by a point light renders the same image with them as without, with less noise. The closed forms
// of test_render_closed_form.cpp (the furnace inside a lit sphere, the lit plane) run with them
// too.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render/light_path.h"
#include "render_test_util.h"

namespace candela {
namespace {

TEST(LightPaths, PointLightsStartSubpathsByPowerAndLightsWithASurfaceNone) {
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4, "spp": 1},
    "spheres": [{"position": [0, -1000, 0], "radius": 999, "color": 0.5}],
    "lights": [{"position": [0, 1, 0], "intensity": 10},
               {"type": "sphere", "position": [3, 1, 0], "radius": 0.5, "intensity": 100},
               {"position": [1, 1, 0], "intensity": 10, "color": [2, 2, 2]},
               {"position": [2, 1, 0], "intensity": 10}]})");
  const SceneView view = data.view();
  ASSERT_EQ(view.lightCount, 4u);
  EXPECT_EQ(view.lightPathLights, 3u);
  EXPECT_FLOAT_EQ(lightPathPmf(view, 0), 0.25f);
  EXPECT_EQ(lightPathPmf(view, 1), 0.0f);  // the sphere light
  EXPECT_FLOAT_EQ(lightPathPmf(view, 2), 0.5f);
  EXPECT_FLOAT_EQ(lightPathPmf(view, 3), 0.25f);
  EXPECT_EQ(pickLightPathLight(view, 0.0f), 0u);
  EXPECT_EQ(pickLightPathLight(view, 0.2499f), 0u);
  EXPECT_EQ(pickLightPathLight(view, 0.2501f), 2u);
  EXPECT_EQ(pickLightPathLight(view, 0.7501f), 3u);
  EXPECT_EQ(pickLightPathLight(view, 0.99999994f), 3u);  // the largest float below 1
  // The density of the vertex straight below light 2, at distance 2: pick 0.5, 1 / (4 pi 2^2).
  EXPECT_FLOAT_EQ(lightVertexPdf(view, 2, Vec3(1, -1, 0), Vec3(0, 1, 0)),
                  0.5f / (4.0f * kPi * 4.0f));
}

TEST(LightPaths, OnlyPathsOfTwoOrMoreInteractionsStartThem) {
  const std::string lit = R"("lights": [{"position": [0, 1, 0], "intensity": 10}]})";
  const char* camera = R"({"camera": {"width": 4, "height": 4, "spp": 1}, )";
  EXPECT_EQ(test::loadTestScene(std::string(camera) + R"("render": {"max_depth": 1}, )" + lit)
                .view()
                .lightPathLights,
            0u);
  EXPECT_EQ(
      test::loadTestScene(std::string(camera) + R"("render": {"integrator": "direct"}, )" + lit)
          .view()
          .lightPathLights,
      0u);
  EXPECT_EQ(test::loadTestScene(std::string(camera) + lit).view().lightPathLights, 1u);
}

// A room of sphere walls lit by a point light near its ceiling, whose bright patch there lights
// the rest: rendered with light-vertex connections and without (the same scene, no light
// starting a subpath), over two seeds each. Each 8 x 8 block's mean agrees within the noise of
// the two renders (estimated from the seeds), and the image with connections is at least
// 1.5 times less noisy (measured: about 3 times).
TEST(LightPaths, ARoomRendersTheSameImageWithLessNoise) {
  const auto room = [](int seed) {
    return test::lampUnderTheCeiling(R"("width": 48, "height": 32, "spp": 16)",
                                     R"("max_depth": 4, "seed": )" + std::to_string(seed));
  };
  const auto renderPair = [&](bool connections) {
    test::SeedPair p;
    for (int seed : {1, 2}) {
      SceneData data = test::loadTestScene(room(seed));
      if (!connections) data.pointLightsWithPower = 0;
      EXPECT_EQ(data.view().lightPathLights, connections ? 1u : 0u);
      (seed == 1 ? p.a : p.b) = renderCpu(data.view(), RenderOptions{});
    }
    return p;
  };
  const auto [noiseWith, noiseWithout] = test::expectSameImage(renderPair(true), renderPair(false));
  EXPECT_LT(noiseWith * 1.5, noiseWithout);
}

}  // namespace
}  // namespace candela
