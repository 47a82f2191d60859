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
  const SceneView turned =
      sceneWithEnvironment(R"({"map": ")" + map + R"(", "rotation": [0, 90, 0]})").view();
  EXPECT_EQ(environmentRadiance(turned, normalize(Vec3(-1, 0, 0.2f))).z, 1.0f);
  EXPECT_EQ(environmentRadiance(turned, normalize(Vec3(-1, 0, -0.2f))).x, 1.0f);
}

// The sampled pdf equals the pdf environmentPdf evaluates for the same direction (what MIS needs)
// and integrates to 1 over the sphere. The distribution is MIS-compensated: it holds only the
// texels brighter than the map's mean (the sun here), so light sampling alone would miss the sky,
// while light sampling beside uniform sampling of the sphere, weighed by the power heuristic as
// the integrator weighs light and BSDF samples, estimates the irradiance that uniform sampling
// alone estimates, with less noise.
TEST(Environment, MapSamplingIsConsistentWithItsPdf) {
  const std::string map = writeMap("env_sun.pfm", 48, 24, [](uint32_t x, uint32_t y) {
    const bool sun = x >= 30 && x < 33 && y >= 6 && y < 8;
    return sun ? Vec3(400, 380, 300) : Vec3(0.1f + 0.01f * float(x % 5), 0.2f, 0.3f + 0.02f * y);
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
  double byMis = 0, byMis2 = 0, byUniform = 0, byUniform2 = 0, pdfIntegral = 0;
  for (int i = 0; i < draws; ++i) {
    double mis = 0.0;
    LightSample ls;
    if (sampleLight(view, light, Vec3(0.0f), u(gen), u(gen), &ls)) {
      ASSERT_NEAR(environmentPdf(view, ls.wi), ls.pdf, 2e-3f * ls.pdf)
          << i << " wi " << ls.wi.x << " " << ls.wi.y << " " << ls.wi.z;
      mis += ls.radiance.x * std::max(0.0f, dot(ls.wi, n)) / ls.pdf *
             powerHeuristic(ls.pdf, uniformPdf);
    }
    const float z = 1 - 2 * u(gen), r = std::sqrt(std::max(0.0f, 1 - z * z)),
                phi = 2 * kPi * u(gen);
    const Vec3 w(r * std::cos(phi), r * std::sin(phi), z);
    const float lightPdf = environmentPdf(view, w);
    pdfIntegral += lightPdf / uniformPdf;
    const double v = environmentRadiance(view, w).x * std::max(0.0f, dot(w, n)) / uniformPdf;
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
  EXPECT_NEAR(pdfIntegral / draws, 1.0, 0.02);
  // The sun's texels are sampled, the sky far from them is not.
  const auto pdfAtTexel = [&](float x, float y) {
    float sinTheta;
    const Vec3 d = mapToDirection((x + 0.5f) / 48, (y + 0.5f) / 24, &sinTheta);
    return environmentPdf(view, view.environment.toWorld * d);
  };
  EXPECT_GT(pdfAtTexel(31, 6), 0.0f);
  EXPECT_EQ(pdfAtTexel(10, 18), 0.0f);
  const double a = byMis / draws, b = byUniform / draws;
  const double tolerance = kZ * std::hypot(error(byMis, byMis2), error(byUniform, byUniform2));
  EXPECT_NEAR(a, b, tolerance);
  EXPECT_LT(error(byMis, byMis2), error(byUniform, byUniform2)) << "importance should help";
}

// Each cell of the sampling distribution has the mean of the bilinear lookup over it (here
// integrated by the midpoint rule on a grid aligned with the bilinear patches, exact for a
// bilinear function), whether texels are split into 4 x 4, 2 x 2 or not at all.
TEST(Environment, SamplingCellsHoldTheMeanOfTheLookupOverThem) {
  const uint32_t w = 6, h = 4;
  std::mt19937 gen(11);
  std::uniform_real_distribution<float> u(0.0f, 5.0f);
  std::vector<Vec3> texels(w * h);
  for (Vec3& t : texels) t = Vec3(u(gen), u(gen), u(gen));
  for (const uint32_t k : {1u, 2u, 4u}) {
    const std::vector<double> cells = environmentCellBrightness(texels.data(), w, h, k);
    ASSERT_EQ(cells.size(), size_t(k * w) * (k * h));
    constexpr uint32_t kSteps = 16;  // even: no step straddles a texel centre
    for (uint32_t cy = 0; cy < k * h; ++cy)
      for (uint32_t cx = 0; cx < k * w; ++cx) {
        double sum = 0.0;
        for (uint32_t j = 0; j < kSteps; ++j)
          for (uint32_t i = 0; i < kSteps; ++i) {
            const float x = (float(cx) + (i + 0.5f) / kSteps) / float(k * w);
            const float y = (float(cy) + (j + 0.5f) / kSteps) / float(k * h);
            sum += componentSum(lookupMap(texels.data(), w, h, x, y));
          }
        EXPECT_NEAR(cells[size_t(cy) * k * w + cx], sum / (kSteps * kSteps), 1e-4)
            << "k " << k << " cell " << cx << ", " << cy;
      }
  }
  EXPECT_EQ(environmentCellsPerTexel(256, 128), 4u);
  EXPECT_EQ(environmentCellsPerTexel(1024, 512), 2u);
  EXPECT_EQ(environmentCellsPerTexel(2048, 1024), 1u);
  EXPECT_EQ(environmentCellsPerTexel(8192, 4096), 1u);
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
            "\"map\")");
  EXPECT_EQ(loadError(R"({"map": "env_inf.pfm", "strength": -1})"),
            "s.json: environment.strength: expected a non-negative number, got -1");
}

}  // namespace
}  // namespace candela
