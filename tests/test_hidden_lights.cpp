// Lights hidden from the camera: a sphere or rectangle light with "visible": false is passed by
// camera rays as if it were not there (a studio's softbox kept out of the shot, as Blender's
// camera ray visibility and Mitsuba 3's hide_emitters do), while it still lights the scene, shows
// in mirrors and through glass. Against closed forms: what a camera ray meets behind it, and the
// rest of the image unchanged, pixel for pixel.
#include <gtest/gtest.h>

#include <string>

#include "render_test_util.h"
#include "temp_dir.h"

namespace candela {
namespace {

// `light` (a JSON light, without its "visible") before a glow of radiance 0.25 facing the camera
// (a quad 5 behind it), seen head-on, partly through a small glass ball that shows it upside down,
// over a grey floor that it lights.
ImageRGB renderBefore(const std::string& light, bool visible, const test::TempDir& dir) {
  dir.write("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n");
  std::string withVisibility = light;
  withVisibility.insert(withVisibility.size() - 1,
                        std::string(R"(, "visible": )") + (visible ? "true" : "false"));
  return test::renderTestScene(R"({
    "camera": {"width": 48, "height": 32, "fov": 40, "position": [0, 0, 6], "spp": 4},
    "render": {"antialiasing": false, "max_depth": 3},
    "spheres": [{"position": [0.35, 0.3, 3], "radius": 0.35,
                 "material": {"type": "glass", "ior": 1.5}},
                {"position": [0, -1001.2, 0], "radius": 1000, "color": 0.5}],
    "objects": [{"file": "quad.obj", "position": [0, 0, -5], "scale": 50,
                 "material": {"type": "emissive", "radiance": 0.25}}],
    "lights": [)" + withVisibility +
                                   "]}",
                               0, dir.path())
      .image;
}

// Where the camera sees the light, the hidden one shows the glow behind it; everywhere else (the
// glow, the ball with the light in it, the floor it lights) the two images are the same to the
// bit.
void expectHiddenFromTheCameraAlone(const std::string& light, double radiance) {
  test::TempDir dir;
  const ImageRGB seen = renderBefore(light, true, dir);
  const ImageRGB hidden = renderBefore(light, false, dir);
  int lightPixels = 0, throughGlass = 0, litFloor = 0;
  for (uint32_t y = 0; y < seen.height; ++y)
    for (uint32_t x = 0; x < seen.width; ++x) {
      const Vec3 a = seen.at(x, y), b = hidden.at(x, y);
      if (std::abs(a.x - radiance) < 1e-4 * radiance) {  // the light, seen directly
        ++lightPixels;
        EXPECT_NEAR(b.x, 0.25, 1e-6) << "pixel (" << x << ", " << y << ")";
      } else {
        throughGlass += a.x > 0.3f;  // the light through the ball
        litFloor += y >= seen.height - 4 && a.x > 0.0f;
        EXPECT_EQ(a.x, b.x) << "pixel (" << x << ", " << y << ")";
        EXPECT_EQ(a.z, b.z) << "pixel (" << x << ", " << y << ")";
      }
    }
  EXPECT_GT(lightPixels, 4);
  EXPECT_GT(throughGlass, 0);
  EXPECT_GT(litFloor, 0);
}

// A 1 x 1 rectangle facing the camera, of radiance 8 / pi.
TEST(HiddenLights, ARectangleLightIsPassedByCameraRaysAlone) {
  expectHiddenFromTheCameraAlone(R"({"type": "rectangle", "position": [0, 0, 0],
    "direction": [0, 0, 1], "size": 1, "intensity": 8})",
                                 8.0 / 3.14159265358979323846);
}

// A sphere of radius 0.5 and radiance 8 / (4 pi^2 0.25): its camera rays pass its front and then,
// from inside, its back.
TEST(HiddenLights, ASphereLightIsPassedByCameraRaysAlone) {
  const double pi = 3.14159265358979323846;
  expectHiddenFromTheCameraAlone(
      R"({"type": "sphere", "position": [0, 0, 0], "radius": 0.5, "intensity": 8})",
      8.0 / (4.0 * pi * pi * 0.25));
}

TEST(HiddenLights, OnlySphereAndRectangleLightsAreSeen) {
  EXPECT_EQ(test::lightsError(R"({"position": [0, 1, 0], "intensity": 1, "visible": false})"),
            "s.json: lights[0].visible: not used by a point light (only \"sphere\" and "
            "\"rectangle\" lights are seen)");
  EXPECT_EQ(test::lightsError(
                R"({"type": "sphere", "position": [0, 1, 0], "radius": 1, "intensity": 1,
                    "visible": 0})"),
            "s.json: lights[0].visible: expected true or false, got 0");
}

}  // namespace
}  // namespace candela
