// Alpha masks (MTL d, Tr, map_d): a masked-out surface is no surface for camera and shadow rays,
// in both CPU ray engines. A black blocker quad hangs between a point light and a grey floor, and
// the camera looks down through it at a patch of floor so small that the floor's radiance is
// L0 = rho I / (4 pi^2 d^2) all over it: alpha 0 shows L0 (no blocker, no shadow), alpha 1 shows
// 0 (the black blocker), and alpha 0.5 a quarter of L0 (half the camera rays reach the floor,
// and half of those points see the light).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/constants.h"
#include "cpu_engines.h"
#include "render_test_util.h"
#include "temp_dir.h"
#include "texture_test_util.h"

namespace candela {
namespace {

constexpr float kRho = 0.5f, kIntensity = 7896.0f, kDistance = 10.0f;
const double kL0 = kRho * kIntensity / (4.0 * kPi * kPi * kDistance * kDistance);

// The scene of `objects` (JSON, comma-separated) seen by the camera over the patch of floor and
// lit by the lamp over the blocker, with `render` added to the render settings.
std::string viewOf(const std::string& objects, const std::string& render = "") {
  return R"({
    "camera": {"width": 32, "height": 32, "fov": 1, "spp": 4, "position": [0, 20, 0],
               "look_at": [0, 0, 0], "up": [0, 0, -1]},
    "render": {"max_depth": 1)" +
         render + R"(},
    "objects": [)" +
         objects + R"(],
    "lights": [{"position": [0, 10, 0], "intensity": 7896}]})";
}

// The view's image, with the blocker's MTL statements `blocker`; with `sheets` 2 a second
// blocker of the same material hangs a unit above the first; `render` adds to the render
// settings.
ImageRGB renderView(const std::string& blocker, CpuEngine engine, const test::TempDir& dir,
                    int sheets = 1, const std::string& render = "") {
  dir.write("scene.mtl", "newmtl floor\nKd 0.5 0.5 0.5\nnewmtl blocker\nKd 0 0 0\n" + blocker);
  dir.write("scene.obj",
            "mtllib scene.mtl\n"
            "v -10 0 -10\nv 10 0 -10\nv 10 0 10\nv -10 0 10\n"
            "v -3 5 -3\nv 3 5 -3\nv 3 5 3\nv -3 5 3\n"
            "v -3 6 -3\nv 3 6 -3\nv 3 6 3\nv -3 6 3\n"
            "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
            "usemtl floor\nf 4 3 2 1\nusemtl blocker\nf 8/4 7/3 6/2 5/1\n" +
                std::string(sheets == 2 ? "f 12/4 11/3 10/2 9/1\n" : ""));
  return test::renderWithEngine(viewOf(R"({"file": "scene.obj"})", render), engine, dir.path());
}

// The mean radiance (channel 0) of the view (renderView).
double renderMean(const std::string& blocker, CpuEngine engine, const test::TempDir& dir,
                  int sheets = 1) {
  return test::regionStats(renderView(blocker, engine, dir, sheets), 0, 0, 32, 32, 0).mean;
}

class Alpha : public ::testing::TestWithParam<CpuEngine> {
 protected:
  test::TempDir dir;
};

TEST_P(Alpha, ZeroIsNoSurfaceOneIsOpaque) {
  EXPECT_NEAR(renderMean("d 0\n", GetParam(), dir), kL0, 2e-3 * kL0);
  EXPECT_NEAR(renderMean("Tr 1\n", GetParam(), dir), kL0, 2e-3 * kL0);
  EXPECT_EQ(renderMean("d 1\n", GetParam(), dir), 0.0);
  EXPECT_EQ(renderMean("", GetParam(), dir), 0.0);
}

TEST_P(Alpha, HalfPassesHalfTheRays) {
  // 4096 camera samples, each reaching a lit floor with probability 1/4: the fraction's standard
  // deviation is sqrt(3/16 / 4096) = 0.0068.
  EXPECT_NEAR(renderMean("d 0.5\n", GetParam(), dir) / kL0, 0.25, 4 * 0.0068);
}

TEST_P(Alpha, EachSheetIsPassedOnItsOwn) {
  // Two sheets of alpha 0.5: a camera ray reaches the floor past both a quarter of the time, and
  // a shadow ray from there reaches the light a quarter of the time, so 1/16 of the camera
  // samples find a lit floor: sd sqrt(15/256 / 4096) = 0.0038. One threshold for the whole ray
  // would pass both sheets or neither, half the time: 1/4.
  EXPECT_NEAR(renderMean("d 0.5\n", GetParam(), dir, 2) / kL0, 1.0 / 16, 4 * 0.0038);
}

TEST_P(Alpha, EachSampleDrawsAnewWithoutAntialiasing) {
  // Without antialiasing a pixel's four samples share their camera ray and their shadow ray,
  // yet each passes the sheet on its own: a pixel is dark or lit throughout only where all four
  // samples agree, (3/4)^4 + (1/4)^4 = 32% of them. A threshold drawn from the ray would make
  // every pixel all dark or all lit, never converging.
  const ImageRGB image = renderView("d 0.5\n", GetParam(), dir, 1, R"(, "antialiasing": false)");
  size_t between = 0;
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 32; ++x) {
      const double v = image.at(x, y).x;
      between += v > 0.1 * kL0 && v < 0.9 * kL0;
    }
  // 68% expected, sd sqrt(0.68 * 0.32 / 1024) = 1.5%.
  EXPECT_GT(between, 1024u / 2);
}

TEST_P(Alpha, MaskTextures) {
  // An RGBA texture masks by its alpha; a grey one by its grey.
  ASSERT_TRUE(test::writeTestPng(dir.file("clear.png"), 1, 1, 4, {255, 255, 255, 0}));
  ASSERT_TRUE(test::writeTestPng(dir.file("white.png"), 1, 1, 1, {255}));
  ASSERT_TRUE(test::writeTestPng(dir.file("black.png"), 1, 1, 1, {0}));
  EXPECT_NEAR(renderMean("map_d clear.png\n", GetParam(), dir), kL0, 2e-3 * kL0);
  EXPECT_NEAR(renderMean("map_d black.png\n", GetParam(), dir), kL0, 2e-3 * kL0);
  EXPECT_EQ(renderMean("map_d white.png\n", GetParam(), dir), 0.0);
  // The constant and the texture multiply.
  EXPECT_NEAR(renderMean("d 0\nmap_d white.png\n", GetParam(), dir), kL0, 2e-3 * kL0);
}

// The view of renderView with the blocker an object of its own whose JSON material is `blocker`
// (a black diffuse surface with an "alpha").
double renderJsonMean(const std::string& blocker, CpuEngine engine, const test::TempDir& dir) {
  dir.write("floor.obj", "v -10 0 -10\nv 10 0 -10\nv 10 0 10\nv -10 0 10\nf 4 3 2 1\n");
  dir.write("blocker.obj",
            "v -3 5 -3\nv 3 5 -3\nv 3 5 3\nv -3 5 3\n"
            "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 4/4 3/3 2/2 1/1\n");
  const std::string objects =
      R"({"file": "floor.obj", "color": 0.5}, {"file": "blocker.obj", "material": )" + blocker +
      "}";
  return test::regionStats(test::renderWithEngine(viewOf(objects), engine, dir.path()), 0, 0, 32,
                           32, 0)
      .mean;
}

// A JSON material's "alpha" masks as MTL's d and map_d do: a number, or a texture read from its
// alpha channel where it has one, else from its luminance, or from the channel it names.
TEST_P(Alpha, JsonMaterialsTakeAnAlpha) {
  ASSERT_TRUE(test::writeTestPng(dir.file("clear.png"), 1, 1, 4, {255, 255, 255, 0}));
  ASSERT_TRUE(test::writeTestPng(dir.file("white.png"), 1, 1, 1, {255}));
  ASSERT_TRUE(test::writeTestPng(dir.file("black.png"), 1, 1, 1, {0}));
  const auto mean = [&](const std::string& alpha) {
    return renderJsonMean(R"({"type": "diffuse", "color": 0, "alpha": )" + alpha + "}", GetParam(),
                          dir);
  };
  EXPECT_NEAR(mean("0"), kL0, 2e-3 * kL0);
  EXPECT_EQ(mean("1"), 0.0);
  EXPECT_NEAR(mean("0.5") / kL0, 0.25, 4 * 0.0068);  // as HalfPassesHalfTheRays
  EXPECT_NEAR(mean(R"({"texture": "clear.png"})"), kL0, 2e-3 * kL0);
  EXPECT_NEAR(mean(R"({"texture": "black.png"})"), kL0, 2e-3 * kL0);
  EXPECT_EQ(mean(R"({"texture": "white.png"})"), 0.0);
  EXPECT_EQ(mean(R"({"texture": "clear.png", "channel": "r"})"), 0.0);  // its red is 1
  EXPECT_NEAR(renderJsonMean(R"({"type": "conductor", "color": 0, "alpha": 0})", GetParam(), dir),
              kL0, 2e-3 * kL0);
}

TEST(AlphaErrors, JsonAlphaIsRefusedWhereItCannotBe) {
  const auto error = test::sphereMaterialError;
  EXPECT_EQ(error(R"({"type": "diffuse", "alpha": 0.5})"),
            "test.json: spheres[0].material: a material with an \"alpha\" on a sphere; expected "
            "it on mesh faces (spheres are not masked)");
  EXPECT_EQ(error(R"({"type": "diffuse", "alpha": 1.5})"),
            "test.json: spheres[0].material.alpha: expected an alpha in [0, 1], got 1.5");
  EXPECT_EQ(error(R"({"type": "emissive", "radiance": 1, "alpha": 0.5})"),
            "test.json: spheres[0].material.alpha: not used by an \"emissive\" material");
  EXPECT_EQ(error(R"({"type": "diffuse", "alpha": {"texture": "x.png", "height": 2}})"),
            "test.json: spheres[0].material.alpha.height: unknown key, expected one of "
            "\"texture\", \"checkerboard\", \"scale\", \"offset\", \"rotation\", \"wrap\", "
            "\"filter\", \"channel\"");
}

INSTANTIATE_TEST_SUITE_P(Engines, Alpha, ::testing::ValuesIn(test::builtCpuEngines()),
                         test::cpuEngineName);

}  // namespace
}  // namespace candela
