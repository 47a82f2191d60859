// Lights hidden from the camera: a sphere or rectangle light with "visible": false is passed by
// camera rays as if it were not there (a studio's softbox kept out of the shot, as Blender's
// camera ray visibility and Mitsuba 3's hide_emitters do), while it still lights the scene, shows
// in mirrors and through glass. Against closed forms: what a camera ray meets behind it, and the
// rest of the image unchanged, pixel for pixel.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
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

// Pixels of `hidden` that differ from `seen` are those where `seen` shows what was hidden (as
// `isHidden` tells from the pixel and its value), and there `hidden` is `behind` (a number, or a
// function of the pixel and its value in `seen`); returns how many they are.
double valueOf(double behind, uint32_t, uint32_t, const Vec3&) { return behind; }
template <class F>
double valueOf(const F& behind, uint32_t x, uint32_t y, const Vec3& seen) {
  return behind(x, y, seen);
}

template <class IsHidden, class Behind>
int expectOnlyTheHiddenChanged(const ImageRGB& seen, const ImageRGB& hidden, IsHidden isHidden,
                               const Behind& behind) {
  int count = 0;
  for (uint32_t y = 0; y < seen.height; ++y)
    for (uint32_t x = 0; x < seen.width; ++x) {
      const Vec3 a = seen.at(x, y), b = hidden.at(x, y);
      if (isHidden(x, y, a)) {
        ++count;
        const double expected = valueOf(behind, x, y, a);
        EXPECT_NEAR(b.x, expected, 1e-6 * (1.0 + expected)) << "pixel (" << x << ", " << y << ")";
      } else {
        EXPECT_EQ(a.x, b.x) << "pixel (" << x << ", " << y << ")";
        EXPECT_EQ(a.z, b.z) << "pixel (" << x << ", " << y << ")";
      }
    }
  return count;
}

// An emissive material with "visible": false, on a sphere before the glow, hides as a light does.
TEST(HiddenLights, AnEmissiveMaterialMayBeHidden) {
  test::TempDir dir;
  const auto render = [&](const char* visible) {
    dir.write("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n");
    return test::renderTestScene(R"({
      "camera": {"width": 24, "height": 16, "fov": 40, "position": [0, 0, 6], "spp": 4},
      "render": {"antialiasing": false, "max_depth": 3},
      "spheres": [{"position": [0, 0, 0], "radius": 0.6,
                   "material": {"type": "emissive", "radiance": 3, "visible": )" +
                                     std::string(visible) + R"(}},
                  {"position": [0, -1001.2, 0], "radius": 1000, "color": 0.5}],
      "objects": [{"file": "quad.obj", "position": [0, 0, -5], "scale": 50,
                   "material": {"type": "emissive", "radiance": 0.25}}]})",
                                 0, dir.path())
        .image;
  };
  const auto isLamp = [](uint32_t, uint32_t, const Vec3& v) {
    return std::abs(v.x - 3.0f) < 1e-4f;
  };
  EXPECT_GT(expectOnlyTheHiddenChanged(render("true"), render("false"), isLamp, 0.25), 4);
}

// The camera's ray through pixel (x, y) of the 32 x 24 image 40 degrees across below.
std::array<double, 3> cameraDirection(uint32_t x, uint32_t y) {
  return test::pixelCentreDirection(32, 24, 40.0, x, y);
}

// Whether that ray, from (0, 0, 6), meets the ball of centre (cx, 0, 0) and radius 0.8.
bool meetsBall(const std::array<double, 3>& d, double cx) {
  return test::chordThroughBall({0.0, 0.0, 6.0}, d, {cx, 0.0, 0.0}, 0.8) > 0.0;
}

// A hidden environment shows black to camera rays that leave the scene, and lights the ball and
// shows through the glass ball as before; a sun's hidden disc likewise.
TEST(HiddenLights, TheEnvironmentAndASunsDiscMayBeHidden) {
  // The sun shines along -sun: its disc, 4 degrees across, is seen ahead, a little right and down.
  const double sun[3] = {0.05 / std::sqrt(1.005), -0.05 / std::sqrt(1.005),
                         -1.0 / std::sqrt(1.005)};
  const auto render = [&](const char* environment, const char* visible) {
    return test::renderTestScene(R"({
      "camera": {"width": 32, "height": 24, "fov": 40, "position": [0, 0, 6], "spp": 4},
      "render": {"antialiasing": false, "max_depth": 4},
      "environment": {"color": 0.5, "visible": )" +
                                 std::string(environment) + R"(},
      "spheres": [{"position": [-1.2, 0, 0], "radius": 0.8, "color": 0.6},
                  {"position": [1.2, 0, 0], "radius": 0.8,
                   "material": {"type": "glass", "ior": 1.5}}],
      "lights": [{"type": "directional", "direction": [)" +
                                 test::num(-sun[0]) + ", " + test::num(-sun[1]) + ", " +
                                 test::num(-sun[2]) + R"(], "angle": 4, "intensity": 2,
                  "visible": )" + visible +
                                 "}]}")
        .image;
  };
  const auto leaves = [](uint32_t x, uint32_t y) {
    const std::array<double, 3> d = cameraDirection(x, y);
    return !meetsBall(d, -1.2) && !meetsBall(d, 1.2);
  };
  const auto inDisc = [&](uint32_t x, uint32_t y) {
    const std::array<double, 3> d = cameraDirection(x, y);
    return d[0] * sun[0] + d[1] * sun[1] + d[2] * sun[2] >
           std::cos(2.0 * 3.14159265358979323846 / 180.0);
  };
  const ImageRGB seen = render("true", "true");
  const auto isSky = [&](uint32_t x, uint32_t y, const Vec3&) { return leaves(x, y); };
  EXPECT_GT(expectOnlyTheHiddenChanged(seen, render("false", "false"), isSky, 0.0), 300);
  // The sun's disc alone: the sky behind it stays; the sky alone: the disc stays, less the sky.
  const auto isSun = [&](uint32_t x, uint32_t y, const Vec3&) {
    return leaves(x, y) && inDisc(x, y);
  };
  EXPECT_GT(expectOnlyTheHiddenChanged(seen, render("true", "false"), isSun, 0.5), 0);
  const auto skyGone = [&](uint32_t x, uint32_t y, const Vec3& v) {
    return inDisc(x, y) ? v.x - 0.5 : 0.0;
  };
  EXPECT_GT(expectOnlyTheHiddenChanged(seen, render("false", "true"), isSky, skyGone), 300);
}

TEST(HiddenLights, OnlyWhatIsSeenMayBeHidden) {
  EXPECT_EQ(test::lightsError(R"({"position": [0, 1, 0], "intensity": 1, "visible": false})"),
            "s.json: lights[0].visible: not used by a point light (only \"sphere\", "
            "\"rectangle\" and \"directional\" lights with a disc are seen)");
  EXPECT_EQ(test::lightsError(R"({"type": "directional", "direction": [0, -1, 0], "intensity": 1,
                                  "visible": false})"),
            "s.json: lights[0].visible: not used by a directional light without an \"angle\" (a "
            "sun of no disc is never seen)");
  EXPECT_EQ(test::lightsError(
                R"({"type": "sphere", "position": [0, 1, 0], "radius": 1, "intensity": 1,
                    "visible": 0})"),
            "s.json: lights[0].visible: expected true or false, got 0");
  EXPECT_EQ(test::loadError(R"({"camera": {}, "materials": {"m": {"type": "diffuse",
                                "visible": false}}})",
                            "."),
            "test.json: materials.m.visible: not used by a \"diffuse\" material");
}

}  // namespace
}  // namespace candela
