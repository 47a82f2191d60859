// Dispersion: glass with an Abbe number bends each colour channel by its own index (Cauchy's law
// through the index at the d line), a path keeping one channel, chosen at random and weighted by
// 3, from the first such glass it meets. So each channel of the image is, within the noise, that
// channel of the same scene rendered with glass of that channel's one index.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render/light_path.h"
#include "render_test_util.h"
#include "scene/cauchy_index.h"

namespace candela {
namespace {

using test::num;

TEST(Dispersion, CauchysIndexHasTheGivenIndexAndAbbeNumber) {
  for (double nd : {1.33, 1.5, 2.42})
    for (double abbe : {15.0, 55.0, 90.0}) {
      EXPECT_NEAR(cauchyIndex(nd, abbe, kLambdaD), nd, 1e-12);
      const double nF = cauchyIndex(nd, abbe, kLambdaF), nC = cauchyIndex(nd, abbe, kLambdaC);
      EXPECT_NEAR((nd - 1.0) / (nF - nC), abbe, 1e-9 * abbe);
      // Normal dispersion: blue bends most.
      EXPECT_GT(cauchyIndex(nd, abbe, kChannelLambda[2]), cauchyIndex(nd, abbe, kChannelLambda[1]));
      EXPECT_GT(cauchyIndex(nd, abbe, kChannelLambda[1]), cauchyIndex(nd, abbe, kChannelLambda[0]));
    }
}

// A ball of strongly dispersive glass (index 1.6, Abbe number 6) in front of three bright strips,
// at `seed`; `glass` is its material's JSON.
ImageRGB renderBall(const std::string& glass, int seed) {
  return test::renderTestScene(R"({
    "camera": {"width": 32, "height": 32, "fov": 24, "position": [0, 1, 6], "spp": 64},
    "render": {"max_depth": 8, "seed": )" +
                               std::to_string(seed) + R"(},
    "environment": {"color": 0.05},
    "spheres": [{"position": [0, 1, 0], "radius": 1.1, "material": )" +
                               glass + R"(}],
    "lights": [
      {"type": "rectangle", "position": [0, 2.3, -3], "size": [8, 0.2], "direction": [0, 0, 1],
       "intensity": 300},
      {"type": "rectangle", "position": [0, 1.2, -3], "size": [8, 0.2], "direction": [0, 0, 1],
       "intensity": 300},
      {"type": "rectangle", "position": [0, 0.1, -3], "size": [8, 0.2], "direction": [0, 0, 1],
       "intensity": 300}]})")
      .image;
}

double squaredDifference(const ImageRGB& a, const ImageRGB& b, int channel) {
  double sum = 0.0;
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x) {
      const double d = double(a.at(x, y)[channel]) - double(b.at(x, y)[channel]);
      sum += d * d;
    }
  return sum;
}

// Each channel of the dispersive ball's image against that channel of the ball rendered with one
// index: the squared differences over the image, over what two renders of each with different
// seeds say the noise alone gives (near 1 when they agree), for the channel's own index and for
// another channel's, which must show.
TEST(Dispersion, EachChannelIsTheGlassOfThatChannelsIndex) {
  const double nd = 1.6, abbe = 6.0;
  const std::string dispersive =
      R"({"type": "glass", "ior": )" + num(nd) + R"(, "abbe": )" + num(abbe) + "}";
  const ImageRGB d1 = renderBall(dispersive, 1), d2 = renderBall(dispersive, 2);
  ImageRGB one[3][2];
  for (int c = 0; c < 3; ++c) {
    const std::string glass =
        R"({"type": "glass", "ior": )" + num(float(cauchyIndex(nd, abbe, kChannelLambda[c]))) + "}";
    one[c][0] = renderBall(glass, 3);
    one[c][1] = renderBall(glass, 4);
  }
  const auto ratio = [&](int channel, int index) {
    const double noise = 0.5 * squaredDifference(d1, d2, channel) +
                         0.5 * squaredDifference(one[index][0], one[index][1], channel);
    return squaredDifference(d1, one[index][0], channel) / noise;
  };
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(ratio(c, c), 1.4) << "channel " << c;
    EXPECT_GT(ratio(c, 2 - c == c ? 0 : 2 - c), 2.0) << "channel " << c << " against another";
  }
}

// Rough dispersive glass holds no light vertex (the channel is the camera path's to choose, after
// the light subpath is traced); rough glass of one index does.
TEST(Dispersion, DispersiveGlassHoldsNoLightVertex) {
  Material rough;
  rough.type = MaterialType::Glass;
  rough.roughness = 0.4f;
  EXPECT_TRUE(holdsLightVertex(rough));
  rough.channelIor = Vec3(1.58f, 1.6f, 1.63f);
  EXPECT_FALSE(holdsLightVertex(rough));
}

// Rough dispersive glass lit by a point light: the image with light subpaths (which start from
// the light) is the image without, within the noise (the ratio of
// EachChannelIsTheGlassOfThatChannelsIndex).
TEST(Dispersion, LightSubpathsLeaveTheImageAsItIs) {
  const auto render = [](const char* lightPaths, int seed) {
    return test::renderTestScene(R"({
      "camera": {"width": 32, "height": 24, "fov": 40, "position": [0, 2, 6],
                 "look_at": [0, 0.8, 0], "spp": 64},
      "render": {"max_depth": 6, "light_paths": ")" +
                                 std::string(lightPaths) + R"(", "seed": )" + std::to_string(seed) +
                                 R"(},
      "spheres": [{"position": [0, -1000, 0], "radius": 1000, "color": 0.6},
                  {"position": [0, 1, 0], "radius": 1,
                   "material": {"type": "glass", "ior": 1.6, "abbe": 6, "roughness": 0.4}}],
      "lights": [{"position": [2, 4, 2], "intensity": 2000}]})")
        .image;
  };
  const ImageRGB on1 = render("on", 1), on2 = render("on", 2);
  const ImageRGB off1 = render("off", 3), off2 = render("off", 4);
  for (int c = 0; c < 3; ++c) {
    const double noise =
        0.5 * squaredDifference(on1, on2, c) + 0.5 * squaredDifference(off1, off2, c);
    EXPECT_LT(squaredDifference(on1, off1, c) / noise, 1.4) << "channel " << c;
  }
}

TEST(Dispersion, TheSceneFormatRefusesWhatItCannotBe) {
  const auto error = test::sphereMaterialError;
  EXPECT_EQ(error(R"({"type": "glass", "abbe": 40})"), "(no error)");
  EXPECT_EQ(error(R"({"type": "glass", "abbe": 0.5})"),
            "test.json: spheres[0].material.abbe: expected an Abbe number of at least 1 (glasses "
            "have 15 to 100), got 0.5");
  EXPECT_EQ(error(R"({"type": "glass", "ior": 1, "abbe": 40})"),
            "test.json: spheres[0].material.abbe: needs an \"ior\" above 1 (a glass denser than "
            "what surrounds it), got 1");
  EXPECT_EQ(error(R"({"type": "plastic", "abbe": 40})"),
            "test.json: spheres[0].material.abbe: not used by a \"plastic\" material");
}

}  // namespace
}  // namespace candela
