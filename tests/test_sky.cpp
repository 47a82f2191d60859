// The analytic sky ("environment": {"sky": ...}, Preetham et al. 1999). Its radiance against the
// test's own evaluation of the paper's formulas (the zenith's luminance and chromaticity, and the
// Perez distribution elsewhere), symmetric about the sun's vertical plane, the ground below the
// horizon; seen by the camera through the map it becomes; lighting a white floor as the
// integral of its radiance over the hemisphere says; then the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render_test_util.h"
#include "scene/sky_model.h"

namespace candela {
namespace {

using test::num;

constexpr double kPiD = 3.14159265358979323846;

Vec3 unit(double x, double y, double z) {
  const double n = std::sqrt(x * x + y * y + z * z);
  return Vec3(float(x / n), float(y / n), float(z / n));
}

// CIE xyY of linear sRGB (D65).
void xyY(const Vec3& c, double* x, double* y, double* luminance) {
  const double X = 0.4124564 * c.x + 0.3575761 * c.y + 0.1804375 * c.z;
  const double Y = 0.2126729 * c.x + 0.7151522 * c.y + 0.0721750 * c.z;
  const double Z = 0.0193339 * c.x + 0.1191920 * c.y + 0.9503041 * c.z;
  *x = X / (X + Y + Z);
  *y = Y / (X + Y + Z);
  *luminance = Y;
}

// The paper's appendix, typed anew: the Perez function F for Y, x and y and the zenith's values,
// for turbidity t and a sun theta_s from the zenith; the sky's xyY at view theta, gamma.
struct Preetham {
  double t, thetaSun;
  double coefficient(int which, int k) const {
    static const double table[3][5][2] = {{{0.1787, -1.4630},
                                           {-0.3554, 0.4275},
                                           {-0.0227, 5.3251},
                                           {0.1206, -2.5771},
                                           {-0.0670, 0.3703}},
                                          {{-0.0193, -0.2592},
                                           {-0.0665, 0.0008},
                                           {-0.0004, 0.2125},
                                           {-0.0641, -0.8989},
                                           {-0.0033, 0.0452}},
                                          {{-0.0167, -0.2608},
                                           {-0.0950, 0.0092},
                                           {-0.0079, 0.2102},
                                           {-0.0441, -1.6537},
                                           {-0.0109, 0.0529}}};
    return table[which][k][0] * t + table[which][k][1];
  }
  double perez(int which, double theta, double gamma) const {
    const double A = coefficient(which, 0), B = coefficient(which, 1), C = coefficient(which, 2),
                 D = coefficient(which, 3), E = coefficient(which, 4);
    return (1 + A * std::exp(B / std::cos(theta))) *
           (1 + C * std::exp(D * gamma) + E * std::cos(gamma) * std::cos(gamma));
  }
  double zenith(int which) const {
    const double s = thetaSun, s2 = s * s, s3 = s2 * s, t2 = t * t;
    if (which == 0) {
      const double chi = (4.0 / 9 - t / 120) * (kPiD - 2 * s);
      return (4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192;
    }
    if (which == 1)
      return t2 * (0.00166 * s3 - 0.00375 * s2 + 0.00209 * s) +
             t * (-0.02903 * s3 + 0.06377 * s2 - 0.03202 * s + 0.00394) +
             (0.11693 * s3 - 0.21196 * s2 + 0.06052 * s + 0.25886);
    return t2 * (0.00275 * s3 - 0.00610 * s2 + 0.00317 * s) +
           t * (-0.04214 * s3 + 0.08970 * s2 - 0.04153 * s + 0.00516) +
           (0.15346 * s3 - 0.26756 * s2 + 0.06670 * s + 0.26688);
  }
  double value(int which, double theta, double gamma) const {
    return zenith(which) * perez(which, theta, gamma) / perez(which, 0, thetaSun);
  }
};

TEST(Sky, RadianceIsThePapersAtTheZenithAndAcrossTheSky) {
  int checked = 0;
  for (const double turbidity : {2.0, 3.0, 6.0}) {
    for (const double elevation : {5.0, 30.0, 60.0, 89.0}) {
      SkyParams sky;
      sky.turbidity = float(turbidity);
      const double e = elevation * kPiD / 180;
      sky.sun = unit(0.3 * std::cos(e), std::sin(e), -0.95 * std::cos(e));
      const Preetham model{turbidity, std::acos(double(sky.sun.y))};
      for (const auto& [theta, phi] :
           {std::pair{0.0, 0.0}, std::pair{0.4, 1.0}, std::pair{1.2, 2.5}, std::pair{1.5, -0.7},
            std::pair{1.0, -2.9}}) {
        const Vec3 d = unit(std::sin(theta) * std::sin(phi), std::cos(theta),
                            -std::sin(theta) * std::cos(phi));
        const double gamma = std::acos(std::min(
            1.0, double(d.x) * sky.sun.x + double(d.y) * sky.sun.y + double(d.z) * sky.sun.z));
        const Vec3 c = skyRadiance(sky, d);
        if (c.x <= 0 || c.y <= 0 || c.z <= 0) continue;  // outside sRGB: clamped
        double x, y, luminance;
        xyY(c, &x, &y, &luminance);
        SCOPED_TRACE("turbidity " + num(turbidity) + ", sun at " + num(elevation) +
                     " degrees, view theta " + num(theta) + ", phi " + num(phi));
        EXPECT_NEAR(luminance, model.value(0, theta, gamma), 2e-5 * luminance);
        EXPECT_NEAR(x, model.value(1, theta, gamma), 2e-5);
        EXPECT_NEAR(y, model.value(2, theta, gamma), 2e-5);
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 50);  // of 60: few directions leave the gamut
}

TEST(Sky, IsSymmetricAboutTheSunsPlaneAndTheGroundLiesBelow) {
  SkyParams sky;
  sky.sun = unit(0, 0.5, -1);  // in the plane x = 0
  sky.ground = Vec3(0.1f, 0.2f, 0.3f);
  for (const Vec3& d : {unit(0.3, 0.4, 0.2), unit(0.9, 0.05, -0.4), unit(0.1, 0.9, 0.3)}) {
    const Vec3 a = skyRadiance(sky, d), b = skyRadiance(sky, Vec3(-d.x, d.y, d.z));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-6 * a[c]);
  }
  const Vec3 down = skyRadiance(sky, unit(0.2, -0.01, 0.5));
  EXPECT_EQ(down.x, 0.1f);
  EXPECT_EQ(down.z, 0.3f);
  // Without a ground, the horizon's radiance at each azimuth goes on below it.
  sky.ground.reset();
  for (const Vec3& d : {unit(0.2, -0.3, 0.5), unit(-0.9, -0.99, 0.1)}) {
    const Vec3 below = skyRadiance(sky, d), horizon = skyRadiance(sky, unit(d.x, 0, d.z));
    for (int c = 0; c < 3; ++c) EXPECT_EQ(below[c], horizon[c]);
  }
  EXPECT_GT(skyRadiance(sky, unit(0.2, -0.3, 0.5)).y, 0.5f);
  // Brighter towards the sun than away from it, bluer overhead than at the horizon.
  EXPECT_GT(skyRadiance(sky, unit(0, 0.4, -1)).y, 1.5f * skyRadiance(sky, unit(0, 0.4, 1)).y);
  const Vec3 zenith = skyRadiance(sky, Vec3(0, 1, 0)), horizon = skyRadiance(sky, unit(1, 0.02, 0));
  EXPECT_GT(zenith.z / zenith.x, 1.5f * horizon.z / horizon.x);
}

// A 1-degree camera at the scene's origin looking 40 degrees up, away from and across from the
// sun: its centre pixel sees the sky map's bilinear lookup, within 0.5% of the model there.
TEST(Sky, TheCameraSeesTheModelThroughTheMap) {
  const Vec3 sun = unit(0.6, 0.57, -0.56);
  for (const double azimuth : {0.0, 90.0, 200.0}) {
    const double e = 40 * kPiD / 180, a = azimuth * kPiD / 180;
    const Vec3 d = unit(std::cos(e) * std::sin(a), std::sin(e), -std::cos(e) * std::cos(a));
    const RenderResult r = test::renderTestScene(
        R"({"camera": {"width": 9, "height": 9, "fov": 1, "spp": 1, "position": [0, 0, 0],
                       "look_at": [)" +
        num(d.x) + ", " + num(d.y) + ", " + num(d.z) + R"(]},
            "render": {"antialiasing": false, "max_depth": 1},
            "environment": {"sky": {"sun": [0.6, 0.57, -0.56], "turbidity": 4},
                            "strength": 2}})");
    SkyParams sky;
    sky.sun = sun;
    sky.turbidity = 4;
    const Vec3 expected = skyRadiance(sky, d) * 2.0f;
    const Vec3 seen = r.image.at(4, 4);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(seen[c], expected[c], 5e-3 * expected[c]) << azimuth;
  }
}

// A white (albedo 0.5) floor under the sky alone, seen from above, direct light only: its
// radiance is 0.5 / pi times the sky's irradiance, integrated here over the hemisphere on a fine
// grid of the model itself.
TEST(Sky, LightsAFloorWithItsIrradiance) {
  SkyParams sky;
  sky.sun = unit(-0.3, 0.7, 0.4);
  sky.turbidity = 2.5f;
  double irradiance[3] = {0, 0, 0};
  const int n = 720;
  for (int i = 0; i < n / 4; ++i) {
    const double theta = (i + 0.5) * (kPiD / 2) / (n / 4);
    for (int j = 0; j < n; ++j) {
      const double phi = (j + 0.5) * 2 * kPiD / n;
      const Vec3 c = skyRadiance(sky, unit(std::sin(theta) * std::cos(phi), std::cos(theta),
                                           std::sin(theta) * std::sin(phi)));
      const double w = std::cos(theta) * std::sin(theta) * (kPiD / 2 / (n / 4)) * (2 * kPiD / n);
      for (int k = 0; k < 3; ++k) irradiance[k] += c[k] * w;
    }
  }
  const RenderResult r = test::renderTestScene(R"({
      "camera": {"width": 16, "height": 16, "projection": "orthographic", "view_width": 2,
                 "position": [0, 5, 0], "rotation": [-90, 0, 0], "spp": 256},
      "render": {"max_depth": 1},
      "environment": {"sky": {"sun": [-0.3, 0.7, 0.4], "turbidity": 2.5}, "visible": false},
      "objects": [{"shape": "rectangle", "scale": 10, "material": {"type": "diffuse", "color": 0.5}}]})");
  for (int k = 0; k < 3; ++k) {
    double mean = 0;
    for (uint32_t y = 0; y < 16; ++y)
      for (uint32_t x = 0; x < 16; ++x) mean += r.image.at(x, y)[k] / 256.0;
    EXPECT_NEAR(mean, 0.5 / kPiD * irradiance[k], 5e-3 * mean) << "channel " << k;
  }
}

std::string environmentError(const std::string& environment) {
  return test::loadError(
      R"({"camera": {"width": 4, "height": 4}, "environment": )" + environment + "}", ".");
}

TEST(Sky, RefusesWhatTheModelCannotBe) {
  EXPECT_EQ(environmentError(R"({"sky": {"sun": [0, -0.1, 1]}})"),
            "test.json: environment.sky.sun: expected a sun at or above the horizon (y >= 0); the "
            "model has no night, got an array [0,-0.1,1]");
  EXPECT_EQ(environmentError(R"({"sky": {"sun": [0, 0, 0]}})"),
            "test.json: environment.sky.sun: expected a direction towards the sun, not [0, 0, 0], "
            "got an array [0,0,0]");
  EXPECT_EQ(
      environmentError(R"({"sky": {"sun": [0, 1, 0], "turbidity": 12}})"),
      "test.json: environment.sky.turbidity: expected a turbidity from 1.7 to 10 (the model's "
      "fitted range), got 12");
  EXPECT_EQ(environmentError(R"({"sky": {"turbidity": 3}})"),
            "test.json: environment.sky: missing required key \"sun\"");
  EXPECT_EQ(environmentError(R"({"sky": {"sun": [0, 1, 0]}, "map": "sky.exr"})"),
            "test.json: environment: expected either \"map\" or \"sky\", got both");
  EXPECT_EQ(environmentError(R"({"sky": {"sun": [0, 1, 0]}, "rotation": [0, 90, 0]})"),
            "test.json: environment.rotation: not used by a \"sky\" (its \"sun\" gives the sun's "
            "direction)");
  EXPECT_EQ(environmentError(R"({"sky": {"sun": [0, 1, 0], "haze": 3}})").substr(0, 40),
            "test.json: environment.sky.haze: unknown");
}

}  // namespace
}  // namespace candela
