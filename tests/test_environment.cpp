// The environment: the equirectangular mapping and its rotation, importance sampling of a map
// (its pdf against the sampled one and against the sphere's measure), furnaces lit by a constant
// environment and by a map, reading .hdr maps, and every bad map refused with one message.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/constants.h"
#include "image/image_io.h"
#include "render/light_sample.h"
#include "render_test_util.h"
#include "scene/flatten_environment.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

constexpr double kZ = 5.0;

std::string tempPath(const std::string& name) { return ::testing::TempDir() + name; }

// Writes a w x h map whose texel (x, y) is texel(x, y) and returns its path.
template <typename F>
std::string writeMap(const std::string& name, uint32_t w, uint32_t h, F texel) {
  ImageRGB image(w, h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) image.set(x, y, texel(x, y));
  const std::string path = tempPath(name);
  writeImage(path, image, OutputDesc{});
  return path;
}

SceneData sceneWithEnvironment(const std::string& environment, const std::string& rest = "") {
  return test::loadTestScene(R"({"camera": {"width": 8, "height": 8, "fov": 10, "spp": 4},
                                 "environment": )" +
                             environment + rest + "}");
}

// The map's left half blue, right half red, its top quarter green: the default camera, looking
// down -z, sees the seam between blue and red at the image's centre; straight up is green.
TEST(Environment, MappingPutsTheMapCentreAlongMinusZ) {
  const std::string map = writeMap("env_halves.pfm", 64, 32, [](uint32_t x, uint32_t y) {
    if (y < 8) return Vec3(0, 1, 0);
    return x < 32 ? Vec3(0, 0, 1) : Vec3(1, 0, 0);
  });
  const SceneData data = sceneWithEnvironment(R"({"map": ")" + map + R"("})");
  const SceneView view = data.view();
  EXPECT_EQ(environmentRadiance(view, normalize(Vec3(0.2f, 0, -1))).x, 1.0f);   // right: red
  EXPECT_EQ(environmentRadiance(view, normalize(Vec3(-0.2f, 0, -1))).z, 1.0f);  // left: blue
  EXPECT_EQ(environmentRadiance(view, Vec3(0, 1, 0)).y, 1.0f);                  // up: green
  // Behind the camera (+z) lie the map's right and left edges, where it wraps: turning right
  // from -z, red continues to the right edge, which meets the blue left edge at +z.
  EXPECT_EQ(environmentRadiance(view, normalize(Vec3(0.2f, 0, 1))).x, 1.0f);
  EXPECT_EQ(environmentRadiance(view, normalize(Vec3(-0.2f, 0, 1))).z, 1.0f);

  // The camera sees the same: its right half red, its left half blue.
  const RenderResult r = renderCpu(view, RenderOptions{});
  EXPECT_GT(r.image.at(6, 4).x, 0.99f);
  EXPECT_GT(r.image.at(1, 4).z, 0.99f);

  // rotation [0, 90, 0] turns the map's frame by 90 degrees about +y: its -z (the centre) now
  // lies along world -x, its +x (red) along world -z.
  const SceneData turnedData =
      sceneWithEnvironment(R"({"map": ")" + map + R"(", "rotation": [0, 90, 0]})");
  const SceneView turned = turnedData.view();
  EXPECT_EQ(environmentRadiance(turned, normalize(Vec3(-1, 0, 0.2f))).z, 1.0f);
  EXPECT_EQ(environmentRadiance(turned, normalize(Vec3(-1, 0, -0.2f))).x, 1.0f);
}

// The sampled pdf equals the pdf environmentPdf evaluates for the same direction (what MIS needs)
// and integrates to 1 over the sphere. The distribution is MIS-compensated: it holds only the
// texels brighter than the map's mean (the sun here), so light sampling alone would miss the sky,
// while light sampling beside uniform sampling of the sphere, weighed by the power heuristic as
// the integrator weighs light and BSDF samples, estimates the irradiance that uniform sampling
// alone estimates, with less noise. The map has w x h texels; its sun covers [0.625, 0.6875) x
// [0.25, 1 / 3) of it, 3 x 2 texels of a 48 x 24 map.
void expectMapSamplingConsistentWithItsPdf(uint32_t w, uint32_t h) {
  const std::string map =
      writeMap("env_sun_" + std::to_string(w) + ".pfm", w, h, [&](uint32_t x, uint32_t y) {
        const float fx = float(x) / float(w), fy = float(y) / float(h);
        const bool sun = fx >= 0.625f && fx < 0.6875f && fy >= 0.25f && fy < 1.0f / 3.0f;
        return sun ? Vec3(400, 380, 300)
                   : Vec3(0.1f + 0.01f * float(x % 5), 0.2f, 0.3f + 0.5f * fy);
      });
  const SceneData data =
      sceneWithEnvironment(R"({"map": ")" + map + R"(", "strength": 2, "rotation": [10, 40, 0]})");
  const SceneView view = data.view();
  ASSERT_GE(view.environment.light, 0);
  const Light& light = view.lights[view.environment.light];
  ASSERT_EQ(light.type, LightType::Environment);

  std::mt19937 gen(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const Vec3 n = normalize(Vec3(0.3f, 1.0f, -0.2f));  // irradiance on a surface facing n
  const float uniformPdf = 1.0f / (4.0f * kPi);
  const int draws = 300000;
  double byMis = 0, byMis2 = 0, byUniform = 0, byUniform2 = 0, pdfIntegral = 0, worst = 0;
  int offBy2e3 = 0;
  for (int i = 0; i < draws; ++i) {
    double mis = 0.0;
    LightSample ls;
    if (sampleLight(view, light, Vec3(0.0f), 0.0f, u(gen), u(gen), &ls)) {
      const double off = std::abs(environmentPdf(view, ls.wi) / ls.pdf - 1.0);
      worst = std::max(worst, off);
      if (off > 2e-3) ++offBy2e3;
      mis += ls.radiance.x * std::max(0.0f, dot(ls.wi, n)) / ls.pdf *
             powerHeuristic(ls.pdf, uniformPdf);
    }
    const float z = 1 - 2 * u(gen), r = std::sqrt(std::max(0.0f, 1 - z * z)),
                phi = 2 * kPi * u(gen);
    const Vec3 wi(r * std::cos(phi), r * std::sin(phi), z);
    const float lightPdf = environmentPdf(view, wi);
    pdfIntegral += lightPdf / uniformPdf;
    const double v = environmentRadiance(view, wi).x * std::max(0.0f, dot(wi, n)) / uniformPdf;
    mis += v * powerHeuristic(uniformPdf, lightPdf);
    byUniform += v;
    byUniform2 += v * v;
    byMis += mis;
    byMis2 += mis * mis;
  }
  const auto error = [&](double sum, double sum2) {
    const double mean = sum / draws;
    return std::sqrt(std::max(0.0, sum2 / draws - mean * mean) / draws);
  };
  // A direction's round trip through the map moves it by about 1e-4 of a cell of the large map,
  // which changes the bilinear density by a part in a few hundred only where it falls steeply to
  // a corner of no weight (at the sun's rim; measured: 3 samples, at most 0.47%).
  EXPECT_LT(worst, 1e-2);
  EXPECT_LE(offBy2e3, draws / 10000);
  EXPECT_NEAR(pdfIntegral / draws, 1.0, 0.02);
  // The sun's texels are sampled, the sky far from them is not.
  const auto pdfAtTexel = [&](float x, float y) {
    float sinTheta;
    const Vec3 d = mapToDirection((x + 0.5f) / float(w), (y + 0.5f) / float(h), &sinTheta);
    return environmentPdf(view, view.environment.toWorld * d);
  };
  EXPECT_GT(pdfAtTexel(0.65f * float(w), 0.3f * float(h)), 0.0f);
  EXPECT_EQ(pdfAtTexel(0.2f * float(w), 0.75f * float(h)), 0.0f);
  const double a = byMis / draws, b = byUniform / draws;
  const double tolerance = kZ * std::hypot(error(byMis, byMis2), error(byUniform, byUniform2));
  EXPECT_NEAR(a, b, tolerance);
  EXPECT_LT(error(byMis, byMis2), error(byUniform, byUniform2)) << "importance should help";
}

TEST(Environment, MapSamplingIsConsistentWithItsPdf) {
  expectMapSamplingConsistentWithItsPdf(48, 24);  // texels split into 4 x 4 cells
  // Over a million texels: not split, on the grid shifted by half a texel.
  ASSERT_TRUE(environmentGrid(1600, 800).shifted);
  expectMapSamplingConsistentWithItsPdf(1600, 800);
}

// The sampling density within a cell is the bilinear interpolation of its corners' values,
// which is the lookup itself: each cell lies within one of the lookup's bilinear patches, whether
// texels are split into 4 x 4 or 2 x 2 cells or, on a grid shifted by half a texel, not at all.
// mapToCell finds the cell and the point in it that cellToMap placed.
TEST(Environment, SamplingCellsInterpolateTheLookupBetweenTheirCorners) {
  const uint32_t w = 6, h = 4;
  std::mt19937 gen(11);
  std::uniform_real_distribution<float> u(0.0f, 5.0f);
  std::vector<Vec3> texels(w * h);
  for (Vec3& t : texels) t = Vec3(u(gen), u(gen), u(gen));
  std::uniform_real_distribution<float> within(0.0f, 1.0f);
  for (const EnvironmentGrid grid :
       {EnvironmentGrid{4 * w, 4 * h, false}, EnvironmentGrid{2 * w, 2 * h, false},
        EnvironmentGrid{w, h + 1, true}}) {
    Environment e;
    e.grid = grid;
    const std::vector<float> corners = environmentCornerBrightness(texels.data(), w, h, grid);
    const uint32_t stride = grid.columns + 1;
    ASSERT_EQ(corners.size(), size_t(stride) * (grid.rows + 1));
    for (uint32_t y = 0; y <= grid.rows; ++y)  // the map wraps
      EXPECT_NEAR(corners[size_t(y) * stride + grid.columns], corners[size_t(y) * stride], 1e-5);
    for (uint32_t row = 0; row < grid.rows; ++row)
      for (uint32_t column = 0; column < grid.columns; ++column)
        for (int i = 0; i < 4; ++i) {
          const float s = within(gen), t = within(gen);
          const float* top = corners.data() + size_t(row) * stride + column;
          const float* bottom = top + stride;
          const double interpolated =
              (1 - t) * ((1 - s) * top[0] + s * top[1]) + t * ((1 - s) * bottom[0] + s * bottom[1]);
          float mu, mv;
          cellToMap(e, column, row, s, t, &mu, &mv);
          EXPECT_NEAR(interpolated, componentSum(lookupMap(texels.data(), w, h, mu, mv)), 1e-4)
              << "cells " << grid.columns << " x " << grid.rows << ", cell " << column << ", "
              << row;
          uint32_t foundColumn, foundRow;
          float foundS, foundT;
          mapToCell(e, mu, mv, &foundColumn, &foundRow, &foundS, &foundT);
          ASSERT_EQ(foundColumn, column);
          ASSERT_EQ(foundRow, row);
          EXPECT_NEAR(foundS, s, 1e-4);
          EXPECT_NEAR(foundT, t, 1e-4);
        }
  }
  const EnvironmentGrid large = environmentGrid(2048, 1024);
  EXPECT_EQ(large.columns, 2048u);
  EXPECT_EQ(large.rows, 1025u);
  EXPECT_TRUE(large.shifted);
  EXPECT_FALSE(environmentGrid(256, 128).shifted);
  EXPECT_EQ(environmentCellsPerTexel(256, 128), 4u);
  EXPECT_EQ(environmentCellsPerTexel(1024, 512), 2u);
  EXPECT_EQ(environmentCellsPerTexel(2048, 1024), 1u);
  EXPECT_EQ(environmentCellsPerTexel(8192, 4096), 1u);
}

// A sun of 2 x 2 texels on a black map: its bilinear lookup is a pyramid whose radiance runs
// from full to nothing, and the light samples follow that shape, so each carries nearly the same
// radiance / pdf: the irradiance of a surface facing the sun has a relative standard deviation
// per sample under 1% (0.23% measured; a piecewise-constant distribution over the same cells
// gave 19%).
TEST(Environment, LightSamplesOfASmallSunCarryNearlyEqualWeights) {
  const uint32_t w = 64, h = 32;
  const std::string map = writeMap("env_small_sun.pfm", w, h, [](uint32_t x, uint32_t y) {
    return x >= 40 && x < 42 && y >= 10 && y < 12 ? Vec3(1000.0f) : Vec3(0.0f);
  });
  const SceneData data = sceneWithEnvironment(R"({"map": ")" + map + R"("})");
  const SceneView view = data.view();
  const Light& light = view.lights[view.environment.light];
  float sinTheta;
  const Vec3 n = view.environment.toWorld * mapToDirection(41.0f / w, 11.0f / h, &sinTheta);
  std::mt19937 gen(9);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const int draws = 100000;
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < draws; ++i) {
    LightSample ls;
    ASSERT_TRUE(sampleLight(view, light, Vec3(0.0f), 0.0f, u(gen), u(gen), &ls));
    const double e = ls.radiance.x * std::max(0.0f, dot(ls.wi, n)) / ls.pdf;
    sum += e;
    sum2 += e * e;
  }
  const double mean = sum / draws, deviation = std::sqrt(sum2 / draws - mean * mean);
  EXPECT_LT(deviation / mean, 0.01);
}

// A diffuse sphere of albedo a alone under an environment of radiance 1 everywhere shows a,
// whether the environment is constant or a map of ones, turned or not.
TEST(Environment, FurnaceUnderAUniformMapShowsTheAlbedo) {
  const std::string map =
      writeMap("env_ones.pfm", 16, 8, [](uint32_t, uint32_t) { return Vec3(0.5f); });
  for (const std::string& environment :
       {std::string(R"({"color": 1})"),
        R"({"map": ")" + map + R"(", "strength": 2, "rotation": [30, 60, 10]})"}) {
    const RenderResult r = test::renderTestScene(R"({
      "camera": {"width": 16, "height": 16, "fov": 20, "position": [0, 0, 6], "spp": 64},
      "render": {"max_depth": 64},
      "environment": )" + environment + R"(,
      "spheres": [{"position": [0, 0, 0], "radius": 1, "color": 0.6}]})");
    for (int c = 0; c < 3; ++c) {
      const test::RegionStats s = test::regionStats(r.image, 5, 5, 11, 11, c);
      EXPECT_NEAR(s.mean, 0.6, kZ * s.standardError() + 1e-4) << environment << " channel " << c;
    }
  }
}

// A Radiance .hdr file (RGBE, flat scanlines) reads back as the radiance it encodes.
TEST(Environment, ReadsRadianceHdr) {
  const std::string path = tempPath("env_tiny.hdr");
  std::ofstream f(path, std::ios::binary);
  f << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n";
  // (128, 64, 32, e=129): mantissas / 256 * 2^(129 - 128) = 1, 0.5, 0.25; then 0.
  const unsigned char pixels[8] = {128, 64, 32, 129, 0, 0, 0, 0};
  f.write(reinterpret_cast<const char*>(pixels), sizeof pixels);
  f.close();
  const ImageRGB image = readImage(path);
  ASSERT_EQ(image.width, 2u);
  ASSERT_EQ(image.height, 1u);
  EXPECT_FLOAT_EQ(image.at(0, 0).x, 1.0f);
  EXPECT_FLOAT_EQ(image.at(0, 0).y, 0.5f);
  EXPECT_FLOAT_EQ(image.at(0, 0).z, 0.25f);
  EXPECT_EQ(image.at(1, 0).x, 0.0f);
}

std::string loadError(const std::string& environment) {
  try {
    parseSceneText(R"({"camera": {}, "environment": )" + environment + "}", "s.json",
                   ::testing::TempDir());
  } catch (const SceneError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Environment, BadMapsAreRefusedWithOneMessage) {
  EXPECT_EQ(loadError(R"({"map": "no_such_sky.exr"})")
                .rfind("s.json: environment.map: cannot read the environment map: ", 0),
            0u);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  writeMap("env_nan.pfm", 4, 2,
           [&](uint32_t x, uint32_t y) { return Vec3(x == 2 && y == 1 ? nan : 1.0f); });
  EXPECT_EQ(loadError(R"({"map": "env_nan.pfm"})"),
            "s.json: environment.map: env_nan.pfm: texel (2, 1) is NaN; expected finite, "
            "non-negative radiance in every texel");
  writeMap("env_negative.pfm", 4, 2,
           [](uint32_t x, uint32_t) { return Vec3(1, x == 3 ? -1.0f : 1.0f, 1); });
  EXPECT_EQ(loadError(R"({"map": "env_negative.pfm"})"),
            "s.json: environment.map: env_negative.pfm: texel (3, 0) is negative; expected finite, "
            "non-negative radiance in every texel");
  const float inf = std::numeric_limits<float>::infinity();
  writeMap("env_inf.pfm", 4, 2, [&](uint32_t, uint32_t y) { return Vec3(y == 1 ? inf : 1.0f); });
  EXPECT_NE(loadError(R"({"map": "env_inf.pfm"})").find(": texel (0, 1) is infinite;"),
            std::string::npos);
  std::ofstream(tempPath("env_text.exr")) << "not an image";
  EXPECT_EQ(loadError(R"({"map": "env_text.exr"})")
                .rfind("s.json: environment.map: cannot read the environment map: ", 0),
            0u);
  EXPECT_EQ(loadError(R"({"color": 1, "strength": 2})"),
            "s.json: environment.strength: not used by a constant environment (only with a "
            "\"map\" or \"sky\")");
  EXPECT_EQ(loadError(R"({"map": "env_inf.pfm", "strength": -1})"),
            "s.json: environment.strength: expected a non-negative number, got -1");
}

TEST(Environment, AMapTooBrightForItsStrengthIsRefused) {
  writeMap("env_bright.pfm", 4, 2,
           [](uint32_t x, uint32_t y) { return Vec3(1, x == 1 && y == 1 ? 1e30f : 1.0f, 1); });
  EXPECT_EQ(loadError(R"({"map": "env_bright.pfm", "strength": 1e10})"),
            "s.json: environment: the map's texel (1, 1), [1, 1e+30, 1], times color [1, 1, 1] "
            "and strength 1e+10 is beyond single precision; expected a smaller strength or color");
  EXPECT_EQ(loadError(R"({"map": "env_bright.pfm", "strength": 1e8})"), "no error");
}

}  // namespace
}  // namespace candela
