// Lights and emitters coloured by temperature ({"temperature": kelvin}): black-body colours whose
// chromaticity lies on the Planckian locus (the CIE's published points, to within the colour
// matching functions' fit) at luminance 1; read for a light and an emitter, an emitter seen as
// that colour times its strength; then the refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "render_test_util.h"
#include "scene/blackbody.h"

namespace candela {
namespace {

void xyY(const Vec3& c, double* x, double* y, double* luminance) {
  const double X = 0.4124564 * c.x + 0.3575761 * c.y + 0.1804375 * c.z;
  const double Y = 0.2126729 * c.x + 0.7151522 * c.y + 0.0721750 * c.z;
  const double Z = 0.0193339 * c.x + 0.1191920 * c.y + 0.9503041 * c.z;
  *x = X / (X + Y + Z);
  *y = Y / (X + Y + Z);
  *luminance = Y;
}

// The Planckian locus (CIE 15:2004; 2856 K is illuminant A): the fit of the colour matching
// functions puts candela's within 1.5e-3 of each, below what an eye tells apart (about 3e-3).
TEST(Blackbody, ColoursLieOnThePlanckianLocusAtLuminanceOne) {
  struct Point {
    double kelvin, x, y;
  };
  for (const Point& p :
       {Point{2856, 0.44757, 0.40745}, Point{4000, 0.38045, 0.37676}, Point{5000, 0.34510, 0.35162},
        Point{6500, 0.31352, 0.32363}, Point{10000, 0.27934, 0.28829}}) {
    double x, y, luminance;
    xyY(blackbodyColour(p.kelvin), &x, &y, &luminance);
    EXPECT_NEAR(x, p.x, 1.5e-3) << p.kelvin;
    EXPECT_NEAR(y, p.y, 1.5e-3) << p.kelvin;
    EXPECT_NEAR(luminance, 1.0, 1e-6) << p.kelvin;
  }
  // Warmer below, bluer above, from the coolest to the hottest.
  double previous = INFINITY;
  for (double k = 1000; k <= 40000; k *= 1.5) {
    const Vec3 c = blackbodyColour(k);
    EXPECT_TRUE(c.x >= 0 && c.y > 0 && c.z >= 0) << k;
    const double ratio = c.x / std::max(c.z, 1e-9f);
    EXPECT_LT(ratio, previous) << k;
    previous = ratio;
  }
}

TEST(Blackbody, LightsAndEmittersTakeATemperature) {
  const SceneDesc scene = parseSceneText(R"({"camera": {"width": 4, "height": 4},
      "lights": [{"type": "point", "position": [0, 1, 0], "intensity": 5,
                  "color": {"temperature": 3200}}],
      "materials": {"panel": {"type": "emissive", "radiance": {"temperature": 5600},
                              "strength": 3}}})",
                                         "s.json", ".");
  const Vec3 warm = blackbodyColour(3200), daylight = blackbodyColour(5600);
  EXPECT_EQ(scene.lights.at(0).color.x, warm.x);
  EXPECT_EQ(scene.lights.at(0).color.z, warm.z);
  // An emitter seen straight on is its radiance times its strength.
  const RenderResult r = test::renderTestScene(R"({
      "camera": {"width": 8, "height": 8, "projection": "orthographic", "view_width": 1,
                 "position": [0, 0, 5], "spp": 1},
      "render": {"antialiasing": false, "max_depth": 1},
      "spheres": [{"position": [0, 0, 0], "radius": 2,
                   "material": {"type": "emissive", "radiance": {"temperature": 5600},
                                "strength": 3}}]})");
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(r.image.at(4, 4)[c], 3.0f * daylight[c]);
  EXPECT_GT(daylight.z, warm.z);
}

std::string sceneError(const std::string& members) {
  return test::loadError(R"({"camera": {"width": 4, "height": 4}, )" + members + "}", ".");
}

TEST(Blackbody, RefusesWhatIsNotATemperature) {
  EXPECT_EQ(sceneError(R"("lights": [{"type": "point", "position": [0, 1, 0], "intensity": 1,
                                      "color": {"temperature": 500}}])"),
            "test.json: lights[0].color.temperature: expected a temperature in kelvin from 1000 to "
            "40000, got 500");
  EXPECT_EQ(sceneError(R"("lights": [{"type": "point", "position": [0, 1, 0], "intensity": 1,
                                      "color": {"temperature": 3000, "tint": 1}}])")
                .substr(0, 41),
            "test.json: lights[0].color.tint: unknown ");
  EXPECT_EQ(
      sceneError(R"("lights": [{"type": "point", "position": [0, 1, 0], "intensity": 1,
                                      "color": {"texture": "a.png"}}])"),
      "test.json: lights[0].color: a texture, which only \"rectangle\" lights take; expected a "
      "colour or {\"temperature\": kelvin}");
}

}  // namespace
}  // namespace candela
