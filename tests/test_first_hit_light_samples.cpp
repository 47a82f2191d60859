// Several light samples at a path's first interaction (render.first_hit_light_samples,
// SceneView::firstHitLightSamples): where they apply, that the plane under a sun with a disc, an
// environment and a point light is still the sum of their closed forms with three of them (each
// sample and each BSDF sample that finds a light weighed as one of that many), that a room lit by
// a lamp of many triangles renders the same image with two as with one and with less noise, and
// what the scene format takes. The plane under a rectangle light with four is in
// test_rectangle_light.cpp; the pilot's choice in test_render_pilot.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/constants.h"
#include "render/view_adjustment.h"
#include "render_test_util.h"

namespace candela {
namespace {

using test::num;

std::string withSamples(const std::string& lights, const std::string& samples) {
  return R"({"camera": {"width": 8, "height": 8},
             "render": {"first_hit_light_samples": )" +
         samples + R"(},
             "spheres": [{"position": [0, 0, -5], "radius": 1, "color": 0.5}],
             "lights": [)" +
         lights + "]}";
}

TEST(FirstHitLightSamples, TakeEffectOnlyWhereALightIsPicked) {
  const std::string twoSpheres =
      R"({"type": "sphere", "position": [2, 2, 0], "radius": 0.5, "intensity": 10},
         {"type": "sphere", "position": [-2, 2, 0], "radius": 0.5, "intensity": 10})";
  EXPECT_EQ(test::loadTestScene(withSamples(twoSpheres, "3")).view().firstHitLightSamples, 3u);
  // "auto" without a pilot: one.
  EXPECT_EQ(test::loadTestScene(withSamples(twoSpheres, "\"auto\"")).view().firstHitLightSamples,
            1u);
  // A lone point light, or each of a few, is sampled without a pick: more samples would repeat it.
  const std::string point = R"({"position": [0, 3, 0], "intensity": 10})";
  const SceneData lone = test::loadTestScene(withSamples(point, "4"));
  EXPECT_TRUE(lone.view().loneDeltaLight);
  EXPECT_EQ(lone.view().firstHitLightSamples, 1u);
  const SceneData few =
      test::loadTestScene(withSamples(point + R"(, {"position": [1, 3, 0], "intensity": 5})", "4"));
  EXPECT_EQ(few.view().firstHitDeltaLights, 2u);
  EXPECT_EQ(few.view().firstHitLightSamples, 1u);
  // A render's adjustment (the pilot's choice) overrides the scene's, where it applies.
  ViewAdjustment two;
  two.firstHitLightSamples = 2;
  EXPECT_EQ(adjustedView(test::loadTestScene(withSamples(twoSpheres, "3")).view(), two)
                .firstHitLightSamples,
            2u);
  EXPECT_EQ(adjustedView(lone.view(), two).firstHitLightSamples, 1u);
}

TEST(FirstHitLightSamples, TheSceneFormatTakesAutoOrOneToFour) {
  const std::string light =
      R"({"type": "sphere", "position": [2, 2, 0], "radius": 0.5, "intensity": 10})";
  for (const char* bad : {"0", "5", "7", "1.5", "-1", "\"two\"", "true"}) {
    const std::string error = test::loadError(withSamples(light, bad), ".");
    EXPECT_NE(error.find("render.first_hit_light_samples"), std::string::npos) << error;
    EXPECT_NE(error.find("expected \"auto\" or an integer from 1 to 4, got "), std::string::npos)
        << error;
  }
  EXPECT_EQ(test::loadError(withSamples(light, "4"), "."), "(no error)");
  EXPECT_EQ(test::loadTestScene(withSamples(light, "\"auto\"")).settings.firstHitLightSamples, 0u);
}

// The plane y = 0 under a sun with a disc wide enough for BSDF samples to find, a uniform
// environment and a point light, pixel centres, one bounce, three light samples at the first
// interaction: every pixel is the sum of the closed forms, rho E cos / pi for the sun,
// rho I cos / d^2 / pi for the point light and rho Le for the environment's upper hemisphere.
// Weighing the BSDF's samples that find the sun or the environment against one light sample
// rather than three would brighten it by several percent.
TEST(FirstHitLightSamples, ThePlaneUnderLightsAtInfinityIsStillTheSumOfItsClosedForms) {
  const std::string obj = test::writePlaneObj("first_hit_samples_plane.obj", 100);
  const double rho = 0.5, environment = 0.3, sunIrradiance = 2.0;
  const double px = -2, py = 4, pz = 1, power = 600;
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 24, "height": 24, "fov": 50, "position": [0, 8, 0],
               "look_at": [0, 0, 0.001], "up": [0, 0, -1], "spp": 128},
    "render": {"max_depth": 1, "antialiasing": false, "first_hit_light_samples": 3},
    "environment": {"color": )" + num(environment) +
                                             R"(},
    "objects": [{"file": ")" + obj + R"(", "color": )" +
                                             num(rho) + R"(}],
    "lights": [{"type": "directional", "direction": [0.5, -1, 0], "intensity": )" +
                                             num(sunIrradiance) + R"(, "angle": 40},
               {"position": [-2, 4, 1], "intensity": 600}]})");
  ASSERT_EQ(data.view().firstHitLightSamples, 3u);
  const RenderResult r = renderCpu(data.view(), RenderOptions{});
  const double sun = rho * sunIrradiance * (1 / std::sqrt(1.25)) / kPi;
  ImageRGB ratios(24, 24);
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 24; ++x) {
      const Vec3 d =
          data.camera.cameraToWorld * (data.camera.inverseK * Vec3(x + 0.5f, y + 0.5f, 1.0f));
      const double t = -double(data.camera.position.y) / d.y;
      const double ax = data.camera.position.x + t * d.x, az = data.camera.position.z + t * d.z;
      const double dx = px - ax, dz = pz - az, d2 = dx * dx + py * py + dz * dz;
      const double point = rho * power * (py / std::sqrt(d2)) / (4 * kPi * kPi * d2);
      ratios.set(x, y, Vec3(float(r.image.at(x, y).x / (sun + point + rho * environment))));
    }
  const test::RegionStats s = test::regionStats(ratios, 0, 0, 24, 24, 0);
  EXPECT_NEAR(s.mean, 1.0, 5 * s.standardError() + 1e-3);
  EXPECT_LT(s.standardError(), 0.004);  // fine enough to see a few percent
}

// The small room of test::torusUnderTheCeiling, lit by a torus of 3,072 emitting triangles: two
// light samples at the first interaction render the same image as one (16 x 16 blocks), and with
// at least 1.1 times less noise (measured: 1.34).
TEST(FirstHitLightSamples, ARoomLitByAMeshLampRendersTheSameImageWithLessNoise) {
  const auto room = [](int seed, int samples) {
    return test::torusUnderTheCeiling(R"("width": 48, "height": 32, "spp": 16)",
                                      R"("max_depth": 3, "seed": )" + std::to_string(seed) +
                                          R"(, "first_hit_light_samples": )" +
                                          std::to_string(samples));
  };
  const auto renderPair = [&](int samples) {
    test::SeedPair p;
    for (int seed : {1, 2}) {
      const SceneData data = test::loadTestScene(room(seed, samples));
      EXPECT_EQ(data.view().firstHitLightSamples, uint32_t(samples));
      (seed == 1 ? p.a : p.b) = renderCpu(data.view(), RenderOptions{});
    }
    return p;
  };
  const test::SeedPair one = renderPair(1), two = renderPair(2);
  EXPECT_GT(two.a.rays.shadow, one.a.rays.shadow);
  const auto [noiseOne, noiseTwo] = test::expectSameImage(one, two, 16);
  EXPECT_LT(noiseTwo * 1.1, noiseOne) << noiseOne / noiseTwo;
}

}  // namespace
}  // namespace candela
