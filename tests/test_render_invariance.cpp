// Properties every render must have: bit-identical results for any thread count, and the same
// image (up to noise) when the whole scene is scaled by 1e-3 or 1e4.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>
#include <cstring>
#include <string>

#include "render_test_util.h"

namespace candela {
namespace {

// A sphere resting on a big "floor" sphere, a mirror and a glass ball, lit by a point light and
// a sphere light: shadows, contact, inter-reflection, caustics.
std::string scaledScene(double k, int spp) {
  const auto v = [k](double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.9g", x * k);
    return std::string(buf);
  };
  const double powerScale = k * k;  // keeps irradiance P / d^2 unchanged
  return R"({
    "camera": {"width": 40, "height": 30, "fov": 50, "position": [0, )" + v(1.5) + ", " + v(6) +
         R"(], "look_at": [0, )" + v(0.5) + R"(, 0], "spp": )" + std::to_string(spp) + R"(},
    "render": {"max_depth": 6, "seed": 7},
    "environment": {"color": [0.05, 0.07, 0.1]},
    "spheres": [
      {"position": [0, )" + v(-1000) + R"(, 0], "radius": )" + v(1000) + R"(, "color": 0.7},
      {"position": [)" + v(-1.2) + ", " + v(0.5) + R"(, 0], "radius": )" + v(0.5) + R"(, "color": [0.8, 0.3, 0.2]},
      {"position": [0, )" + v(0.5) + ", " + v(-0.6) + R"(], "radius": )" + v(0.5) + R"(, "material": "mirror"},
      {"position": [)" + v(1.2) + ", " + v(0.5) + R"(, 0], "radius": )" + v(0.5) + R"(, "material": "glass"}],
    "lights": [
      {"position": [)" + v(2) + ", " + v(4) + ", " + v(3) + R"(], "intensity": )" + std::to_string(800 * powerScale) + R"(},
      {"type": "sphere", "position": [)" + v(-3) + ", " + v(3) + ", " + v(1) + R"(], "radius": )" + v(0.4) +
         R"(, "intensity": )" + std::to_string(300 * powerScale) + R"(}]})";
}

TEST(RenderInvariance, BitIdenticalForAnyThreadCount) {
  const std::string scene = scaledScene(1.0, 8);
  const RenderResult one = test::renderTestScene(scene, 1);
  const RenderResult two = test::renderTestScene(scene, 2);
  const RenderResult many = test::renderTestScene(scene, 7);
  ASSERT_EQ(one.image.pixels.size(), two.image.pixels.size());
  EXPECT_EQ(0, std::memcmp(one.image.pixels.data(), two.image.pixels.data(),
                           one.image.pixels.size() * sizeof(float)));
  EXPECT_EQ(0, std::memcmp(one.image.pixels.data(), many.image.pixels.data(),
                           one.image.pixels.size() * sizeof(float)));
  EXPECT_EQ(one.rays.total(), two.rays.total());
  EXPECT_GT(one.rays.shadow, 0u);
  EXPECT_GT(one.rays.bounce, 0u);
  EXPECT_EQ(one.rays.camera, 40u * 30u * 8u);
}

TEST(RenderInvariance, DifferentSeedsGiveDifferentNoise) {
  std::string a = scaledScene(1.0, 4), b = a;
  b.replace(b.find("\"seed\": 7"), 9, "\"seed\": 8");
  const RenderResult ra = test::renderTestScene(a), rb = test::renderTestScene(b);
  EXPECT_NE(0, std::memcmp(ra.image.pixels.data(), rb.image.pixels.data(),
                           ra.image.pixels.size() * sizeof(float)));
}

// Samples are counter-based, so disjoint sample ranges are exact slices of the full render: their
// count-weighted mean equals it up to float rounding (what distributed rendering relies on).
TEST(RenderInvariance, SampleRangeSlicesSumToTheFullRender) {
  const SceneData data = test::loadTestScene(scaledScene(1.0, 8));
  const RenderResult full = renderCpu(data.view(), RenderOptions{});
  std::vector<double> merged(full.image.pixels.size(), 0.0);
  uint64_t cameraRays = 0;
  for (const SampleRange slice : {SampleRange{0, 3}, SampleRange{3, 1}, SampleRange{4, 0}}) {
    RenderOptions options;
    options.samples = slice;
    const RenderResult part = renderCpu(data.view(), options);
    const double count = slice.count ? slice.count : 8 - slice.begin;
    for (size_t i = 0; i < merged.size(); ++i) merged[i] += part.image.pixels[i] * count / 8.0;
    cameraRays += part.rays.camera;
  }
  EXPECT_EQ(cameraRays, full.rays.camera);
  double maxDiff = 0;
  for (size_t i = 0; i < merged.size(); ++i)
    maxDiff = std::max(maxDiff, std::fabs(merged[i] - full.image.pixels[i]) /
                                    std::max(1.0, double(std::fabs(full.image.pixels[i]))));
  EXPECT_LT(maxDiff, 1e-5);
}

TEST(RenderInvariance, SampleRangeOutsideSppIsRejected) {
  const SceneData data = test::loadTestScene(scaledScene(1.0, 4));
  RenderOptions options;
  options.samples = {4, 0};
  EXPECT_THROW(renderCpu(data.view(), options), std::invalid_argument);
  options.samples = {2, 3};
  EXPECT_THROW(renderCpu(data.view(), options), std::invalid_argument);
}

// Scaling the scene changes only floating-point rounding (the random numbers are the same), so
// the images agree closely; any scene-scale epsilon would show up as leaks, acne or black spots.
void expectSameImageAtScale(double k) {
  const RenderResult ref = test::renderTestScene(scaledScene(1.0, 16));
  const RenderResult scaled = test::renderTestScene(scaledScene(k, 16));
  double sumRef = 0, sumScaled = 0, sumAbsDiff = 0;
  size_t bigDiffs = 0;
  for (size_t i = 0; i < ref.image.pixels.size(); ++i) {
    const double a = ref.image.pixels[i], b = scaled.image.pixels[i];
    sumRef += a;
    sumScaled += b;
    sumAbsDiff += std::fabs(a - b);
    if (std::fabs(a - b) > 0.05 * (std::fabs(a) + 0.05)) ++bigDiffs;
  }
  EXPECT_NEAR(sumScaled / sumRef, 1.0, 0.01) << "scale " << k;
  EXPECT_LT(sumAbsDiff / sumRef, 0.03) << "scale " << k;
  // Paths may diverge where rounding flips a glass or roulette decision: a few pixels, no more.
  EXPECT_LT(bigDiffs, ref.image.pixels.size() / 20) << "scale " << k;
}

TEST(RenderInvariance, SceneScaledBy1eMinus3RendersTheSame) { expectSameImageAtScale(1e-3); }
TEST(RenderInvariance, SceneScaledBy1e4RendersTheSame) { expectSameImageAtScale(1e4); }

}  // namespace
}  // namespace candela
