// The emitters seen, sampled again for the denoiser (backends/seen_emitters.h), and the window
// renders they are made of.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "backends/seen_emitters.h"
#include "render/aov_layers.h"
#include "render_test_util.h"

namespace candela {
namespace {

// A camera at the origin looking down -z, fx = fy = 40 with the principal point at the image
// centre, sees an emissive sphere of radius 2 at distance 10 on its axis as a disk of radius
// 40 tan(asin(0.2)) = 8.165 pixels around (24, 20), in front of a black background.
constexpr uint32_t kWidth = 48, kHeight = 40;
constexpr double kDiskRadius = 40.0 * 0.2 / 0.97979589711327;  // tan(asin(0.2)) = 0.2 / sqrt(0.96)
constexpr float kRadiance = 40.0f;

std::string emitterScene(const std::string& camera, const std::string& render) {
  return R"({
    "camera": {"width": 48, "height": 40, "intrinsics": {"fx": 40, "fy": 40, "cx": 24, "cy": 20},
               "position": [0, 0, 0], "look_at": [0, 0, -1], )" +
         camera + R"(},
    "render": {)" +
         render + R"(},
    "spheres": [{"position": [0, 0, -10], "radius": 2,
                 "material": {"type": "emissive", "radiance": 40}}]})";
}

// The share of pixel (x, y) that the disk covers, from a 64 x 64 grid of points in it.
double diskCoverage(uint32_t x, uint32_t y) {
  constexpr int n = 64;
  int inside = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = x + (i + 0.5) / n - 24.0, v = y + (j + 0.5) / n - 20.0;
      inside += u * u + v * v < kDiskRadius * kDiskRadius;
    }
  return double(inside) / (n * n);
}

TEST(SeenEmitters, WindowsAreRunsOfTheTilesAroundTheEdgesOfTheEmittersSeen) {
  // 20 x 12 pixels: tiles of 8 in three columns (the last 4 wide) and two rows (the last 4 high).
  ImageLayer emission("emission", {"R", "G", "B"}, false, 20, 12);
  emission.pixels[3 * (7 * 20 + 9) + 1] = 0.5f;  // (9, 7): its neighbours reach row 8
  emission.pixels[3 * (2 * 20 + 16)] = 2.0f;     // (16, 2): its neighbours reach column 15
  const std::vector<PixelWindow> windows = seenEmitterWindows(emission);
  ASSERT_EQ(windows.size(), 2u);
  // Tiles (1, 0) and (2, 0) as one run, cut at the image's edge; then tile (1, 1).
  EXPECT_EQ(windows[0].x, 8u);
  EXPECT_EQ(windows[0].y, 0u);
  EXPECT_EQ(windows[0].width, 12u);
  EXPECT_EQ(windows[0].height, 8u);
  EXPECT_EQ(windows[1].x, 8u);
  EXPECT_EQ(windows[1].y, 8u);
  EXPECT_EQ(windows[1].width, 8u);
  EXPECT_EQ(windows[1].height, 4u);
  EXPECT_TRUE(seenEmitterWindows(ImageLayer("emission", {"R", "G", "B"}, false, 20, 12)).empty());

  // An emitter of one radiance over [4, 36) x [4, 36) of 40 x 40 pixels: its edges lie in the
  // ring of tiles around the image's 3 x 3 middle ones, which nothing inside it differs in.
  ImageLayer square("emission", {"R", "G", "B"}, false, 40, 40);
  for (uint32_t y = 4; y < 36; ++y)
    for (uint32_t x = 4; x < 36; ++x)
      for (int c = 0; c < 3; ++c) square.pixels[3 * (size_t(y) * 40 + x) + c] = 3.0f;
  const std::vector<PixelWindow> ring = seenEmitterWindows(square);
  ASSERT_EQ(ring.size(), 8u);  // the first and last rows of tiles whole, the rows between at
                               // their ends
  uint32_t pixels = 0;
  for (const PixelWindow& window : ring) {
    pixels += window.width * window.height;
    EXPECT_FALSE(window.x <= 20 && 20 < window.x + window.width && window.y <= 20 &&
                 20 < window.y + window.height);
  }
  EXPECT_EQ(pixels, 40u * 40 - 24 * 24);
}

TEST(ViewAdjustment, AWindowRendersThePixelsOfTheWholeImage) {
  // Antialiased samples with light subpaths: every pixel draws many random numbers, and the
  // window's pixels draw the same as in the whole image's render, to the bit.
  const SceneData scene = test::loadTestScene(
      test::lampUnderTheCeiling(R"("width": 24, "height": 18, "spp": 4)", R"("max_depth": 3)"));
  RenderOptions whole, window;
  window.adjust.window = {5, 3, 7, 6};
  const RenderResult a = renderCpu(scene.view(), whole), b = renderCpu(scene.view(), window);
  ASSERT_EQ(b.image.width, 7u);
  ASSERT_EQ(b.image.height, 6u);
  double sum = 0;
  for (uint32_t y = 0; y < 6; ++y)
    for (uint32_t x = 0; x < 7; ++x) {
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(b.image.at(x, y)[c], a.image.at(5 + x, 3 + y)[c]) << x << ", " << y;
      sum += b.image.at(x, y).x;
    }
  EXPECT_GT(sum, 0.0);
}

TEST(ViewAdjustment, SeenOnlyRendersWhatTheCameraSeesWithoutScattering) {
  const SceneData scene = test::loadTestScene(
      test::lampUnderTheCeiling(R"("width": 8, "height": 8, "spp": 2)", R"("max_depth": 3)"));
  const SceneView view = scene.view();
  ViewAdjustment adjust;
  adjust.seenOnly = true;
  adjust.spp = 32;
  const SceneView seen = adjustedView(view, adjust);
  EXPECT_EQ(seen.settings.maxDepth, 0u);
  EXPECT_EQ(seen.lightPathLights, 0u);
  EXPECT_EQ(seen.settings.spp, 32u);
  EXPECT_EQ(view.settings.spp, 2u);
  // A room lit by a point light, which no camera ray meets: black.
  RenderOptions options;
  options.adjust = adjust;
  const RenderResult r = renderCpu(view, options);
  for (float v : r.image.pixels) EXPECT_EQ(v, 0.0f);
}

TEST(SeenEmitters, SampleAnEmittersEdgesCloserToWhatItCovers) {
  const SceneData scene = test::loadTestScene(emitterScene(R"("spp": 16)", R"("seed": 5)"));
  ASSERT_EQ(seenEmitterSamples(scene), 16u * kSeenEmitterSampleFactor);
  CpuRenderer renderer(CpuEngine::Bvh);
  renderer.setScene(scene, SceneChange::Structure);
  RenderOptions options;
  options.aovs = true;
  const RenderResult own = renderer.render(options);
  const ImageLayer ownEmission = makeAovLayers(scene, {Aov::Emission}, own.aovs)[0];
  const SeenEmitters seen = sampleSeenEmitters(renderer, scene, options);
  ASSERT_FALSE(seen.cancelled);
  ASSERT_EQ(seen.covered.size(), size_t(kWidth) * kHeight);

  double ownError = 0, seenError = 0;
  int edgePixels = 0;
  for (uint32_t y = 0; y < kHeight; ++y)
    for (uint32_t x = 0; x < kWidth; ++x) {
      const size_t i = size_t(y) * kWidth + x;
      const double coverage = diskCoverage(x, y), expected = kRadiance * coverage;
      // Every pixel the disk's edge crosses lies in a window; those far from it do not.
      if (coverage > 0 && coverage < 1) {
        EXPECT_TRUE(seen.covered[i]) << x << ", " << y;
      }
      if (std::hypot(x + 0.5 - 24.0, y + 0.5 - 20.0) > kDiskRadius + 18) {
        EXPECT_FALSE(seen.covered[i]) << x << ", " << y;
      }
      if (!seen.covered[i]) continue;
      const float value = seen.emission.pixels[3 * i];
      if (coverage == 1.0) {
        EXPECT_FLOAT_EQ(value, kRadiance) << x << ", " << y;
      }
      if (coverage == 0.0 || coverage == 1.0) continue;
      ++edgePixels;
      ownError += std::pow(ownEmission.pixels[3 * i] - expected, 2);
      seenError += std::pow(value - expected, 2);
    }
  ASSERT_GT(edgePixels, 40);
  // Sixteen times the samples: the squared error falls 16 times for independent samples, more
  // for stratified ones (about 60 times here).
  EXPECT_LT(seenError, ownError / 16) << seenError << " vs " << ownError;

  // The render's own pass where no window covers it, the windows' elsewhere.
  std::vector<float> pass = ownEmission.pixels;
  seen.replaceIn(pass.data());
  for (size_t i = 0; i < seen.covered.size(); ++i)
    EXPECT_EQ(pass[3 * i],
              seen.covered[i] ? seen.emission.pixels[3 * i] : ownEmission.pixels[3 * i]);
}

TEST(SeenEmitters, NothingIsSampledAgainWhereNothingWouldGain) {
  // Without antialiasing every sample of a pinhole camera goes through the pixel's centre; at
  // 4096 spp and more the render's own samples are as many; a scene without an emitting surface
  // shows none.
  EXPECT_EQ(seenEmitterSamples(
                test::loadTestScene(emitterScene(R"("spp": 16)", R"("antialiasing": false)"))),
            0u);
  EXPECT_EQ(seenEmitterSamples(test::loadTestScene(emitterScene(R"("spp": 4096)", ""))), 0u);
  EXPECT_EQ(seenEmitterSamples(test::loadTestScene(emitterScene(R"("spp": 1024)", ""))),
            kMaxSeenEmitterSamples);
  const SceneData lamp = test::loadTestScene(
      test::lampUnderTheCeiling(R"("width": 8, "height": 8, "spp": 2)", R"("max_depth": 3)"));
  EXPECT_EQ(seenEmitterSamples(lamp), 0u);
  CpuRenderer renderer(CpuEngine::Bvh);
  renderer.setScene(lamp, SceneChange::Structure);
  const SeenEmitters seen = sampleSeenEmitters(renderer, lamp, RenderOptions());
  EXPECT_TRUE(seen.covered.empty());
  EXPECT_FALSE(seen.cancelled);

  // An emitter behind the camera: its pilot finds no tile to sample again.
  std::string away = emitterScene(R"("spp": 16)", "");
  away.replace(away.find("[0, 0, -1]"), 10, "[0, 0, 1] ");
  const SceneData behind = test::loadTestScene(away);
  EXPECT_GT(seenEmitterSamples(behind), 0u);
  renderer.setScene(behind, SceneChange::Structure);
  EXPECT_TRUE(sampleSeenEmitters(renderer, behind, RenderOptions()).covered.empty());
}

}  // namespace
}  // namespace candela
