// Light-vertex connections (render/light_path.h): which lights start subpaths, that a room lit
// by a point light renders the same image with them as without, with less noise, and the same
// image with them at the first interactions alone (render.light_path_depth). The closed forms of
// test_render_closed_form.cpp (the furnace inside a lit sphere, the lit plane) run with them too.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render/light_emission.h"
#include "render/light_path.h"
#include "render_test_util.h"
#include "temp_dir.h"

namespace candela {
namespace {

// The three strategies' weights of one path sum to one under either heuristic; a light that
// starts no subpaths keeps the power heuristic, to the bit powerHeuristic between two, and one
// that does gets the balance heuristic.
TEST(LightPaths, MisWeightsOfAPathSumToOneUnderTheLightsHeuristic) {
  const float densities[][3] = {{1, 3, 0.5f}, {2, 0, 7}, {0.25f, 0.25f, 0}, {1e-3f, 40, 2}};
  for (const auto& d : densities) {
    for (bool startsSubpaths : {false, true}) {
      const float sum = misWeight3(d[0], d[1], d[2], startsSubpaths) +
                        misWeight3(d[1], d[0], d[2], startsSubpaths) +
                        misWeight3(d[2], d[0], d[1], startsSubpaths);
      EXPECT_NEAR(sum, 1.0f, 1e-6f) << d[0] << " " << d[1] << " " << d[2];
    }
    EXPECT_EQ(misWeight3(d[0], d[1], 0.0f, false), powerHeuristic(d[0], d[1]));
    EXPECT_FLOAT_EQ(misWeight3(d[0], d[1], d[2], true), d[0] / (d[0] + d[1] + d[2]));
  }
  EXPECT_FLOAT_EQ(misWeight3(1, 3, 0, true), 0.25f);
  EXPECT_FLOAT_EQ(misWeight3(1, 3, 0, false), 0.1f);
}

TEST(LightPaths, EveryLightButTheEnvironmentStartsSubpathsByPower) {
  // Powers (RGB sums): 30, a sphere light of intensity 100 (300), 60, 30; 420 in all.
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4, "spp": 1},
    "environment": {"color": 0.2},
    "spheres": [{"position": [0, -1000, 0], "radius": 999, "color": 0.5}],
    "lights": [{"position": [0, 1, 0], "intensity": 10},
               {"type": "sphere", "position": [3, 1, 0], "radius": 0.5, "intensity": 100},
               {"position": [1, 1, 0], "intensity": 10, "color": [2, 2, 2]},
               {"position": [2, 1, 0], "intensity": 10}]})");
  const SceneView view = data.view();
  ASSERT_EQ(view.lightCount, 5u);
  EXPECT_EQ(view.lightPathLights, 4u);
  EXPECT_TRUE(view.areaLightPaths);
  const float expected[] = {30.0f / 420, 300.0f / 420, 60.0f / 420, 30.0f / 420};
  uint32_t point = 0;
  for (uint32_t i = 0; i < view.lightCount; ++i) {
    if (view.lights[i].type == LightType::Environment) {
      EXPECT_EQ(lightPathPmf(view, i), 0.0f);
      continue;
    }
    EXPECT_NEAR(lightPathPmf(view, i), expected[point++], 1e-6f) << "light " << i;
  }
  ASSERT_EQ(point, 4u);
  ASSERT_EQ(view.lights[4].type, LightType::Environment);  // the lights as declared, then it
  EXPECT_EQ(pickLightPathLight(view, 0.0f), 0u);
  EXPECT_EQ(pickLightPathLight(view, 0.07f), 0u);
  EXPECT_EQ(pickLightPathLight(view, 0.072f), 1u);
  EXPECT_EQ(pickLightPathLight(view, 0.78f), 1u);
  EXPECT_EQ(pickLightPathLight(view, 0.79f), 2u);
  EXPECT_EQ(pickLightPathLight(view, 0.93f), 3u);
  EXPECT_EQ(pickLightPathLight(view, 0.99999994f), 3u);  // the largest float below 1
  // The density of the vertex straight below light 2, at distance 2: pick 1/7, 1 / (4 pi 2^2).
  EXPECT_FLOAT_EQ(lightVertexPdf(view, 2, 0.0f, Vec3(1, -1, 0), Vec3(0, 1, 0)),
                  (1.0f / 7.0f) / (4.0f * kPi * 4.0f));
}

TEST(LightPaths, PointLightsAloneDrawNoNumbersForAPoint) {
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4, "spp": 1},
    "lights": [{"position": [0, 1, 0], "intensity": 10},
               {"position": [1, 1, 0], "intensity": 5}]})");
  EXPECT_EQ(data.view().lightPathLights, 2u);
  EXPECT_FALSE(data.view().areaLightPaths);
}

// Points from sampleEmissionPoint lie on the light's surface, uniformly (their mean is the
// shape's centroid), with the emitting side's normal; emissionAreaPdf is one over the area.
TEST(LightPaths, EmissionPointsAreUniformOverTheLightsSurface) {
  const test::TempDir dir;
  const std::string quad = dir.write("lamp.obj",
                                     "v -3.5 5.9 -3.5\nv -2.5 5.9 -3.5\nv -2.5 5.9 -2.5\n"
                                     "v -3.5 5.9 -2.5\nf 1 2 3 4\n");
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4, "spp": 1},
    "objects": [{"file": ")" + quad + R"(", "material": {"type": "emissive", "radiance": 3}}],
    "lights": [{"type": "sphere", "position": [1, 2, 3], "radius": 0.5, "intensity": 100}]})");
  const SceneView view = data.view();
  for (uint32_t i = 0; i < view.lightCount; ++i) {
    const Light& light = view.lights[i];
    const bool sphere = light.type == LightType::Sphere;
    EXPECT_NEAR(emissionAreaPdf(view, light, 0.0f), sphere ? 1.0f / kPi : 2.0f, 1e-5f);
    Vec3 mean(0.0f);
    const int n = 4096;
    for (int k = 0; k < n; ++k) {
      const EmissionPoint e = sampleEmissionPoint(view, light, 0.0f, (k + 0.5f) / n,
                                                  float((k * 2654435761u) % 4096u) / 4096.0f);
      mean += e.p / float(n);
      if (sphere) {
        EXPECT_NEAR(length(e.p - Vec3(1, 2, 3)), 0.5f, 1e-5f);
        EXPECT_NEAR(length(e.n * 0.5f - (e.p - Vec3(1, 2, 3))), 0.0f, 1e-5f);
      } else {
        EXPECT_NEAR(e.p.y, 5.9f, 1e-5f);
        EXPECT_NEAR(e.n.y, -1.0f, 1e-6f);  // the side that faces the room
        EXPECT_EQ(e.radiance.x, 3.0f);
      }
    }
    const Triangle& tri = view.triangles[light.shape];
    const Vec3 centroid = sphere ? Vec3(1, 2, 3)
                                 : (view.positions[tri.v[0]] + view.positions[tri.v[1]] +
                                    view.positions[tri.v[2]]) / 3.0f;
    EXPECT_LT(length(mean - centroid), 0.01f) << "light " << i;
  }
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
      if (!connections) data.lightsStartingPaths = 0;
      EXPECT_EQ(data.view().lightPathLights, connections ? 1u : 0u);
      (seed == 1 ? p.a : p.b) = renderCpu(data.view(), RenderOptions{});
    }
    return p;
  };
  const auto [noiseWith, noiseWithout] = test::expectSameImage(renderPair(true), renderPair(false));
  EXPECT_LT(noiseWith * 1.5, noiseWithout);
}

// The small room lit instead by lights with a surface that brighten a patch of its ceiling (a
// sphere light under it, behind the camera, and an emissive quad facing up, whose dark back the
// camera sees), which light subpaths now start from too: the same image with the connections as
// without them, 16 x 16 blocks (without them the image is heavy-tailed: a few samples find the
// bright patch), and at least 2 times less noisy (measured: 12 and 6 times).
TEST(LightPaths, ARoomLitByASurfaceRendersTheSameImageWithLessNoise) {
  const test::TempDir dir;
  const std::string quad = dir.write("lamp.obj",
                                     "v -3.5 4.5 -3.5\nv -3.5 4.5 -2.5\nv -2.5 4.5 -2.5\n"
                                     "v -2.5 4.5 -3.5\nf 1 2 3 4\n");
  const std::string lamps[] = {
      R"("lights": [{"type": "sphere", "position": [-3, 4, 9.5], "radius": 0.5,
                     "intensity": 400}])",
      R"("objects": [{"file": ")" + quad +
          R"(", "material": {"type": "emissive", "radiance": 40}}])"};
  for (const std::string& lamp : lamps) {
    SCOPED_TRACE(lamp);
    const auto room = [&](int seed) {
      return R"({
        "camera": {"fov": 70, "position": [0, 2, 9], "look_at": [0, 2, 0], "width": 48,
                   "height": 32, "spp": 16},
        "render": {"max_depth": 4, "seed": )" +
             std::to_string(seed) + R"(},
        "spheres": [)" +
             std::string(test::kSmallRoomWalls) + R"(,
                    {"position": [1, 1, -1], "radius": 1, "color": 0.5}],
        )" + lamp + "}";
    };
    const auto renderPair = [&](bool connections) {
      test::SeedPair p;
      for (int seed : {1, 2}) {
        SceneData data = test::loadTestScene(room(seed));
        if (!connections) data.lightsStartingPaths = 0;
        EXPECT_EQ(data.view().lightPathLights > 0, connections);
        (seed == 1 ? p.a : p.b) = renderCpu(data.view(), RenderOptions{});
      }
      return p;
    };
    const auto [noiseWith, noiseWithout] =
        test::expectSameImage(renderPair(true), renderPair(false), 16);
    EXPECT_LT(noiseWith * 2, noiseWithout);
  }
}

// Connections at a path's first one or two interactions alone (render.light_path_depth, the
// pilot's other choice): the rest of the path weighs its next-event estimation and BSDF samples
// against no connection from an interaction that makes none, so the image stays the same as with
// connections at every interaction; in the room lit by a point light near its ceiling and in the
// one lit by a sphere light under it (whose BSDF-sampled hits are weighed against the
// connections too), 16 x 16 blocks over two seeds each, max_depth 5.
TEST(LightPaths, ConnectionsAtTheFirstInteractionsAloneRenderTheSameImage) {
  const std::string lamps[] = {
      R"([{"position": [-3, 5.5, -3], "intensity": 400}])",
      R"([{"type": "sphere", "position": [-3, 4, -3], "radius": 0.5, "intensity": 400}])"};
  for (const std::string& lamp : lamps) {
    SCOPED_TRACE(lamp);
    const auto renderPair = [&](const char* depth) {
      test::SeedPair p;
      for (int seed : {1, 2}) {
        const SceneData data = test::loadTestScene(
            test::smallRoomLitBy(R"("width": 48, "height": 32, "spp": 32)",
                                 R"("max_depth": 5, "light_paths": "on", "light_path_depth": )" +
                                     std::string(depth) + ", \"seed\": " + std::to_string(seed),
                                 R"("lights": )" + lamp));
        (seed == 1 ? p.a : p.b) = renderCpu(data.view(), RenderOptions{});
      }
      return p;
    };
    const test::SeedPair every = renderPair("\"all\"");
    for (const char* depth : {"1", "2"}) {
      SCOPED_TRACE(depth);
      const test::SeedPair first = renderPair(depth);
      EXPECT_NE(first.a.rays.shadow, every.a.rays.shadow);  // fewer connections were made
      test::expectSameImage(every, first, 16);
    }
  }
}

// render.light_path_depth: "all" (the default), "auto" (the pilot's), or the deepest interaction
// connected;
// anything else is one error naming the field and what it takes.
TEST(LightPaths, TheSceneSetsTheirDepth) {
  const auto withDepth = [](const std::string& depth) {
    return R"({"camera": {"width": 4, "height": 4, "spp": 1}, "render": {"light_path_depth": )" +
           depth + R"(}, "lights": [{"position": [0, 1, 0], "intensity": 10}]})";
  };
  const std::string unset =
      R"({"camera": {"width": 4, "height": 4, "spp": 1}, "lights": [{"position": [0, 1, 0], "intensity": 10}]})";
  EXPECT_EQ(test::loadTestScene(unset).settings.lightPathDepth, kEveryInteraction);  // the default
  EXPECT_EQ(test::loadTestScene(withDepth("\"auto\"")).settings.lightPathDepth, 0u);
  EXPECT_EQ(test::loadTestScene(withDepth("\"auto\"")).view().lightPathDepth, kEveryInteraction);
  EXPECT_EQ(test::loadTestScene(withDepth("\"all\"")).view().lightPathDepth, kEveryInteraction);
  EXPECT_EQ(test::loadTestScene(withDepth("2")).view().lightPathDepth, 2u);
  EXPECT_EQ(test::loadTestScene(withDepth("1e12")).view().lightPathDepth, kEveryInteraction);
  for (const char* bad : {"0", "-1", "1.5", "\"every\"", "true", "[2]"}) {
    const std::string error = test::loadError(withDepth(bad), ".");
    EXPECT_NE(error.find("render.light_path_depth"), std::string::npos) << bad << ": " << error;
    EXPECT_NE(error.find("expected \"auto\", \"all\" or a positive integer, got "),
              std::string::npos)
        << bad << ": " << error;
  }
}

}  // namespace
}  // namespace candela
