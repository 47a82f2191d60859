// Light selection for next-event estimation: the power-proportional pmf the scene loader sets and
// the bisection that picks a light from it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "render/light_sample.h"
#include "render_test_util.h"

namespace candela {
namespace {

SceneView viewOf(const std::vector<Light>& lights) {
  SceneView v;
  v.lights = lights.data();
  v.lightCount = static_cast<uint32_t>(lights.size());
  return v;
}

TEST(LightSelection, FewLightsAreEachSampled) {
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4, "fov": 40},
    "lights": [{"position": [0, 1, 0], "intensity": 0},
               {"position": [0, 1, 0], "intensity": 2},
               {"type": "sphere", "position": [0, 5, 0], "radius": 1, "intensity": 3}]})");
  ASSERT_EQ(data.lights.size(), 3u);
  for (const Light& l : data.lights) EXPECT_EQ(l.selectPmf, 1.0f);
}

TEST(LightSelection, ManyLightsArePickedByPowerSkippingLightsWithout) {
  std::string lights = R"({"position": [0, 1, 0], "intensity": 0},
                          {"position": [0, 1, 0], "intensity": 2},
                          {"position": [0, 1, 0], "intensity": 0},
                          {"type": "sphere", "position": [0, 5, 0], "radius": 1, "intensity": 3,
                           "color": [1, 2, 3]},
                          {"position": [0, 1, 0], "intensity": 1, "color": 0})";
  for (uint32_t i = 5; i <= kSampleEveryLightUpTo; ++i)
    lights += R"(, {"position": [0, 1, 0], "intensity": 0})";
  const SceneData data = test::loadTestScene(R"({"camera": {"width": 4, "height": 4, "fov": 40},
                                                 "lights": [)" + lights + "]}");
  ASSERT_EQ(data.lights.size(), kSampleEveryLightUpTo + 1);
  // Powers (RGB sums): 0, 6, 0, 18, then nothing.
  for (size_t i = 0; i < data.lights.size(); ++i)
    EXPECT_NEAR(data.lights[i].selectPmf, i == 1 ? 0.25f : (i == 3 ? 0.75f : 0.0f), 1e-7f);
  EXPECT_EQ(data.lights[3].selectCdf, 1.0f);

  const SceneView view = viewOf(data.lights);
  std::vector<int> picked(data.lights.size(), 0);
  const int n = 100000;
  for (int k = 0; k < n; ++k) ++picked[selectLight(view, (k + 0.5f) / n)];
  EXPECT_NEAR(picked[1], 0.25 * n, 1.0);
  EXPECT_NEAR(picked[3], 0.75 * n, 1.0);
  EXPECT_EQ(picked[1] + picked[3], n);
  EXPECT_EQ(selectLight(view, 0.0f), 1);
  EXPECT_EQ(selectLight(view, 0.99999994f), 3);  // the largest float below 1
}

TEST(LightSelection, NoLightWithPowerPicksNothing) {
  std::vector<Light> lights(3);  // default lights have no power
  EXPECT_EQ(selectLight(viewOf(lights), 0.5f), -1);
  EXPECT_EQ(selectLight(viewOf({}), 0.5f), -1);
}

}  // namespace
}  // namespace candela
