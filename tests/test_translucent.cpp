// Translucent diffuse surfaces (a diffuse material's "transmittance"; render/bsdf_diffuse.h):
// against closed forms, a sheet under a sun from behind shows T E cos / pi and from the front
// R E cos / pi, pixel for pixel; under an emissive sphere behind it, T L (r / d)^2 cos (next-event
// estimation and MIS through the back); a lantern around a point light shows the irradiance of an
// integrating sphere; a sphere of R + T = 1 in a white furnace vanishes; the
// scene format's refusals and the warning for R + T above 1.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/constants.h"
#include "render_test_util.h"
#include "temp_dir.h"
#include "texture_test_util.h"

namespace candela {
namespace {

using test::num;

// The camera above the plane y = 0 looking down, pixel centres, `spp` samples each.
std::string camera(int spp) {
  return R"("camera": {"width": 32, "height": 24, "fov": 60, "position": [0, 6, 0],
                       "look_at": [0, 0, 0.001], "up": [0, 0, -1], "spp": )" +
         std::to_string(spp) + R"(}, "render": {"antialiasing": false, "max_depth": 1})";
}

std::string sheet(const std::string& obj, double r, double t) {
  return R"("objects": [{"file": ")" + obj + R"(", "material": {"type": "diffuse", "color": )" +
         num(r) + R"(, "transmittance": )" + num(t) + "}}]";
}

TEST(Translucent, UnderASunFromBehindTheSheetShowsTransmittanceTimesIrradiance) {
  const std::string obj = test::writePlaneObj("translucent_plane.obj", 100);
  const double r = 0.3, t = 0.55, irradiance = 2.5;
  for (const double dy : {1.0, -1.0}) {  // upwards: onto the back; downwards: onto the front
    SCOPED_TRACE(dy > 0 ? "from behind" : "from the front");
    const double dx = -0.6, dz = 0.3;
    const RenderResult image = test::renderTestScene(
        "{" + camera(4) + ", " + sheet(obj, r, t) +
            R"(, "lights": [{"type": "directional", "direction": [)" + num(dx) + ", " + num(dy) +
            ", " + num(dz) + R"(], "intensity": )" + num(irradiance) + "}]}",
        1);
    const double cosine = 1.0 / std::sqrt(dx * dx + dy * dy + dz * dz);
    const double expected = (dy > 0 ? t : r) * irradiance * cosine / kPi;
    for (uint32_t y = 0; y < 24; ++y)
      for (uint32_t x = 0; x < 32; ++x)
        ASSERT_NEAR(image.image.at(x, y).x, expected, 2e-6 + 2e-6 * expected) << x << "," << y;
  }
}

// A transmittance texture tints what passes, point by point: a sheet whose texture is magenta on
// its left half and cyan on its right (read from the nearest texel), under a sun from behind.
TEST(Translucent, ATransmittanceTextureTintsWhatPassesPointByPoint) {
  test::TempDir dir;
  dir.write("sheet.obj",
            "v -100 0 100\nv 100 0 100\nv 100 0 -100\nv -100 0 -100\n"
            "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n");
  ASSERT_TRUE(test::writeTestPng(dir.file("halves.png"), 2, 1, 3, {255, 0, 255, 0, 255, 255}));
  const double irradiance = 2.0;
  const RenderResult image = test::renderTestScene(
      "{" + camera(4) + R"(, "objects": [{"file": "sheet.obj", "material": {"type": "diffuse",
          "color": 0.2, "transmittance": {"texture": "halves.png", "filter": "nearest"}}}],
          "lights": [{"type": "directional", "direction": [0, 1, 0], "intensity": )" +
          num(irradiance) + "}]}",
      1, dir.path());
  // The texels are the transmittance (sRGB 255: 1, 0: 0), the sun straight from below.
  const double through = irradiance / kPi;
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 32; ++x) {
      if (x == 15 || x == 16) continue;  // the seam under the image's centre
      const Vec3 v = image.image.at(x, y);
      const bool left = x < 16;
      EXPECT_NEAR(v.x, left ? through : 0.0, 2e-6) << x << "," << y;
      EXPECT_NEAR(v.y, left ? 0.0 : through, 2e-6) << x << "," << y;
      EXPECT_NEAR(v.z, through, 2e-6) << x << "," << y;
    }
}

// An emissive sphere of radiance L and radius rs, its centre a depth h below the sheet, lights a
// point of the sheet at distance d from the centre with irradiance pi L (rs / d)^2 cos, all of it
// in view; what the front shows is T / pi of that.
TEST(Translucent, AnEmitterBehindTheSheetIsSampledThroughIt) {
  const std::string obj = test::writePlaneObj("translucent_plane2.obj", 100);
  const double t = 0.6, radiance = 5.0, rs = 1.0, h = 3.0;
  const SceneData data = test::loadTestScene(
      "{" + camera(64) + ", " + sheet(obj, 0.2, t) + R"(, "spheres": [{"position": [0.5, )" +
      num(-h) + R"(, 0.2], "radius": )" + num(rs) +
      R"(, "material": {"type": "emissive", "radiance": )" + num(radiance) + "}}]}");
  RenderOptions options;
  options.threads = 1;
  const RenderResult image = renderCpu(data.view(), options);
  const Camera& cam = data.camera;
  double sumRendered = 0, sumExpected = 0;
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 32; ++x) {
      const Vec3 d = cam.cameraToWorld * (cam.inverseK * Vec3(x + 0.5f, y + 0.5f, 1.0f));
      const double s = -double(cam.position.y) / d.y;
      const double px = cam.position.x + s * d.x - 0.5, pz = cam.position.z + s * d.z - 0.2;
      const double dist2 = px * px + h * h + pz * pz;
      const double expected = t * radiance * rs * rs / dist2 * (h / std::sqrt(dist2));
      EXPECT_NEAR(image.image.at(x, y).y, expected, 0.05 * expected) << x << "," << y;
      sumRendered += image.image.at(x, y).y;
      sumExpected += expected;
    }
  EXPECT_NEAR(sumRendered / sumExpected, 1.0, 0.005);
}

// Every path's throughput stays 1 where R + T = 1 (each lobe's weight is its colour over its
// chance), so the sphere, lit through and through by a sky of radiance 1, is radiance 1 wherever
// it is seen; a sheet that lost its transmission would show 0.3.
TEST(Translucent, ASphereOfNoLossVanishesInAWhiteFurnace) {
  const RenderResult image = test::renderTestScene(
      R"({"camera": {"width": 24, "height": 24, "fov": 30, "position": [0, 0, 5], "spp": 16},
          "render": {"max_depth": 64}, "environment": {"color": 1},
          "spheres": [{"position": [0, 0, 0], "radius": 1.2, "material": {"type": "diffuse",
                       "color": 0.3, "transmittance": 0.7}}]})",
      1);
  const test::RegionStats all = test::regionStats(image.image, 0, 0, 24, 24, 0);
  EXPECT_NEAR(all.mean, 1.0, 5 * all.standardError() + 1e-4);
  EXPECT_LT(all.stddev, 0.1);
}

// A lantern: a shell of reflectance R and transmittance T, radius r, around a point light of
// power P (its "intensity") at its centre. Inside, as in an integrating sphere, the light
// reflected from any patch lands evenly on the whole shell, so the irradiance is the same
// everywhere, E = P / (4 pi r^2) + R E; outside, the shell shows T E / pi wherever it is seen.
TEST(Translucent, ALanternShowsTheIrradianceOfAnIntegratingSphere) {
  const double r = 0.3, t = 0.6, radius = 1.0, intensity = 20.0;
  const double expected = t * intensity / (4.0 * kPi * radius * radius * (1.0 - r)) / kPi;
  // Paths alone, and with light subpaths connected to them (render/light_path.h), whose first
  // surface is the shell's inside.
  for (const char* lightPaths : {"off", "on"}) {
    SCOPED_TRACE(std::string("light_paths ") + lightPaths);
    const RenderResult image = test::renderTestScene(
        R"({"camera": {"width": 24, "height": 24, "fov": 20, "position": [0, 0, 5], "spp": 16},
            "render": {"max_depth": 64, "light_paths": ")" +
            std::string(lightPaths) + R"("}, "spheres": [{"position": [0, 0, 0], "radius": )" +
            num(radius) + R"(, "material": {"type": "diffuse", "color": )" + num(r) +
            R"(, "transmittance": )" + num(t) + R"(}}],
            "lights": [{"type": "point", "position": [0, 0, 0], "intensity": )" +
            num(intensity) + "}]}",
        1);
    // The shell fills the view; the central 8 x 8 pixels, seen nearly head-on, are compared.
    const test::RegionStats centre = test::regionStats(image.image, 8, 8, 16, 16, 0);
    EXPECT_NEAR(centre.mean, expected, 5 * centre.standardError() + 1e-4 * expected);
    EXPECT_LT(centre.stddev, 0.1 * expected);
  }
}

TEST(Translucent, TheSceneFormatRefusesWhatASheetCannotBe) {
  const auto error = [](const std::string& m) { return test::sphereMaterialError(m); };
  EXPECT_EQ(error(R"({"type": "diffuse", "transmittance": [0.5, 1.5, 0]})"),
            "test.json: spheres[0].material.transmittance: expected a colour of channels in [0, "
            "1], got [0.5, 1.5, 0]");
  EXPECT_EQ(error(R"({"type": "diffuse", "transmittance": 0.5, "coat": 1})"),
            "test.json: spheres[0].material.transmittance: a translucent material takes no "
            "\"coat\" or \"sheen\" (they lie on one side)");
  EXPECT_EQ(error(R"({"type": "diffuse", "transmittance": {"texture": 3}})"),
            "test.json: spheres[0].material.transmittance.texture: expected a string, got 3");
  EXPECT_EQ(error(R"({"type": "plastic", "transmittance": 0.5})"),
            "test.json: spheres[0].material.transmittance: not used by a \"plastic\" material (a "
            "\"diffuse\" one lets light through diffusely)");
  EXPECT_EQ(error(R"({"type": "glass", "transmittance": 0.5})"),
            "test.json: spheres[0].material.transmittance: not used by a \"glass\" material (a "
            "\"diffuse\" one lets light through diffusely; a glass's \"color\" tints what "
            "passes it)");
  const SceneDesc bright = parseSceneText(
      R"({"camera": {}, "spheres": [{"position": [0, 0, 0], "radius": 1, "material":
          {"type": "diffuse", "color": 0.6, "transmittance": 0.5}}]})",
      "test.json", ".");
  // Textured, the tint (1) is not what the texels let through: no warning.
  test::TempDir dir;
  ASSERT_TRUE(test::writeTestPng(dir.file("grey.png"), 1, 1, 3, {100, 100, 100}));
  EXPECT_TRUE(parseSceneText(
                  R"({"camera": {}, "spheres": [{"position": [0, 0, 0], "radius": 1, "material":
                      {"type": "diffuse", "color": 0.6, "transmittance": {"texture":
                      "grey.png"}}}]})",
                  "test.json", dir.path())
                  .warnings.empty());
  ASSERT_EQ(bright.warnings.size(), 1u);
  EXPECT_NE(bright.warnings[0].find("color [0.6, 0.6, 0.6] and transmittance [0.5, 0.5, 0.5] sum "
                                    "above 1"),
            std::string::npos)
      << bright.warnings[0];
}

}  // namespace
}  // namespace candela
