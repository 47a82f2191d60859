// The pilot render (backends/render_pilot.h): the sparse pixels it renders, the choice it makes
// where connections clearly pay and where they clearly do not, of their depth where the deeper
// ones pay and where they do not, and of light samples at the first interaction where a second
// pays and where it does not, that the choices are the same on any thread count, and when it is
// skipped.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "backends/render_pilot.h"
#include "render/render_pixel.h"
#include "render_test_util.h"

namespace candela {
namespace {

// The room of test::lampUnderTheCeiling, square: the pilot measured about 0.16 of the
// variance x cost without connections.
std::string lampUnderTheCeiling(int width, int spp, const std::string& render = "") {
  return test::lampUnderTheCeiling("\"width\": " + std::to_string(width) + ", \"height\": " +
                                       std::to_string(width) + ", \"spp\": " + std::to_string(spp),
                                   "\"max_depth\": 4, \"seed\": 3" + render);
}

// Two balls on an open floor under a lamp 50 units up: half the light's rays leave the scene,
// the rest land on the floor, lit evenly, where BSDF samples find as much; connections only cost
// (the pilot measured about 1.8 times the variance x cost with them).
std::string lampHighAboveAnOpenFloor(const std::string& render = "") {
  return R"({
    "camera": {"width": 256, "height": 256, "fov": 50, "position": [0, 3, 8],
               "look_at": [0, 0.8, 0], "spp": 16},
    "render": {"max_depth": 4, "seed": 1)" +
         render + R"(},
    "spheres": [{"position": [0, -1000, 0], "radius": 1000, "color": 0.6},
                {"position": [0, 1, 0], "radius": 1, "color": [0.7, 0.5, 0.3]},
                {"position": [-1.8, 0.6, 0.5], "radius": 0.6, "color": 0.8}],
    "lights": [{"position": [0, 50, 0], "intensity": 4000}]})";
}

RenderOptions twoSamplesAPixel() {
  RenderOptions o;
  o.samples = {0, 2};
  return o;
}

PilotChoice choose(const SceneData& scene, int threads = 0) {
  CpuRenderer renderer(CpuEngine::Bvh);
  renderer.setScene(scene, SceneChange::Structure);
  RenderOptions options;
  options.threads = threads;
  return choosePilot(renderer, scene, options);
}

TEST(ViewAdjustment, AStrideRendersTheMiddlePixelOfEachBlock) {
  // Direct light from a lone point light through pixel centres draws no random number, so each
  // pixel is one exact value: the strided render's pixel (x, y) is the full render's
  // (4x + 2, 4y + 2).
  const SceneData scene = test::loadTestScene(R"({
    "camera": {"width": 18, "height": 13, "fov": 60, "position": [0, 1, 6], "look_at": [0, 1, 0],
               "spp": 1},
    "render": {"max_depth": 1, "antialiasing": false},
    "spheres": [{"position": [0, -1000, 0], "radius": 1000, "color": 0.6},
                {"position": [0.5, 1, 0], "radius": 1, "color": [0.7, 0.5, 0.3]}],
    "lights": [{"position": [2, 5, 3], "intensity": 100}]})");
  RenderOptions full, strided;
  strided.adjust.pixelStride = 4;
  const SceneView view = scene.view();
  const RenderResult a = renderCpu(view, full), b = renderCpu(view, strided);
  ASSERT_EQ(b.image.width, 4u);  // 18 / 4: the last, partial block is left out
  ASSERT_EQ(b.image.height, 3u);
  double sum = 0;
  for (uint32_t y = 0; y < 3; ++y)
    for (uint32_t x = 0; x < 4; ++x) {
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(b.image.at(x, y)[c], a.image.at(4 * x + 2, 4 * y + 2)[c]) << x << ", " << y;
      sum += b.image.at(x, y).x;
    }
  EXPECT_GT(sum, 0.0);  // the comparison saw lit pixels
  EXPECT_EQ(adjustedView(view, strided.adjust).camera.pixelStride, 4u);
  EXPECT_EQ(view.camera.pixelStride, 1u);
}

TEST(ViewAdjustment, ReseedsAndTurnsLightPathsOffForOneRender) {
  const SceneData scene = test::loadTestScene(lampUnderTheCeiling(16, 4));
  ViewAdjustment adjust;
  adjust.lightPaths = false;
  adjust.reseed = true;
  adjust.seed = 77;
  const SceneView view = adjustedView(scene.view(), adjust);
  EXPECT_EQ(view.lightPathLights, 0u);
  EXPECT_EQ(view.settings.seed, 77u);
  EXPECT_EQ(scene.view().lightPathLights, 1u);
  EXPECT_EQ(scene.view().settings.seed, 3u);
}

// Each pixel's noise counts relative to its value, as the bench's relMSE counts it: the same
// difference between two seeds' renders weighs (bright^2 + 0.01 m^2) / (dark^2 + 0.01 m^2) times
// more in a dark half than in a bright one, and a weight is 1 / (v^2 + 0.01 m^2) exactly.
TEST(LightPathPilot, WeighsEachPixelsNoiseRelativeToItsValue) {
  const uint32_t w = 8, h = 8;
  ImageRGB image(w, h);  // the left half dark (0.1), the right bright (1.9): the mean is 1
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) image.set(x, y, Vec3(x < w / 2 ? 0.1f : 1.9f));
  const std::vector<double> weights = relativeErrorWeights({&image, &image});
  ASSERT_EQ(weights.size(), size_t(3) * w * h);
  EXPECT_NEAR(weights[0], 1.0 / (0.01 + 0.01), 1e-4);      // (0, 0): dark all around
  EXPECT_NEAR(weights[3 * 7], 1.0 / (3.61 + 0.01), 1e-6);  // (7, 0): bright all around

  ImageRGB darkNoise = image, brightNoise = image;
  for (uint32_t y = 0; y < h; ++y) {
    darkNoise.set(0, y, image.at(0, y) + Vec3(0.05f));
    brightNoise.set(7, y, image.at(7, y) + Vec3(0.05f));
  }
  const double dark = relativeVariance(darkNoise, image, weights);
  const double bright = relativeVariance(brightNoise, image, weights);
  EXPECT_NEAR(dark, 3.0 * h * 0.0025 * weights[0] / (2 * 3 * w * h), 1e-6 * dark);
  EXPECT_NEAR(dark / bright, 3.62 / 0.02, 0.01 * 3.62 / 0.02);
}

// A pixel's weight comes from its neighbourhood, not its own value alone: one pixel that came out
// dark amid bright ones (a render's noise) does not weigh as a dark region would.
TEST(LightPathPilot, TakesAPixelsWeightFromItsNeighbourhood) {
  ImageRGB image(5, 5);
  for (uint32_t y = 0; y < 5; ++y)
    for (uint32_t x = 0; x < 5; ++x) image.set(x, y, Vec3(1.0f));
  image.set(2, 2, Vec3(0.0f));
  const std::vector<double> weights = relativeErrorWeights({&image});
  const double m = 24.0 / 25, v = 8.0 / 9;  // the mean; the centre's 3x3 mean
  EXPECT_NEAR(weights[3 * 12], 1.0 / (v * v + 0.01 * m * m), 1e-6);
  EXPECT_LT(weights[3 * 12], 2 * weights[0]);
}

// The connections go off only where going without them is at least 10% cheaper: the one-sample
// pilot understates their gain, so a near tie keeps them.
TEST(LightPathPilot, TurnsThemOffOnlyWhereClearlyCheaperWithout) {
  EXPECT_TRUE(pilotKeepsLightPaths(1.0, 0.95));  // 5% cheaper without: a near tie
  EXPECT_TRUE(pilotKeepsLightPaths(1.0, 0.905));
  EXPECT_FALSE(pilotKeepsLightPaths(1.0, 0.895));
  EXPECT_FALSE(pilotKeepsLightPaths(1.8, 1.0));
  EXPECT_TRUE(pilotKeepsLightPaths(1.0, 1.2));
  EXPECT_TRUE(pilotKeepsLightPaths(std::nan(""), std::nan("")));  // an image without light
}

TEST(LightPathPilot, KeepsLightPathsWhereALampLightsTheCeilingOfASmallRoom) {
  const PilotChoice c = choose(test::loadTestScene(lampUnderTheCeiling(256, 16)));
  EXPECT_TRUE(c.piloted);
  EXPECT_TRUE(c.lightPaths);
  EXPECT_LT(c.withLightPaths, 0.5 * c.withoutLightPaths);
  EXPECT_GT(c.rays.camera, 0u);
}

// The Cornell box, lit by its ceiling quad, which the camera sees: the connections pay there
// (full renders: 0.72 of the relMSE x time without them), but the quad's rim, noisy alike either
// way and far brighter than the rest, outweighed that while the pilot weighed each pixel's
// noise absolutely (1.5 times worse on every seed); weighed relative to each pixel's value, as
// relMSE weighs it, 0.92.
TEST(LightPathPilot, KeepsThemForTheCornellBoxWhoseLampIsSeen) {
  const std::string cornell = std::string(CANDELA_SOURCE_DIR) + "/scenes/meshes/cornell/";
  const PilotChoice c = choose(test::loadTestScene(R"({
    "camera": {"width": 128, "height": 128, "fov": 39.3, "position": [2.78, 2.73, -8.0],
               "look_at": [2.78, 2.73, 0], "spp": 64},
    "render": {"max_depth": 5, "seed": 11},
    "objects": [{"file": ")" + cornell + R"(white.obj", "color": [0.725, 0.71, 0.68]},
                {"file": ")" + cornell + R"(red.obj", "color": [0.63, 0.065, 0.05]},
                {"file": ")" + cornell + R"(green.obj", "color": [0.14, 0.45, 0.091]},
                {"file": ")" + cornell + R"(lamp.obj",
                 "material": {"type": "emissive", "radiance": [17, 12, 4]}}]})"));
  EXPECT_TRUE(c.piloted);
  EXPECT_TRUE(c.lightPaths);
}

TEST(LightPathPilot, TurnsThemOffUnderALampHighAboveAnOpenFloor) {
  const PilotChoice c = choose(test::loadTestScene(lampHighAboveAnOpenFloor()));
  EXPECT_TRUE(c.piloted);
  EXPECT_FALSE(c.lightPaths);
  EXPECT_GT(c.withLightPaths, 1.2 * c.withoutLightPaths);
}

TEST(LightPathPilot, ChoosesAlikeOnAnyThreadCount) {
  const SceneData scene = test::loadTestScene(lampHighAboveAnOpenFloor());
  const PilotChoice one = choose(scene, 1), two = choose(scene, 2), three = choose(scene, 3);
  EXPECT_EQ(one.withLightPaths, two.withLightPaths);
  EXPECT_EQ(one.withoutLightPaths, two.withoutLightPaths);
  EXPECT_EQ(one.withLightPaths, three.withLightPaths);
  EXPECT_EQ(one.withoutLightPaths, three.withoutLightPaths);
}

TEST(LightPathPilot, TheSceneSettingDecidesWithoutAPilot) {
  for (const char* setting : {"on", "off"}) {
    // At every interaction, so that their depth is not the pilot's either.
    const PilotChoice c = choose(test::loadTestScene(lampHighAboveAnOpenFloor(
        std::string(R"(, "light_path_depth": "all", "light_paths": ")") + setting + "\"")));
    EXPECT_FALSE(c.piloted) << setting;
    EXPECT_EQ(c.lightPaths, std::string(setting) == "on");
    EXPECT_EQ(c.rays.total(), 0u);
  }
  // "off" renders what the pilot's choice of none renders, and not what "on" does.
  const SceneData off =
      test::loadTestScene(lampUnderTheCeiling(16, 4, R"(, "light_paths": "off")"));
  const SceneData on = test::loadTestScene(lampUnderTheCeiling(16, 4, R"(, "light_paths": "on")"));
  EXPECT_EQ(off.view().lightPathLights, 0u);
  RenderOptions none;
  none.adjust.lightPaths = false;
  EXPECT_EQ(renderCpu(off.view(), {}).image.pixels, renderCpu(on.view(), none).image.pixels);
  EXPECT_NE(renderCpu(off.view(), {}).image.pixels, renderCpu(on.view(), {}).image.pixels);
}

TEST(LightPathPilot, IsSkippedWhereItWouldCostMoreThanASixteenthOfTheRender) {
  // 128 x 128 at 16 spp is 262,144 samples, of which the pilot's 4 x 16,384 would be a quarter.
  const PilotChoice small = choose(test::loadTestScene(lampUnderTheCeiling(128, 16)));
  EXPECT_FALSE(small.piloted);
  EXPECT_TRUE(small.lightPaths);
  EXPECT_EQ(small.rays.total(), 0u);
  // At 64 spp the same image has enough samples: a sixteenth of 1,048,576.
  EXPECT_TRUE(choose(test::loadTestScene(lampUnderTheCeiling(128, 64))).piloted);
}

TEST(LightPathPilot, IsSkippedWhereNoLightStartsASubpath) {
  const PilotChoice c = choose(test::loadTestScene(R"({
    "camera": {"width": 256, "height": 256, "spp": 64},
    "render": {"first_hit_light_samples": 1},
    "environment": {"color": 0.5},
    "spheres": [{"position": [0, -1000, 0], "radius": 999, "color": 0.5}]})"));
  EXPECT_FALSE(c.piloted);  // the environment, its only light, starts none
  EXPECT_EQ(c.rays.total(), 0u);
}

// The room of test::torusUnderTheCeiling (the bench's lamp room in small): a second light sample
// at the first interaction cuts the noise of picking among the torus's triangles for a shadow
// ray more (the pilot measured 0.85 of the variance x cost).
std::string roomUnderATorusLamp(const std::string& render = "") {
  return test::torusUnderTheCeiling(R"("width": 256, "height": 256, "spp": 32)",
                                    R"("max_depth": 4, "seed": 3)" + render);
}

TEST(LightSamplePilot, TakesTwoWhereATorusOfManyTrianglesLightsARoom) {
  const PilotChoice c = choose(test::loadTestScene(roomUnderATorusLamp()));
  EXPECT_TRUE(c.lightSamplesPiloted);
  EXPECT_EQ(c.firstHitLightSamples, 2u);
  EXPECT_LT(c.twoLightSamples, 0.95 * c.oneLightSample);
}

// Two spheres on a floor under a uniform sky: a second light sample costs a shadow ray for little
// (the pilot measured about 2 times the variance x cost with it).
TEST(LightSamplePilot, KeepsOneUnderASky) {
  const PilotChoice c = choose(test::loadTestScene(R"({
    "camera": {"width": 256, "height": 256, "fov": 50, "position": [0, 3, 8],
               "look_at": [0, 0.8, 0], "spp": 16},
    "render": {"max_depth": 4, "seed": 1},
    "environment": {"color": [0.4, 0.5, 0.7]},
    "spheres": [{"position": [0, -1000, 0], "radius": 1000, "color": 0.6},
                {"position": [0, 1, 0], "radius": 1, "color": [0.7, 0.5, 0.3]},
                {"position": [-1.8, 0.6, 0.5], "radius": 0.6, "color": 0.8}]})"));
  EXPECT_TRUE(c.lightSamplesPiloted);
  EXPECT_EQ(c.firstHitLightSamples, 1u);
  EXPECT_GT(c.twoLightSamples, 1.3 * c.oneLightSample);
}

TEST(LightSamplePilot, IsSkippedWhereTheSceneSetsThemOrNoLightIsPicked) {
  const PilotChoice set = choose(test::loadTestScene(
      roomUnderATorusLamp(R"(, "first_hit_light_samples": 3, "light_paths": "on",
                             "light_path_depth": "all")")));
  EXPECT_FALSE(set.lightSamplesPiloted);
  EXPECT_EQ(set.firstHitLightSamples, 3u);
  EXPECT_EQ(set.rays.total(), 0u);
  // A lone point light is sampled without a pick.
  const PilotChoice lone = choose(test::loadTestScene(lampHighAboveAnOpenFloor()));
  EXPECT_FALSE(lone.lightSamplesPiloted);
  EXPECT_EQ(lone.firstHitLightSamples, 1u);
}

// Two samples a pixel of `scene`, as the pilot chooses, on `renderer`: *choice is its choice.
RenderResult renderAsPiloted(CpuRenderer& renderer, const SceneData& scene, PilotChoice* choice) {
  renderer.setScene(scene, SceneChange::Structure);
  return renderWithPilot(renderer, scene, twoSamplesAPixel(), choice);
}

TEST(LightSamplePilot, TheRenderTakesTheChosenSamples) {
  const SceneData scene = test::loadTestScene(roomUnderATorusLamp());
  CpuRenderer renderer(CpuEngine::Bvh);
  PilotChoice choice;
  const RenderResult chosen = renderAsPiloted(renderer, scene, &choice);
  ASSERT_EQ(choice.firstHitLightSamples, 2u);
  RenderOptions two = twoSamplesAPixel();
  two.adjust.lightPaths = choice.lightPaths;
  two.adjust.firstHitLightSamples = 2;
  const RenderResult plain = renderer.render(two);
  EXPECT_EQ(chosen.image.pixels, plain.image.pixels);
  two.adjust.firstHitLightSamples = 1;
  EXPECT_LT(renderer.render(two).rays.shadow, plain.rays.shadow);
}

TEST(LightPathPilot, TheRenderFollowsTheChoiceAndCountsThePilot) {
  const SceneData scene = test::loadTestScene(lampHighAboveAnOpenFloor());
  CpuRenderer renderer(CpuEngine::Bvh);
  renderer.setScene(scene, SceneChange::Structure);
  PilotChoice choice;
  const RenderResult chosen = renderWithPilot(renderer, scene, {}, &choice);
  ASSERT_TRUE(choice.piloted);
  ASSERT_FALSE(choice.lightPaths);
  RenderOptions without;
  without.adjust.lightPaths = false;
  const RenderResult plain = renderer.render(without);
  EXPECT_EQ(chosen.image.pixels, plain.image.pixels);
  EXPECT_EQ(chosen.rays.total(), plain.rays.total());
  EXPECT_GT(choice.rays.total(), 0u);
  EXPECT_GE(chosen.seconds, choice.seconds);
}

// The bench's dragon room with a ball for the dragon: sphere walls 60 units out, lit by two
// point lights hung far from them, whose light no wall gathers into a bright patch. Connections
// pay at the first interactions, but deeper ones only cost (the pilot measured 0.87-0.92 of the
// variance x cost without them over three seeds; full renders of the dragon, 0.87).
std::string lightsInTheOpen(const std::string& render = "", int maxDepth = 5) {
  return R"({
    "camera": {"width": 256, "height": 256, "fov": 60, "position": [0, 0, 55], "spp": 32},
    "render": {"max_depth": )" +
         std::to_string(maxDepth) + R"(, "seed": 1)" + render + R"(},
    "spheres": [{"position": [-1000, 0, 0], "radius": 940, "color": [0.72, 0.27, 0.18]},
                {"position": [1000, 0, 0], "radius": 940, "color": [0.22, 0.34, 0.62]},
                {"position": [0, 0, -1000], "radius": 940, "color": [0.4, 0.56, 0.38]},
                {"position": [0, 0, 1000], "radius": 940, "color": [0.8, 0.74, 0.62]},
                {"position": [0, -1000, 0], "radius": 990, "color": [0.5, 0.42, 0.32]},
                {"position": [0, 1000, 0], "radius": 940, "color": 0.75},
                {"position": [0, 2, -8], "radius": 12, "color": 0.8}],
    "lights": [{"position": [-25, 30, 25], "intensity": 7e9},
               {"position": [30, 15, 10], "intensity": 4e9}]})";
}

// The depth of the connections is the pilot's only where the scene asks (its default is "all").
constexpr const char* kDepthByPilot = R"(, "light_path_depth": "auto")";

TEST(LightPathDepthPilot, LimitsThemToTheFirstTwoInteractionsWhereLightsHangInTheOpen) {
  const PilotChoice c = choose(test::loadTestScene(lightsInTheOpen(kDepthByPilot)));
  EXPECT_TRUE(c.lightPaths);
  EXPECT_TRUE(c.depthPiloted);
  EXPECT_EQ(c.lightPathDepth, 2u);
  EXPECT_LT(c.firstInteractions, kPilotDepthMargin * c.everyInteraction);
}

// The small room whose lamp brightens a patch of its ceiling: the paths reach that patch after
// bounces too, and connections there pay at every interaction.
TEST(LightPathDepthPilot, KeepsThemAtEveryInteractionWhereALampLightsTheCeiling) {
  const PilotChoice c = choose(test::loadTestScene(lampUnderTheCeiling(256, 32, kDepthByPilot)));
  EXPECT_TRUE(c.lightPaths);
  EXPECT_TRUE(c.depthPiloted);
  EXPECT_EQ(c.lightPathDepth, kEveryInteraction);
  EXPECT_GT(c.firstInteractions, 1.05 * c.everyInteraction);
}

// Only where at least 8% cheaper: the pilot's 16 samples a pixel understate the deeper
// connections' gain in renders of more.
TEST(LightPathDepthPilot, LimitsThemOnlyWhereClearlyCheaper) {
  EXPECT_TRUE(pilotLimitsLightPathDepth(1.0, 0.91));
  EXPECT_FALSE(pilotLimitsLightPathDepth(1.0, 0.93));
  EXPECT_FALSE(pilotLimitsLightPathDepth(1.0, 1.0));
  EXPECT_FALSE(pilotLimitsLightPathDepth(1.0, 1.2));
  EXPECT_FALSE(pilotLimitsLightPathDepth(std::nan(""), std::nan("")));  // an image without light
}

TEST(LightPathDepthPilot, IsSkippedWhereTheSceneSetsItOrPathsAreShort) {
  const PilotChoice byDefault = choose(test::loadTestScene(lightsInTheOpen()));
  EXPECT_FALSE(byDefault.depthPiloted);
  EXPECT_EQ(byDefault.lightPathDepth, kEveryInteraction);
  const PilotChoice set =
      choose(test::loadTestScene(lightsInTheOpen(R"(, "light_path_depth": 3)")));
  EXPECT_FALSE(set.depthPiloted);
  EXPECT_EQ(set.lightPathDepth, 3u);
  const PilotChoice all =
      choose(test::loadTestScene(lightsInTheOpen(R"(, "light_path_depth": "all")")));
  EXPECT_FALSE(all.depthPiloted);
  EXPECT_EQ(all.lightPathDepth, kEveryInteraction);
  // With three interactions at most, the first two are all that connect anyway.
  const PilotChoice shallow = choose(test::loadTestScene(lightsInTheOpen(kDepthByPilot, 3)));
  EXPECT_TRUE(shallow.piloted);
  EXPECT_FALSE(shallow.depthPiloted);
  // Without connections there is no depth to choose.
  const PilotChoice off = choose(test::loadTestScene(
      lightsInTheOpen(std::string(kDepthByPilot) + R"(, "light_paths": "off")")));
  EXPECT_FALSE(off.depthPiloted);
  EXPECT_EQ(off.rays.total(), 0u);
}

TEST(LightPathDepthPilot, TheRenderConnectsAsChosen) {
  const SceneData scene = test::loadTestScene(lightsInTheOpen(kDepthByPilot));
  CpuRenderer renderer(CpuEngine::Bvh);
  PilotChoice choice;
  const RenderResult chosen = renderAsPiloted(renderer, scene, &choice);
  ASSERT_EQ(choice.lightPathDepth, 2u);
  RenderOptions first = twoSamplesAPixel();
  first.adjust.lightPathDepth = 2;
  const RenderResult plain = renderer.render(first);
  EXPECT_EQ(chosen.image.pixels, plain.image.pixels);
  first.adjust.lightPathDepth = kEveryInteraction;
  EXPECT_GT(renderer.render(first).rays.shadow, plain.rays.shadow);
}

}  // namespace
}  // namespace candela
