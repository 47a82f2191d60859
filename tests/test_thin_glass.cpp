// Thin glass: a sheet of dielectric, such as a window pane, modelled as one face. It reflects
// 2R / (1 + R) of the light (R the Fresnel reflectance at its angle: every bounce between its two
// faces summed) and sends the rest straight on, which traversal does by letting the transmitted
// rays through (geometry/alpha_mask.h). So a glow seen through a pane is dimmed by exactly the
// transmittance, what the pane reflects adds its share, and shadow rays see through the pane as
// the light does: a floor under a pane in sunlight gets the sun's light times the transmittance.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/dielectric_fresnel.h"
#include "cpu_engines.h"
#include "render_test_util.h"
#include "temp_dir.h"

namespace candela {
namespace {

using test::num;

constexpr double kPiDouble = 3.14159265358979323846;

// The unpolarised Fresnel reflectance of a smooth interface, in double precision.
double fresnel(double cosI, double eta) {
  const double cosT = std::sqrt(1.0 - (1.0 - cosI * cosI) / (eta * eta));
  const double rp = (eta * cosI - cosT) / (eta * cosI + cosT);
  const double rs = (cosI - eta * cosT) / (cosI + eta * cosT);
  return 0.5 * (rp * rp + rs * rs);
}

// What a sheet transmits, summed bounce by bounce: T T, T R R T, T R^4 T, ...
double sheetTransmittance(double cosI, double eta) {
  const double r = fresnel(cosI, eta), t = 1.0 - r;
  double sum = 0.0, bounces = t * t;
  for (int k = 0; k < 200; ++k, bounces *= r * r) sum += bounces;
  return sum;
}

TEST(ThinGlass, TheSheetReflectsWhatItsBouncesAddUpTo) {
  for (double eta : {1.2, 1.5, 2.4})
    for (double cosI : {1.0, 0.8, 0.5, 0.2, 0.05})
      EXPECT_NEAR(thinSheetReflectance(float(cosI), float(eta)),
                  1.0 - sheetTransmittance(cosI, eta), 2e-6)
          << "eta " << eta << ", cos " << cosI;
  EXPECT_NEAR(thinSheetReflectance(1.0f, 1.5f), 2.0 * 0.04 / 1.04, 1e-7);  // R = 0.04 head-on
  EXPECT_EQ(thinSheetReflectance(0.0f, 1.5f), 1.0f);                       // grazing
  EXPECT_EQ(thinSheetReflectance(0.6f, 1.0f), 0.0f);  // glass of the air's index is not there
}

class ThinGlass : public ::testing::TestWithParam<CpuEngine> {
 protected:
  test::TempDir dir;

  ImageRGB render(const std::string& json) const {
    dir.write("quad.obj",  // faces +z: counter-clockwise seen from there
              "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n");
    return test::renderWithEngine(json, GetParam(), dir.path());
  }
};

// Every camera ray meets a pane turned `degrees` about y, then a glow of radiance 1 behind it or,
// reflected, a glow of radiance 2 behind the camera: each sample sees 1 with the chance T that the
// pane lets its ray through, else 2, so the image's mean is T + 2 (1 - T) within the binomial
// noise of its 8 x 8 x 4096 samples. The narrow view (every ray within half a degree of the
// axis) sees the pane off its centre, away from the edge its two triangles share: a ray along
// that edge is tested by both, as with any alpha mask, which at pixel centres would not be rare.
TEST_P(ThinGlass, APaneLetsThroughItsTransmittanceAndReflectsTheRest) {
  for (double degrees : {0.0, 40.0}) {
    const ImageRGB image = render(R"({
      "camera": {"width": 8, "height": 8, "fov": 1, "position": [0.3, 0.2, 5], "spp": 4096},
      "render": {"antialiasing": false, "max_depth": 3},
      "materials": {"pane": {"type": "thin_glass", "ior": 1.5}},
      "objects": [
        {"file": "quad.obj", "material": "pane", "scale": 10, "rotation": [0, )" +
                                  num(degrees) + R"(, 0]},
        {"file": "quad.obj", "position": [0, 0, -3], "scale": 100,
         "material": {"type": "emissive", "radiance": 1}},
        {"file": "quad.obj", "position": [0, 0, 10], "scale": 1000, "rotation": [0, 180, 0],
         "material": {"type": "emissive", "radiance": 2}}]})");
    const double t = sheetTransmittance(std::cos(degrees * kPiDouble / 180.0), 1.5);
    const double n = 8.0 * 8.0 * 4096.0;
    const double bound = 5.0 * std::sqrt(t * (1.0 - t) / n);  // a sample is 1 or 2
    const test::RegionStats s = test::regionStats(image, 0, 0, 8, 8, 1);
    EXPECT_NEAR(s.mean, t + 2.0 * (1.0 - t), bound) << degrees << " degrees";
    EXPECT_GT(s.stddev, 0.0);  // the pane is there: not every sample sees the same glow
  }
}

// A floor of albedo 0.5 seen from below a horizontal pane, lit only through it by a sun
// of irradiance 3 at 50 degrees from straight down: the floor's radiance is
// 0.5 / pi * 3 cos 50 times the pane's transmittance at 50 degrees, its shadow rays passing the
// pane as often as the light does (and with the pane's index 1 it lets all of it through).
TEST_P(ThinGlass, ShadowRaysPassThePaneAsOftenAsTheLightDoes) {
  const double theta = 50.0 * kPiDouble / 180.0;
  for (double ior : {1.5, 1.0}) {
    const ImageRGB image =
        render(R"({
      "camera": {"width": 8, "height": 8, "fov": 30, "position": [0, 1, 0], "look_at": [0, 0, 0],
                 "up": [0, 0, -1], "spp": 512},
      "render": {"max_depth": 1},
      "objects": [
        {"file": "quad.obj", "position": [0, 2, 0], "scale": 100, "rotation": [90, 0, 0],
         "material": {"type": "thin_glass", "ior": )" +
               num(ior) + R"(}},
        {"file": "quad.obj", "scale": 100, "rotation": [-90, 0, 0], "color": 0.5}],
      "lights": [{"type": "directional", "direction": [)" +
               num(std::sin(theta)) + ", " + num(-std::cos(theta)) + R"(, 0], "intensity": 3}]})");
    const double t = ior == 1.0 ? 1.0 : sheetTransmittance(std::cos(theta), ior);
    const double full = 0.5 / kPiDouble * 3.0 * std::cos(theta);
    const double n = 8.0 * 8.0 * 512.0;
    const double bound = 5.0 * full * std::sqrt(t * (1.0 - t) / n) + 1e-5 * full;
    EXPECT_NEAR(test::regionStats(image, 0, 0, 8, 8, 0).mean, full * t, bound) << "ior " << ior;
  }
}

INSTANTIATE_TEST_SUITE_P(Engines, ThinGlass, ::testing::ValuesIn(test::builtCpuEngines()),
                         test::cpuEngineName);

TEST(ThinGlass, TheSceneFormatRefusesWhatItCannotBe) {
  const auto error = test::sphereMaterialError;
  EXPECT_EQ(error(R"({"type": "thin_glass"})"),
            "test.json: spheres[0].material: a \"thin_glass\" material on a sphere; expected it "
            "on mesh faces (a thin sheet, such as a window pane), or \"glass\" for a solid sphere");
  EXPECT_EQ(error(R"({"type": "thin_glass", "color": 0.9})"),
            "test.json: spheres[0].material.color: not used by a \"thin_glass\" material");
  EXPECT_EQ(error(R"({"type": "thin_glass", "roughness": 0.2})"),
            "test.json: spheres[0].material.roughness: not used by a \"thin_glass\" material");
  EXPECT_EQ(error(R"({"type": "thin_glass", "ior": 0})"),
            "test.json: spheres[0].material.ior: expected a positive number, got 0");
}

}  // namespace
}  // namespace candela
