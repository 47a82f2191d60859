// A rectangle light whose "color" is a texture (a screen, a window, a gobo): the texture tints its
// radiance point by point, u across its width and v up its height, so that seen from in front it
// shows the image upright and unmirrored. Against closed forms: each quadrant of a four-colour
// texture seen head-on, with the light's up turned; a uniform texture of value g lights the scene
// g times as brightly as the plain light, pixel for pixel; and the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "render_test_util.h"
#include "temp_dir.h"
#include "texture_test_util.h"

namespace candela {
namespace {

using test::num;

constexpr double kPiDouble = 3.14159265358979323846;

class RectangleLightTexture : public ::testing::Test {
 protected:
  void SetUp() override {
    // 8 x 8 texels, a 4 x 4 block of each colour: red, green over blue, white (rows from the
    // top), so that bilinear lookups away from the blocks' edges see one colour.
    std::vector<uint8_t> bytes;
    const uint8_t colours[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x)
        for (int c = 0; c < 3; ++c) bytes.push_back(colours[(y / 4) * 2 + x / 4][c]);
    ASSERT_TRUE(test::writeTestPng(dir.file("quads.png"), 8, 8, 3, bytes));
  }
  ImageRGB render(const std::string& json) const {
    return test::renderTestScene(json, 0, dir.path()).image;
  }
  test::TempDir dir;
};

// The light, 2 x 2 and of power P = pi * 4 (radiance 1 times the texel), faces the camera from 4
// in front; with `up` turned to +x its top is on the right, and so the texture's top row.
TEST_F(RectangleLightTexture, SeenHeadOnItShowsTheTextureUpright) {
  for (const char* up : {"[0, 1, 0]", "[1, 0, 0]"}) {
    const ImageRGB image = render(R"({
      "camera": {"width": 8, "height": 8, "fov": 20, "position": [0, 0, 4], "spp": 1},
      "render": {"antialiasing": false, "max_depth": 1},
      "lights": [{"type": "rectangle", "position": [0, 0, 0], "direction": [0, 0, 1],
                  "up": )" + std::string(up) +
                                  R"(, "size": 2, "intensity": )" + num(4.0 * kPiDouble) +
                                  R"(, "color": {"texture": "quads.png"}}]})");
    const bool turned = std::string(up) == "[1, 0, 0]";
    // The pixels nearest each image corner: (1, 1) top left ... (6, 6) bottom right.
    const Vec3 red(1, 0, 0), green(0, 1, 0), blue(0, 0, 1), white(1, 1, 1);
    const Vec3 topLeft = turned ? blue : red, topRight = turned ? red : green;
    const Vec3 bottomLeft = turned ? white : blue, bottomRight = turned ? green : white;
    const std::pair<int, int> at[4] = {{1, 1}, {6, 1}, {1, 6}, {6, 6}};
    const Vec3 expected[4] = {topLeft, topRight, bottomLeft, bottomRight};
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(image.at(at[k].first, at[k].second)[c], expected[k][c], 1e-5)
            << "up " << up << ", corner " << k << ", channel " << c;
  }
}

// A floor lit only by the light, whose texture is one grey g: every pixel is g times the plain
// light's (the same samples, each scaled).
TEST_F(RectangleLightTexture, AUniformTextureScalesItsLight) {
  ASSERT_TRUE(test::writeTestPng(dir.file("grey.png"), 1, 1, 1, {128}));
  const double g = std::pow((128.0 / 255.0 + 0.055) / 1.055, 2.4);  // sRGB decoded
  const auto scene = [](const std::string& color) {
    return R"({
      "camera": {"width": 16, "height": 12, "fov": 50, "position": [0, 3, 5],
                 "look_at": [0, 0, 0], "spp": 16},
      "render": {"max_depth": 3},
      "spheres": [{"position": [0, -1000, 0], "radius": 1000, "color": 0.5},
                  {"position": [0, 0.5, 0], "radius": 0.5, "color": 0.7}],
      "lights": [{"type": "rectangle", "position": [0, 2, 0], "direction": [0, -1, 0],
                  "size": [1.5, 1], "intensity": 30, "color": )" +
           color + "}]}";
  };
  const ImageRGB plain = render(scene("1"));
  const ImageRGB textured = render(scene(R"({"texture": "grey.png"})"));
  double total = 0.0;
  for (uint32_t y = 0; y < plain.height; ++y)
    for (uint32_t x = 0; x < plain.width; ++x)
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(textured.at(x, y)[c], g * plain.at(x, y)[c], 1e-4 * plain.at(x, y)[c] + 1e-7)
            << "pixel (" << x << ", " << y << ")";
        total += plain.at(x, y)[c];
      }
  EXPECT_GT(total, 1.0);  // the floor is lit
}

TEST_F(RectangleLightTexture, TheSceneFormatRefusesWhatItCannotBe) {
  EXPECT_EQ(test::loadError(R"({"camera": {}, "lights": [{"position": [0, 1, 0], "intensity": 1,
                                "color": {"texture": "quads.png"}}]})",
                            dir.path()),
            "test.json: lights[0].color: a texture, which only \"rectangle\" lights take; "
            "expected a colour or {\"temperature\": kelvin}");
  EXPECT_EQ(test::loadError(R"({"camera": {}, "lights": [{"id": "screen", "type": "rectangle",
        "position": [0, 1, 0], "direction": [0, 0, 1], "size": 1, "intensity": 1,
        "color": {"texture": "quads.png"}}],
        "animation": {"frames": 2, "tracks": [{"target": "screen", "property": "color",
                                               "keys": [[0, 1], [1, 0.5]]}]}})",
                            dir.path()),
            "test.json: animation.tracks[0].property: \"color\" is not used by a rectangle light "
            "whose \"color\" is a texture");
}

}  // namespace
}  // namespace candela
