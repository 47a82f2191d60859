// Light selection for next-event estimation: the power-proportional pmf the scene loader sets and
// the alias table that picks a light from it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "render/light_sample.h"
#include "render_test_util.h"
#include "scene/light_selection.h"

namespace candela {
namespace {

SceneView viewOf(const std::vector<Light>& lights) {
  SceneView v;
  v.lights = lights.data();
  v.lightCount = static_cast<uint32_t>(lights.size());
  return v;
}

TEST(LightSelection, FewPointLightsAreEachSampled) {
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4, "fov": 40},
    "lights": [{"position": [0, 1, 0], "intensity": 0},
               {"position": [0, 1, 0], "intensity": 2},
               {"position": [0, 5, 0], "intensity": 3}]})");
  ASSERT_EQ(data.lights.size(), 3u);
  EXPECT_TRUE(data.sampleEveryLight);
  EXPECT_TRUE(data.view().sampleEveryLight);
  for (const Light& l : data.lights) EXPECT_EQ(l.selectPmf, 1.0f);
}

// With an area light among few lights, one light is picked by power; the unlit one never.
TEST(LightSelection, FewLightsWithAnAreaLightArePickedByPower) {
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4, "fov": 40},
    "lights": [{"position": [0, 1, 0], "intensity": 0},
               {"position": [0, 1, 0], "intensity": 2},
               {"type": "sphere", "position": [0, 5, 0], "radius": 1, "intensity": 3}]})");
  ASSERT_EQ(data.lights.size(), 3u);
  EXPECT_FALSE(data.sampleEveryLight);
  EXPECT_EQ(data.lights[0].selectPmf, 0.0f);
  EXPECT_GT(data.lights[1].selectPmf, 0.0f);
  EXPECT_GT(data.lights[2].selectPmf, 0.0f);
  EXPECT_NEAR(data.lights[1].selectPmf + data.lights[2].selectPmf, 1.0f, 1e-6f);
}

// The environment takes half the picks beside other lights, however large the scene's bounds
// (a ground sphere of radius 1000 once made its estimated power dwarf a lamp's); the other
// lights share the rest by power. Alone, it takes them all.
TEST(LightSelection, EnvironmentTakesHalfThePicksBesideOtherLights) {
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4, "fov": 40},
    "environment": {"color": 0.5},
    "spheres": [{"position": [0, -1000, 0], "radius": 1000}],
    "lights": [{"type": "sphere", "position": [0, 5, 0], "radius": 1, "intensity": 10},
               {"type": "sphere", "position": [0, 5, 3], "radius": 1, "intensity": 30}]})");
  ASSERT_EQ(data.lights.size(), 3u);
  float environment = 0.0f;
  for (const Light& l : data.lights)
    if (l.type == LightType::Environment) environment = l.selectPmf;
  EXPECT_NEAR(environment, 0.5f, 1e-6f);
  EXPECT_NEAR(data.lights[0].selectPmf, 0.125f, 1e-6f);
  EXPECT_NEAR(data.lights[1].selectPmf, 0.375f, 1e-6f);

  const SceneData alone = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4, "fov": 40}, "environment": {"color": 0.5},
    "spheres": [{"position": [0, -1000, 0], "radius": 1000}]})");
  ASSERT_EQ(alone.lights.size(), 1u);
  EXPECT_EQ(alone.lights[0].selectPmf, 1.0f);
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
                                                 "lights": [)" +
                                             lights + "]}");
  ASSERT_EQ(data.lights.size(), kSampleEveryLightUpTo + 1);
  // Powers (RGB sums): 0, 6, 0, 18, then nothing.
  for (size_t i = 0; i < data.lights.size(); ++i)
    EXPECT_NEAR(data.lights[i].selectPmf, i == 1 ? 0.25f : (i == 3 ? 0.75f : 0.0f), 1e-7f);

  const SceneView view = viewOf(data.lights);
  std::vector<int> picked(data.lights.size(), 0);
  const int n = 100000;
  for (int k = 0; k < n; ++k) ++picked[selectLight(view, (k + 0.5f) / n)];
  // Stratified u: each of the table's slots is off by at most one pick.
  const double slots = double(data.lights.size());
  EXPECT_NEAR(picked[1], 0.25 * n, slots);
  EXPECT_NEAR(picked[3], 0.75 * n, slots);
  EXPECT_EQ(picked[1] + picked[3], n);
  for (float u : {0.0f, 0.5f, 0.99999994f})  // 0.99999994: the largest float below 1
    EXPECT_TRUE(selectLight(view, u) == 1 || selectLight(view, u) == 3) << u;
}

// The alias table over many lights of random powers, some without: each is picked in proportion
// to its power (stratified u, so each slot is off by at most one pick) and never without power.
TEST(LightSelection, AliasTableFollowsThePowers) {
  std::vector<Light> lights(1000);
  std::vector<double> powers(lights.size());
  uint32_t state = 12345;
  double total = 0;
  for (size_t i = 0; i < powers.size(); ++i) {
    state = state * 1664525u + 1013904223u;
    powers[i] = i % 7 == 0 ? 0.0 : double(state >> 8) / double(1u << 24) * (i % 3 + 1);
    total += powers[i];
  }
  setLightSelection(lights, powers);
  const SceneView view = viewOf(lights);
  std::vector<int> picked(lights.size(), 0);
  const int n = 2000000;
  for (int k = 0; k < n; ++k) {
    const int i = selectLight(view, (k + 0.5f) / n);
    ASSERT_GE(i, 0);
    ++picked[size_t(i)];
  }
  for (size_t i = 0; i < lights.size(); ++i) {
    EXPECT_NEAR(lights[i].selectPmf, powers[i] / total, 1e-6) << i;
    if (powers[i] == 0.0) {
      EXPECT_EQ(picked[i], 0) << i;
    }
    // float u resolves n samples only to ~1e-7 of [0, 1): a few picks of rounding besides.
    EXPECT_NEAR(picked[i], powers[i] / total * n, double(lights.size()) * 1e-3 + 4.0) << i;
  }
}

TEST(LightSelection, NoLightWithPowerPicksNothing) {
  std::vector<Light> lights(3);  // default lights have no power
  EXPECT_EQ(selectLight(viewOf(lights), 0.5f), -1);
  EXPECT_EQ(selectLight(viewOf({}), 0.5f), -1);
}

}  // namespace
}  // namespace candela
