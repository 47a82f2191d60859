// Splitting at smooth glass (render/path_branch.h): a room seen through a glass ball renders the
// same image as when each path chooses between reflection and refraction, with less noise; scenes
// without smooth glass render exactly as without splitting; the branches' random numbers are the
// sample's own, apart from the path's.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render/integrator.h"
#include "render_test_util.h"

namespace candela {
namespace {

// The small room of test::kSmallRoomWalls lit by a point light, a ball of glass (or of `ball`'s
// material) filling most of the view, a diffuse one behind it, at `seed`.
std::string glassBallInARoom(int seed, const std::string& ball = R"("material": "glass")") {
  return R"({
    "camera": {"width": 48, "height": 32, "fov": 50, "position": [0, 2.5, 7], "look_at": [0, 2.5, 0],
               "spp": 16},
    "render": {"max_depth": 5, "seed": )" +
         std::to_string(seed) + R"(},
    "spheres": [)" +
         std::string(test::kSmallRoomWalls) + R"(,
                {"position": [1.5, 1, -2.5], "radius": 1, "color": 0.5},
                {"position": [0, 2.5, 1], "radius": 2.5, )" +
         ball + R"(}],
    "lights": [{"position": [-2, 5, 2], "intensity": 300}]})";
}

RenderResult renderSplitting(const std::string& scene, uint32_t splitDepth) {
  const SceneData data = test::loadTestScene(scene);
  SceneView view = data.view();
  EXPECT_EQ(view.glassSplitDepth, kGlassSplitDepth);  // the default
  view.glassSplitDepth = splitDepth;
  return renderCpu(view, RenderOptions{});
}

// Rendered with splitting and with each path choosing, over two seeds each: each 8 x 8 block's
// mean agrees within the noise of the two renders (estimated from the seeds), and the image that
// splits is at least 1.5 times less noisy.
TEST(GlassSplit, ARoomSeenThroughAGlassBallRendersTheSameImageWithLessNoise) {
  const auto renderPair = [](uint32_t splitDepth) {
    return test::SeedPair{renderSplitting(glassBallInARoom(1), splitDepth),
                          renderSplitting(glassBallInARoom(2), splitDepth)};
  };
  const test::SeedPair split = renderPair(kGlassSplitDepth), chosen = renderPair(0);
  // The branches trace rays of their own.
  EXPECT_GT(split.a.rays.bounce, chosen.a.rays.bounce);
  const auto [noiseSplit, noiseChosen] = test::expectSameImage(split, chosen);
  EXPECT_LT(noiseSplit * 1.5, noiseChosen);  // measured: 2.2 times
}

TEST(GlassSplit, ScenesWithoutSmoothGlassRenderAsWithoutSplitting) {
  // Rough glass and a mirror have no two delta lobes to follow: nothing splits, and the images
  // and ray counts are the same, bit for bit.
  for (const char* ball : {R"("material": {"type": "glass", "roughness": 0.2})",
                           R"("material": "mirror", "color": 0.9)"}) {
    const RenderResult split = renderSplitting(glassBallInARoom(1, ball), kGlassSplitDepth);
    const RenderResult chosen = renderSplitting(glassBallInARoom(1, ball), 0);
    EXPECT_EQ(split.image.pixels, chosen.image.pixels) << ball;
    EXPECT_EQ(split.rays.bounce, chosen.rays.bounce) << ball;
  }
  // Smooth glass does split, and so changes the image.
  EXPECT_NE(renderSplitting(glassBallInARoom(1), kGlassSplitDepth).image.pixels,
            renderSplitting(glassBallInARoom(1), 0).image.pixels);
}

TEST(GlassSplit, ABranchDrawsNumbersOfItsOwn) {
  SampleStream path(7, 12, 3, 16);
  path.next1D();
  SampleStream branch = path.branch();
  SampleStream again = path.branch();
  // The branch's numbers are a function of where it split, and not the path's next ones.
  const float b = branch.next1D();
  EXPECT_EQ(b, again.next1D());
  EXPECT_NE(b, path.next1D());
}

}  // namespace
}  // namespace candela
