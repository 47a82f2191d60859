// Scattering media inside glass: glass with a "scattering" coefficient (and an absorption from its
// "transmission_depth") holds a homogeneous medium that a path enters by a transmission, travels
// through by free-flight sampling (render/medium.h) and scatters in by the Henyey-Greenstein
// phase function (render/phase_function.h).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "render/dispersion.h"
#include "render/medium.h"
#include "render/phase_function.h"
#include "render_test_util.h"
#include "temp_dir.h"

namespace candela {
namespace {

using test::num;

constexpr double kPiD = 3.14159265358979323846;

// The density integrates to 1 over the sphere and its mean cosine is g, the parameter's meaning,
// by the midpoint rule in cos(theta).
TEST(GlassMedia, HenyeyGreensteinIsADensityWhoseMeanCosineIsG) {
  for (float g : {-0.8f, -0.3f, 0.0f, 0.0005f, 0.4f, 0.9f}) {
    const int n = 200000;
    double total = 0.0, meanCos = 0.0;
    for (int i = 0; i < n; ++i) {
      const double c = -1.0 + (i + 0.5) * 2.0 / n;
      const double p = henyeyGreenstein(float(c), g) * 2.0 * kPiD * (2.0 / n);
      total += p;
      meanCos += p * c;
    }
    EXPECT_NEAR(total, 1.0, 2e-4) << "g " << g;
    // Below kIsotropicPhaseG the density is isotropic's, as its sampling is.
    EXPECT_NEAR(meanCos, std::fabs(g) < kIsotropicPhaseG ? 0.0f : g, 2e-4) << "g " << g;
  }
}

// Sampled directions follow the density: the share of samples in each of 16 bins of cos(theta)
// about the direction of travel matches the density's integral over the bin (within 5 standard
// errors of the count), their mean cosine is g, and they are unit vectors turned about the travel
// direction evenly (the mean of their part across it is 0).
TEST(GlassMedia, HenyeyGreensteinSamplesFollowTheDensity) {
  const Vec3 travel = normalize(Vec3(0.3f, -0.5f, 0.8f));
  const Frame frame(travel);
  for (float g : {-0.6f, 0.0f, 0.3f, 0.85f}) {
    const int bins = 16, n = 1 << 16;
    std::array<int, 16> count{};
    double meanCos = 0.0, meanS = 0.0;
    for (int i = 0; i < n; ++i) {
      // A rank-1 lattice: stratified in u1, spread evenly in u2.
      const double golden = 0.6180339887498949;
      const float u1 = (i + 0.5f) / n, u2 = float(std::fmod(i * golden, 1.0));
      const Vec3 wi = sampleHenyeyGreenstein(travel, g, u1, u2);
      ASSERT_NEAR(length(wi), 1.0f, 1e-5f);
      const float c = dot(wi, travel);
      meanCos += c;
      meanS += dot(wi, frame.s);
      ++count[std::min(bins - 1, int((c + 1.0f) * 0.5f * bins))];
    }
    for (int b = 0; b < bins; ++b) {
      double expected = 0.0;
      const int steps = 1000;
      for (int k = 0; k < steps; ++k) {
        const double c = -1.0 + (b + (k + 0.5) / steps) * 2.0 / bins;
        expected += henyeyGreenstein(float(c), g) * 2.0 * kPiD * (2.0 / bins / steps);
      }
      const double sigma = std::sqrt(expected * (1.0 - expected) / n);
      EXPECT_NEAR(double(count[b]) / n, expected, 5.0 * sigma + 1e-5) << "g " << g << " bin " << b;
    }
    EXPECT_NEAR(meanCos / n, g, 2e-3) << "g " << g;
    EXPECT_NEAR(meanS / n, 0.0, 2e-3) << "g " << g;
  }
}

// The transport of a medium over a step towards a surface tMax ahead, in one channel of
// extinction st and scattering s: the chance of passing, Tr(tMax), and the integrals of
// s Tr(t) f(t) from 0 to tMax for f = 1 and f = t.
struct Transport {
  double pass, scatter, scatterT;
};
Transport transport(double st, double s, double tMax) {
  const double tr = std::isinf(tMax) ? (st > 0.0 ? 0.0 : 1.0) : std::exp(-st * tMax);
  if (!(st > 0.0)) return {tr, 0.0, 0.0};
  return {tr, s / st * (1.0 - tr),
          s / (st * st) * (1.0 - tr) - (std::isinf(tMax) ? 0.0 : s / st * tMax * tr)};
}

// One step's weights (HeroChannel::take) have the medium's transport as their expectation in every
// channel, over the hero's pick and u (midpoint rule, each channel picked alike): passing to the
// surface tMax ahead averages Tr(tMax), scattering times f(t) the integral of sigmaS Tr(t) f(t) up
// to tMax, for f = 1 and f = t, however the channels' extinctions differ, also in a channel
// that stops nothing and where the path carries one channel alone (after dispersive glass).
TEST(GlassMedia, FreeFlightWeightsAverageTheMediumsTransport) {
  const Vec3 sigmaA(0.2f, 0.0f, 0.0f), sigmaS(0.7f, 2.5f, 0.0f);
  for (float tMax : {0.4f, 1.3f, kInfinity}) {
    for (int pathChannel : {kAllChannels, 0, 1}) {
      const int n = 1 << 17;
      double pass[3] = {}, scatter[3] = {}, scatterT[3] = {};
      for (int pick = 0; pick < 3; ++pick)
        for (int i = 0; i < n; ++i) {
          HeroChannel hero;
          hero.pick(pathChannel, (pick + 0.5f) / 3.0f);
          const MediumStep step =
              sampleMediumStep(sigmaA, sigmaS, hero.channel, tMax, (i + 0.5f) / n);
          const Vec3 factor = hero.take(step);
          for (int c = 0; c < 3; ++c) {
            const double w = factor[c] / (3.0 * n);
            ASSERT_TRUE(std::isfinite(w));
            if (step.scattered) {
              scatter[c] += w;
              scatterT[c] += w * step.t;
            } else {
              pass[c] += w;
            }
          }
        }
      for (int c = 0; c < 3; ++c) {
        if (pathChannel != kAllChannels && c != pathChannel) continue;
        const Transport expected = transport(double(sigmaA[c]) + sigmaS[c], sigmaS[c], tMax);
        const std::string where = "channel " + std::to_string(c) + ", path's channel " +
                                  std::to_string(pathChannel) + ", tMax " + num(tMax);
        EXPECT_NEAR(pass[c], expected.pass, 2e-4) << where;
        EXPECT_NEAR(scatter[c], expected.scatter, 2e-4) << where;
        EXPECT_NEAR(scatterT[c], expected.scatterT, 2e-4) << where;
      }
    }
  }
}

// Over two steps the hero and its densities carry on: the product of the two factors averages
// the product of the two steps' transports (scattering in the first and passing the second, or
// passing both), each step in a medium of its own, by the midpoint rule over the pick and both u.
TEST(GlassMedia, TheHerosDensitiesCarryFromStepToStep) {
  const Vec3 sigmaA1(0.1f, 1.0f, 0.3f), sigmaS1(2.0f, 0.4f, 1.0f);
  const Vec3 sigmaA2(0.6f, 0.0f, 0.2f), sigmaS2(0.3f, 3.0f, 0.0f);
  const float d1 = 0.8f, d2 = 0.5f;
  const int n = 1 << 9;
  double scatterPass[3] = {}, passPass[3] = {};
  for (int pick = 0; pick < 3; ++pick)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        HeroChannel hero;
        hero.pick(kAllChannels, (pick + 0.5f) / 3.0f);
        const MediumStep first =
            sampleMediumStep(sigmaA1, sigmaS1, hero.channel, d1, (i + 0.5f) / n);
        const Vec3 f1 = hero.take(first);
        const MediumStep second =
            sampleMediumStep(sigmaA2, sigmaS2, hero.channel, d2, (j + 0.5f) / n);
        if (second.scattered) continue;
        const Vec3 f = f1 * hero.take(second);
        for (int c = 0; c < 3; ++c)
          (first.scattered ? scatterPass : passPass)[c] += f[c] / (3.0 * n * n);
      }
  for (int c = 0; c < 3; ++c) {
    const Transport one = transport(double(sigmaA1[c]) + sigmaS1[c], sigmaS1[c], d1);
    const Transport two = transport(double(sigmaA2[c]) + sigmaS2[c], sigmaS2[c], d2);
    EXPECT_NEAR(passPass[c], one.pass * two.pass, 2e-3) << "channel " << c;
    EXPECT_NEAR(scatterPass[c], one.scatter * two.pass, 2e-3) << "channel " << c;
  }
}

TEST(GlassMedia, SingleScatteringAlbedoIsScatteringOverExtinction) {
  const Vec3 a = singleScatteringAlbedo(Vec3(1.0f, 0.0f, 0.0f), Vec3(3.0f, 2.0f, 0.0f));
  EXPECT_FLOAT_EQ(a.x, 0.75f);
  EXPECT_FLOAT_EQ(a.y, 1.0f);
  EXPECT_EQ(a.z, 0.0f);  // stops nothing: not 0 / 0
}

// A ball of glass that neither absorbs nor has anything else in view, in a white furnace (a
// constant environment of radiance 1): however the light scatters inside, bends and reflects at
// its surface, it all comes out again, so every pixel is 1 on average (the ball's inside with a
// different extinction in each channel, forward-scattering, within index 1.5 that traps light by
// total internal reflection; and at index 1). The tolerance is five standard errors of the mean
// over the ball's pixels, from their spread.
TEST(GlassMedia, AScatteringBallThatAbsorbsNothingIsInvisibleInAWhiteFurnace) {
  for (const char* ior : {"1.5", "1"}) {
    const RenderResult result = test::renderTestScene(
        R"({"camera": {"width": 24, "height": 24, "fov": 30, "position": [0, 0, 5], "spp": 64},
            "render": {"max_depth": 1000, "seed": 3},
            "environment": {"color": 1},
            "spheres": [{"position": [0, 0, 0], "radius": 1, "material": {"type": "glass",
              "ior": )" +
        std::string(ior) + R"(, "scattering": [0.5, 2, 6], "scattering_anisotropy": 0.6}}]})");
    for (int c = 0; c < 3; ++c) {
      double sum = 0.0, sum2 = 0.0;
      const int n = 24 * 24;
      for (uint32_t y = 0; y < 24; ++y)
        for (uint32_t x = 0; x < 24; ++x) {
          const double v = result.image.at(x, y)[c];
          ASSERT_TRUE(std::isfinite(v));
          sum += v;
          sum2 += v * v;
        }
      const double mean = sum / n, stdError = std::sqrt((sum2 / n - mean * mean) / (n - 1));
      EXPECT_NEAR(mean, 1.0, 5.0 * stdError + 1e-4) << "ior " << ior << ", channel " << c;
      EXPECT_GT(stdError, 0.0);  // the scattering did take place
      // and its weights stay tame: a biased weighting of the channels spreads by orders more.
      EXPECT_LT(stdError, 0.05);
    }
  }
}

// The colour channels of a render are independent: each channel of a ball whose inside absorbs
// and scatters differently in each (so a path's distances are drawn by one channel and weighed for
// all three) renders as a grey ball of that channel's coefficients, whose distances every channel
// draws alike. Compared per pixel, where the two images differ by noise alone: the mean
// difference over the ball within five standard errors of the differences' spread.
TEST(GlassMedia, EachChannelOfAColouredMediumRendersAsAGreyMediumOfItsCoefficients) {
  const std::array<double, 3> color = {0.6, 0.8, 0.95}, scattering = {1, 3, 8};
  const auto render = [](const std::string& colorJson, const std::string& scatteringJson) {
    return test::renderTestScene(
               R"({"camera": {"width": 24, "height": 24, "fov": 28, "position": [0, 0, 5],
                              "spp": 64},
                   "render": {"max_depth": 1000, "seed": 5},
                   "environment": {"color": 1},
                   "spheres": [{"position": [0, 0, 0], "radius": 1, "material": {"type": "glass",
                     "ior": 1.4, "transmission_depth": 1, "scattering_anisotropy": 0.6,
                     "color": )" +
               colorJson + R"(, "scattering": )" + scatteringJson + "}}]}")
        .image;
  };
  const ImageRGB coloured = render("[0.6, 0.8, 0.95]", "[1, 3, 8]");
  for (int c = 0; c < 3; ++c) {
    const ImageRGB grey = render(num(color[c]), num(scattering[c]));
    double sum = 0.0, sum2 = 0.0;
    const int n = 24 * 24;
    for (uint32_t y = 0; y < 24; ++y)
      for (uint32_t x = 0; x < 24; ++x) {
        const double d = double(coloured.at(x, y)[c]) - grey.at(x, y)[c];
        ASSERT_TRUE(std::isfinite(d));
        sum += d;
        sum2 += d * d;
      }
    const double mean = sum / n, stdError = std::sqrt((sum2 / n - mean * mean) / (n - 1));
    EXPECT_NEAR(mean, 0.0, 5.0 * stdError + 1e-5) << "channel " << c;
    EXPECT_GT(stdError, 0.0);   // both scattered, each by its own noise
    EXPECT_LT(stdError, 0.05);  // and tamely (as in the furnace above)
  }
}

// Glass of index 1 is crossed by shadow rays: a wall lit by a point light through a slab of smoke
// held in such glass (out of the camera's view) is lit as without it, times the smoke's
// transmittance exp(-sigmaT L) along each shadow ray (L: its length within the slab), and times
// the glass's colour at each of its two crossings where the glass is tinted instead. With
// max_depth 1, pixel-centre rays and one point light every pixel is exact: against the wall
// without the slab within 1e-4 of the ratio.
TEST(GlassMedia, ShadowRaysCrossIndexMatchedGlassThroughItsMedium) {
  test::TempDir dir;
  dir.write("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n");
  const uint32_t size = 9;
  const double fov = 20.0, distance = 6.0, light[3] = {0.0, 5.0, 2.5};
  const auto render = [&](const std::string& slab) {
    const std::string objects =
        R"([{"file": "quad.obj", "scale": 100, "color": 0.5})" +
        (slab.empty() ? std::string()
                      : R"(, {"shape": "cube", "position": [0, 2.5, 2.5], "scale": [6, 1, 4],
                              "material": )" +
                            slab + "}") +
        "]";
    const SceneData data = flattenScene(parseSceneText(
        R"({"camera": {"width": 9, "height": 9, "fov": 20, "position": [0, 0, 6], "spp": 2},
            "render": {"antialiasing": false, "max_depth": 1},
            "lights": [{"position": [0, 5, 2.5], "intensity": 100}],
            "objects": )" +
            objects + "}",
        "slab.json", dir.path()));
    return renderCpu(data.view(), RenderOptions{}).image;
  };
  const ImageRGB open = render("");
  const ImageRGB smoke = render(
      R"({"type": "glass", "ior": 1, "color": 0.7, "transmission_depth": 1, "scattering": [0.5, 1, 2]})");
  const ImageRGB tinted = render(R"({"type": "glass", "ior": 1, "color": [0.8, 0.9, 1]})");
  const double sigmaT[3] = {-std::log(0.7) + 0.5, -std::log(0.7) + 1.0, -std::log(0.7) + 2.0};
  const double tint[3] = {0.8, 0.9, 1.0};
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x) {
      const std::array<double, 3> d = test::pixelCentreDirection(size, size, fov, x, y);
      const double p[3] = {d[0] * distance / -d[2], d[1] * distance / -d[2], 0.0};
      const double toLight[3] = {light[0] - p[0], light[1] - p[1], light[2] - p[2]};
      const double length =
          std::sqrt(toLight[0] * toLight[0] + toLight[1] * toLight[1] + toLight[2] * toLight[2]);
      const double inSlab = length / toLight[1];  // the slab spans y in [2, 3]
      for (int c = 0; c < 3; ++c) {
        const double lit = open.at(x, y)[c];
        ASSERT_GT(lit, 0.0);
        EXPECT_NEAR(smoke.at(x, y)[c] / lit, std::exp(-sigmaT[c] * inSlab), 1e-4)
            << "pixel (" << x << ", " << y << "), channel " << c;
        EXPECT_NEAR(tinted.at(x, y)[c] / lit, tint[c] * tint[c], 1e-4)
            << "pixel (" << x << ", " << y << "), channel " << c;
      }
    }
}

// A camera ray crosses clear glass of index 1 without an interaction: at max_depth 1 the wall
// behind a box of it is lit by the point light as without the box (were the crossings
// interactions, the path would end at the box), pixel by pixel within rounding.
TEST(GlassMedia, CrossingIndexMatchedGlassIsNoInteraction) {
  test::TempDir dir;
  dir.write("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n");
  const auto render = [&](const std::string& box) {
    const SceneData data = flattenScene(parseSceneText(
        R"({"camera": {"width": 9, "height": 9, "fov": 20, "position": [0, 0, 6], "spp": 2},
            "render": {"antialiasing": false, "max_depth": 1},
            "lights": [{"position": [3, 0, 4], "intensity": 100}],
            "objects": [{"file": "quad.obj", "scale": 100, "color": 0.5})" +
            box + "]}",
        "box.json", dir.path()));
    return renderCpu(data.view(), RenderOptions{}).image;
  };
  const ImageRGB open = render("");
  const ImageRGB boxed = render(
      R"(, {"shape": "cube", "position": [0, 0, 3], "scale": 2, "material": {"type": "glass", "ior": 1}})");
  for (uint32_t y = 0; y < 9; ++y)
    for (uint32_t x = 0; x < 9; ++x)
      for (int c = 0; c < 3; ++c) {
        ASSERT_GT(open.at(x, y)[c], 0.0f);
        EXPECT_NEAR(boxed.at(x, y)[c] / open.at(x, y)[c], 1.0, 1e-4)
            << "pixel (" << x << ", " << y << "), channel " << c;
      }
}

TEST(GlassMedia, ScatteringIsReadOnGlassAndRefusedWhereItMeansNothing) {
  const SceneData data = test::loadTestScene(
      R"({"camera": {}, "spheres": [{"position": [0, 0, 0], "radius": 1, "material": {"type":
          "glass", "scattering": [1, 2, 3], "scattering_anisotropy": -0.25}}]})");
  const Material* glass = nullptr;
  for (const Material& m : data.materials)
    if (m.type == MaterialType::Glass) glass = &m;
  ASSERT_NE(glass, nullptr);
  const Material& m = *glass;
  EXPECT_EQ(m.scattering.x, 1.0f);
  EXPECT_EQ(m.scattering.z, 3.0f);
  EXPECT_EQ(m.scatteringAnisotropy, -0.25f);
  EXPECT_TRUE(hasMedium(m));
  EXPECT_EQ(test::sphereMaterialError(R"({"type": "glass", "scattering": 2})"), "(no error)");

  EXPECT_EQ(test::sphereMaterialError(R"({"type": "glass", "scattering": -1})"),
            "test.json: spheres[0].material.scattering: expected a non-negative number, got -1");
  EXPECT_EQ(test::sphereMaterialError(
                R"({"type": "glass", "scattering": 1, "scattering_anisotropy": 1})"),
            "test.json: spheres[0].material.scattering_anisotropy: expected a number between -1 "
            "and 1, exclusive (0 scatters alike in every direction), got 1");
  EXPECT_EQ(test::sphereMaterialError(R"({"type": "glass", "scattering_anisotropy": 0.5})"),
            "test.json: spheres[0].material.scattering_anisotropy: not used without a "
            "\"scattering\" beside it");
  EXPECT_EQ(test::sphereMaterialError(R"({"type": "plastic", "scattering": 1})"),
            "test.json: spheres[0].material.scattering: not used by a \"plastic\" material (a "
            "\"glass\" holds a scattering medium inside)");
}

}  // namespace
}  // namespace candela
