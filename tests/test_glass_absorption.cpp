// Absorbing glass: glass with a "transmission_depth" d absorbs inside by Beer's law, so that white
// light keeps `color` of itself after d units (OpenPBR's transmission_depth), and no longer tints
// each crossing. The path carries the medium it travels in, entered and left by transmissions
// through the glass's surface, and keeps it through reflections inside.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render/absorption.h"
#include "render_test_util.h"
#include "temp_dir.h"

namespace candela {
namespace {

using test::num;

TEST(GlassAbsorption, BeerTransmittanceIsExponentialAndSafeAtInfinity) {
  const Vec3 t = beerTransmittance(Vec3(0.0f, 0.5f, 2.0f), 3.0f);
  EXPECT_EQ(t.x, 1.0f);
  EXPECT_NEAR(t.y, std::exp(-1.5), 1e-7);
  EXPECT_NEAR(t.z, std::exp(-6.0), 1e-8);
  const Vec3 far = beerTransmittance(Vec3(0.0f, 0.5f, 0.0f), kInfinity);
  EXPECT_EQ(far.x, 1.0f);  // not 0 * infinity
  EXPECT_EQ(far.y, 0.0f);
  EXPECT_EQ(far.z, 1.0f);
}

// A ball of glass of index 1 (which neither bends nor reflects) in front of a glow of radiance 1:
// each pixel's ray, through the pixel's centre, keeps color^(chord / depth) of the glow, the chord
// being its path through the ball: nothing on its way in or out, or after it. The same for rough
// glass, which at index 1 is smooth.
TEST(GlassAbsorption, ABallOfIndexOneKeepsTheColourToThePowerOfItsChordOverTheDepth) {
  test::TempDir dir;
  dir.write("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n");
  const double color[3] = {0.5, 0.25, 0.8}, depth = 0.7, radius = 1.0, distance = 6.0;
  const uint32_t size = 15;
  const double fov = 22.0;
  for (const char* roughness : {"0", "0.3"}) {
    const SceneData data = flattenScene(parseSceneText(
        R"({"camera": {"width": 15, "height": 15, "fov": )" + num(fov) +
            R"(, "position": [0, 0, 6], "spp": 2},
          "render": {"antialiasing": false, "max_depth": 6},
          "spheres": [{"position": [0, 0, 0], "radius": 1, "material": {"type": "glass",
            "ior": 1, "roughness": )" +
            roughness + R"(, "color": [0.5, 0.25, 0.8], "transmission_depth": )" + num(depth) +
            R"(}}],
          "objects": [{"file": "quad.obj", "position": [0, 0, -3], "scale": 100,
                       "material": {"type": "emissive", "radiance": 1}}]})",
        "absorption.json", dir.path()));
    const ImageRGB image = renderCpu(data.view(), RenderOptions{}).image;
    int through = 0;
    for (uint32_t y = 0; y < size; ++y)
      for (uint32_t x = 0; x < size; ++x) {
        const double chord = test::chordThroughBall(
            {0.0, 0.0, distance}, test::pixelCentreDirection(size, size, fov, x, y),
            {0.0, 0.0, 0.0}, radius);
        through += chord > 0.0;
        for (int k = 0; k < 3; ++k)
          EXPECT_NEAR(image.at(x, y)[k], std::pow(color[k], chord / depth), 2e-5)
              << "pixel (" << x << ", " << y << "), channel " << k << ", roughness " << roughness;
      }
    EXPECT_GT(through, int(size * size / 4));  // the ball fills much of the view
  }
}

// A slab of glass of index 1.5 and thickness h seen head-on between a glow of radiance 1 behind it
// and one of radiance 2 behind the camera. Each face reflects R = 0.04 and passes T = 0.96; each
// crossing of the slab keeps a = color^(h / depth). The light from behind passes both faces,
// bouncing 2k times inside on the way: T^2 a / (1 - R^2 a^2); the light from the camera's side is
// reflected by the front face, R, or enters and comes back after an odd number of reflections
// inside: T^2 R a^2 / (1 - R^2 a^2). A medium lost at a reflection inside, or given to the
// reflection off the front face (which stays outside), would show.
TEST(GlassAbsorption, ASlabKeepsItsMediumThroughReflectionsInside) {
  test::TempDir dir;
  dir.write("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n");
  const double color[3] = {0.5, 0.3, 0.9}, depth = 0.5, h = 0.4;
  const SceneData data = flattenScene(parseSceneText(
      R"({"camera": {"width": 8, "height": 8, "fov": 1, "position": [0, 0, 5], "spp": 1024},
        "render": {"antialiasing": false, "max_depth": 64},
        "materials": {"slab": {"type": "glass", "ior": 1.5, "color": [0.5, 0.3, 0.9],
                               "transmission_depth": )" +
          num(depth) + R"(}},
        "objects": [
          {"file": "quad.obj", "material": "slab", "scale": 50},
          {"file": "quad.obj", "material": "slab", "scale": 50, "position": [0, 0, )" +
          num(-h) + R"(], "rotation": [0, 180, 0]},
          {"file": "quad.obj", "position": [0, 0, -3], "scale": 100,
           "material": {"type": "emissive", "radiance": 1}},
          {"file": "quad.obj", "position": [0, 0, 10], "scale": 1000, "rotation": [0, 180, 0],
           "material": {"type": "emissive", "radiance": 2}}]})",
      "slab.json", dir.path()));
  const ImageRGB image = renderCpu(data.view(), RenderOptions{}).image;
  const double r = 0.04, t = 0.96;
  for (int k = 0; k < 3; ++k) {
    const double a = std::pow(color[k], h / depth), bounces = 1.0 / (1.0 - r * r * a * a);
    const double expected = t * t * a * bounces + 2.0 * (r + t * t * r * a * a * bounces);
    const test::RegionStats s = test::regionStats(image, 0, 0, 8, 8, k);
    EXPECT_NEAR(s.mean, expected, 5.0 * s.standardError() + 1e-4 * expected) << "channel " << k;
  }
}

TEST(GlassAbsorption, TheSceneFormatRefusesWhatItCannotBe) {
  const auto error = test::sphereMaterialError;
  EXPECT_EQ(error(R"({"type": "glass", "color": [0.5, 0.2, 1], "transmission_depth": 2})"),
            "(no error)");
  EXPECT_EQ(error(R"({"type": "glass", "color": [0.5, 0, 1], "transmission_depth": 2})"),
            "test.json: spheres[0].material.color: expected a colour in (0, 1] in every channel "
            "with \"transmission_depth\" (what white light keeps after that depth inside), got "
            "an array [0.5,0,1]");
  EXPECT_EQ(
      error(R"({"type": "glass", "color": 1.5, "transmission_depth": 2})"),
      "test.json: spheres[0].material.color: expected a colour in (0, 1] in every channel "
      "with \"transmission_depth\" (what white light keeps after that depth inside), got 1.5");
  EXPECT_EQ(error(R"({"type": "glass", "transmission_depth": 0})"),
            "test.json: spheres[0].material.transmission_depth: expected a positive number, got 0");
  EXPECT_EQ(error(R"({"type": "glass", "color": 1e-38, "transmission_depth": 1e-38})"),
            "test.json: spheres[0].material.color: absorbs more over 1e-38 than single "
            "precision can say; expected a longer transmission_depth or a lighter colour");
  EXPECT_EQ(error(R"({"type": "plastic", "transmission_depth": 1})"),
            "test.json: spheres[0].material.transmission_depth: not used by a \"plastic\" "
            "material");
  EXPECT_EQ(test::loadError(R"({"camera": {}, "spheres": [{"id": "amber", "position": [0, 0, 0],
        "radius": 1, "material": {"type": "glass", "color": 0.5, "transmission_depth": 1}}],
        "animation": {"frames": 2, "tracks": [{"target": "amber", "property": "color",
                                               "keys": [[0, 0.5], [1, 0.7]]}]}})",
                            "."),
            "test.json: animation.tracks[0].property: \"color\" is not used by glass with a "
            "\"transmission_depth\" (its colour sets what it absorbs, once)");
}

}  // namespace
}  // namespace candela
