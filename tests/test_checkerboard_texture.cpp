// The "checkerboard" texture object: two colours in squares as Mitsuba 3.9's `checkerboard` lays
// them (colour0 where frac(u) and frac(v) are both past one half or neither is), read by the
// nearest texel. Seen on a glowing panel, pixel by pixel against that rule; read for a roughness
// and a bump map; then the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render_test_util.h"
#include "scene/read/texture_reader.h"

namespace candela {
namespace {

// A panel 2 x 2 units facing the camera (u along +x, v along +y), its radiance red and blue
// squares repeated 3 x 2 times: 64 x 64 pixels over 2.5 units, pixel centres only.
TEST(CheckerboardTexture, SquaresLieWhereMitsubasRulePutsThem) {
  const RenderResult r = test::renderTestScene(R"({
      "camera": {"width": 64, "height": 64, "projection": "orthographic", "view_width": 2.5,
                 "position": [0, 0, 5], "spp": 1},
      "render": {"antialiasing": false, "max_depth": 1},
      "objects": [{"shape": "rectangle", "scale": 2, "rotation": [90, 0, 0],
                   "material": {"type": "emissive", "radiance":
                     {"checkerboard": [[1, 0, 0], [0, 0, 1]], "scale": [3, 2]}}}]})");
  int red = 0, blue = 0;
  for (uint32_t y = 0; y < 64; ++y)
    for (uint32_t x = 0; x < 64; ++x) {
      const double a = (x + 0.5 - 32) * 2.5 / 64, b = -(y + 0.5 - 32) * 2.5 / 64;
      const Vec3 seen = r.image.at(x, y);
      if (std::fabs(a) > 1 || std::fabs(b) > 1) {
        ASSERT_EQ(seen.x + seen.z, 0.0f) << x << "," << y;
        continue;
      }
      const double u = 3 * (a + 1) / 2, v = 2 * (b + 1) / 2;
      const double fu = u - std::floor(u), fv = v - std::floor(v);
      // Pixel centres on a square's edge could read either colour.
      if (std::fabs(fu - 0.5) < 1e-3 || fu < 1e-3 || std::fabs(fv - 0.5) < 1e-3 || fv < 1e-3)
        continue;
      const bool colour0 = (fu > 0.5) == (fv > 0.5);
      red += colour0;
      blue += !colour0;
      ASSERT_EQ(seen.x, colour0 ? 1.0f : 0.0f) << x << "," << y;
      ASSERT_EQ(seen.z, colour0 ? 0.0f : 1.0f) << x << "," << y;
    }
  EXPECT_GT(red, 1200);
  EXPECT_GT(blue, 1200);
}

TEST(CheckerboardTexture, ReadsForScalarFieldsAndBumpMaps) {
  const SceneDesc scene = parseSceneText(R"({"camera": {"width": 4, "height": 4},
      "materials": {"tiles": {"type": "plastic", "roughness": {"checkerboard": [0.1, 0.6]},
                              "bump_map": {"checkerboard": [0, 1], "height": 0.01}}}})",
                                         "s.json", ".");
  ASSERT_EQ(scene.textures.size(), 2u);
  const bool first = scene.textures[0]->file.find("[0.1 ") != std::string::npos;
  const TextureDesc& roughness = *scene.textures[first ? 0 : 1];
  ASSERT_EQ(roughness.width, 2u);
  ASSERT_EQ(roughness.height, 2u);
  // Rows from the top: colour0 at the top right and bottom left.
  for (size_t i = 0; i < 4; ++i)
    EXPECT_FLOAT_EQ(texelValue(roughness, i, 0), i == 1 || i == 2 ? 0.1f : 0.6f) << i;
  // One texture for one pair of colours however often it is named.
  const SceneDesc twice = parseSceneText(R"({"camera": {"width": 4, "height": 4},
      "materials": {"a": {"type": "diffuse", "color": {"checkerboard": [0.2, 0.8]}},
                    "b": {"type": "diffuse", "color": {"checkerboard": [0.2, 0.8],
                                                       "scale": [4, 4]}}}})",
                                         "s.json", ".");
  EXPECT_EQ(twice.textures.size(), 1u);
}

std::string materialError(const std::string& material) {
  return test::loadError(
      R"({"camera": {"width": 4, "height": 4}, "materials": {"m": )" + material + "}}", ".");
}

TEST(CheckerboardTexture, RefusesWhatIsNotTwoColours) {
  EXPECT_EQ(materialError(R"({"type": "diffuse", "color": {"checkerboard": [0.2, 0.8, 0.5]}})"),
            "test.json: materials.m.color.checkerboard: expected an array of two colours, "
            "[colour0, colour1], got an array [0.2,0.8,0.5]");
  EXPECT_EQ(materialError(R"({"type": "diffuse", "color": {"checkerboard": [0.2, -1]}})"),
            "test.json: materials.m.color.checkerboard[1]: expected a non-negative number, got -1");
  EXPECT_EQ(
      materialError(
          R"({"type": "diffuse", "color": {"checkerboard": [0, 1], "texture": "a.png"}})"),
      "test.json: materials.m.color: expected either \"texture\" or \"checkerboard\", got both");
  EXPECT_EQ(materialError(R"({"type": "diffuse", "color": {"scale": [2, 2]}})"),
            "test.json: materials.m.color: missing required key \"texture\" (an image file) or "
            "\"checkerboard\" ([colour, colour])");
  EXPECT_EQ(materialError(R"({"type": "glass", "color": {"checkerboard": [0, 1]}})"),
            "test.json: materials.m.color: a texture on a field that takes none (expected a number "
            "or an array of 3 numbers)");
}

}  // namespace
}  // namespace candela
