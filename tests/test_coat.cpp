// Clear coats (render/bsdf_coat.h) rendered against closed forms written here from the model's
// definition, f = w f_coat + (1 - w + w T(wi) T(wo)) f_base: a coated diffuse plane under the
// sun seen straight down (no noise), and a coated white ball in a uniform sky (a furnace,
// against the hemispherical integral of the coat's transmittance). Then how scenes say it and the
// refusals. The BSDF's sampling, reciprocity and energy are tested with every other material's
// in test_bsdf.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/constants.h"
#include "render/material_prepare.h"
#include "render_test_util.h"

namespace candela {
namespace {

using test::num;

// The exact Fresnel reflectance of a smooth dielectric of relative index eta (>= 1) at cos mu.
double fresnel(double mu, double eta) {
  const double sin2t = (1 - mu * mu) / (eta * eta), cost = std::sqrt(1 - sin2t);
  const double rs = (mu - eta * cost) / (mu + eta * cost);
  const double rp = (eta * mu - cost) / (eta * mu + cost);
  return 0.5 * (rs * rs + rp * rp);
}

// GGX of alpha a: the density of normals at cos theta_h = c, and Smith's masking at cos mu.
double ggxD(double c, double a) {
  const double k = c * c * (a * a - 1) + 1;
  return a * a / (kPi * k * k);
}
double ggxG1(double mu, double a) {
  return 2 / (1 + std::sqrt(1 + a * a * (1 - mu * mu) / (mu * mu)));
}

const double kSunDirection[3] = {0.3, -1, 0.5};
constexpr double kIrradiance = 2, kAlbedo = 0.5, kIor = 1.5;

// A diffuse plane of albedo 0.5 under `coat` (JSON fields) lit by the sun, seen from straight
// above by an orthographic camera, one bounce: every pixel sees it from the same direction.
RenderResult sunlitPlane(const std::string& coat) {
  const std::string plane = test::writePlaneObj("coat_plane.obj", 4);
  return test::renderTestScene(R"({
    "camera": {"width": 12, "height": 8, "projection": "orthographic", "view_width": 3,
               "position": [0, 5, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "spp": 2},
    "render": {"antialiasing": false, "max_depth": 1},
    "objects": [{"file": ")" + plane +
                               R"(", "material": {"type": "diffuse", "color": )" + num(kAlbedo) +
                               ", " + coat + R"(}}],
    "lights": [{"type": "directional", "direction": [)" +
                               num(kSunDirection[0]) + ", " + num(kSunDirection[1]) + ", " +
                               num(kSunDirection[2]) + R"(], "intensity": )" + num(kIrradiance) +
                               "}]}");
}

void expectUniform(const RenderResult& r, double expected) {
  for (uint32_t y = 0; y < r.image.height; ++y)
    for (uint32_t x = 0; x < r.image.width; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(r.image.at(x, y)[c], expected, 2e-4 * expected) << x << "," << y;
}

// Seen from straight above (cos_o = 1) with the sun at cos_i: the base's rho / pi E cos_i under
// the coat's transmittance both ways, plus, for a rough coat, its microfacet reflection of the
// sun, w F(h.wo) D(h) G1(wi) G1(wo) / (4 cos_o) E (f cos_i with cos_i cancelled).
TEST(Coat, ASunlitCoatedPlaneMatchesItsClosedForm) {
  const double length =
      std::sqrt(kSunDirection[0] * kSunDirection[0] + 1 + kSunDirection[2] * kSunDirection[2]);
  const double cosI = 1 / length;
  const double base = kAlbedo / kPi * kIrradiance * cosI;
  // Smooth: T = 1 - F; the sun's mirror image in the coat lies outside the view.
  for (const double w : {1.0, 0.5}) {
    SCOPED_TRACE("smooth, weight " + num(w));
    const double t = (1 - fresnel(cosI, kIor)) * (1 - fresnel(1, kIor));
    expectUniform(sunlitPlane(R"("coat": )" + num(w)), base * (1 - w + w * t));
  }
  // Rough (0.5, alpha 0.25): T by quadrature over the visible normals (the table the plastic
  // uses, held against Mitsuba in test_bsdf.cpp), at cos_i and 1.
  const double roughness = 0.5, alpha = roughness * roughness, w = 0.8;
  const double t = roughCoatTransmittance(cosI, float(kIor), float(alpha)) *
                   roughCoatTransmittance(1, float(kIor), float(alpha));
  const double wi[3] = {-kSunDirection[0] / length, 1 / length, -kSunDirection[2] / length};
  const double hy = (wi[1] + 1), hLength = std::sqrt(wi[0] * wi[0] + hy * hy + wi[2] * wi[2]);
  const double cosH = hy / hLength;  // h = (wi + wo) / |wi + wo|, wo = +y: h.wo = h.y
  const double highlight = w * fresnel(cosH, kIor) * ggxD(cosH, alpha) * ggxG1(cosI, alpha) *
                           ggxG1(1, alpha) / 4 * kIrradiance;
  ASSERT_GT(highlight, 0.05 * base);  // the highlight is part of what is checked
  expectUniform(sunlitPlane(R"("coat": )" + num(w) + R"(, "coat_roughness": )" + num(roughness)),
                base * (1 - w + w * t) + highlight);
}

// A white diffuse ball under a full smooth coat in a sky of radiance 1, seen by an orthographic
// camera: at a point seen at cos_o it reflects the sky in its coat, F(cos_o), and shows its base
// through the coat, (1 - F(cos_o)) (1 - F_avg), F_avg = 2 int F(mu) mu dmu over the hemisphere
// of the light that reaches it. Each ring of pixels by cos_o is within its noise of that.
TEST(Coat, ACoatedBallInAUniformSkyMatchesItsClosedForm) {
  constexpr int kIntervals = 4096;
  double average = 0;
  for (int i = 0; i < kIntervals; ++i) {
    const double mu = (i + 0.5) / kIntervals;
    average += 2 * mu * fresnel(mu, kIor) / kIntervals;
  }
  const RenderResult r = test::renderTestScene(R"({
    "camera": {"width": 48, "height": 48, "projection": "orthographic", "view_width": 2.4,
               "position": [0, 0, 5], "look_at": [0, 0, 0], "spp": 64},
    "render": {"antialiasing": false, "max_depth": 2},
    "environment": {"color": 1},
    "spheres": [{"position": [0, 0, 0], "radius": 1,
                 "material": {"type": "diffuse", "color": 1, "coat": 1}}]})");
  constexpr int kRings = 6;
  double sum[kRings] = {}, squares[kRings] = {}, expectedSum[kRings] = {};
  int count[kRings] = {};
  for (uint32_t y = 0; y < 48; ++y)
    for (uint32_t x = 0; x < 48; ++x) {
      const double px = (x + 0.5 - 24) / 20, py = (24 - y - 0.5) / 20, r2 = px * px + py * py;
      if (r2 > 0.95) continue;  // clear of the rim, where the sky shows beside the ball
      const double cosO = std::sqrt(1 - r2);
      const double expected = fresnel(cosO, kIor) + (1 - fresnel(cosO, kIor)) * (1 - average);
      const double value = r.image.at(x, y).y;
      const int ring = std::min(kRings - 1, int(r2 / 0.95 * kRings));
      sum[ring] += value - expected;
      squares[ring] += (value - expected) * (value - expected);
      expectedSum[ring] += expected;
      ++count[ring];
    }
  for (int ring = 0; ring < kRings; ++ring) {
    ASSERT_GT(count[ring], 50);
    const double mean = sum[ring] / count[ring];
    const double sd = std::sqrt(squares[ring] / count[ring] - mean * mean);
    EXPECT_NEAR(mean, 0, 4 * sd / std::sqrt(count[ring]) + 1e-4)
        << "ring " << ring << ", expected about " << expectedSum[ring] / count[ring];
  }
  // Without its coat the ball shows 1; the coat's darkening is what the closed form checks.
  EXPECT_LT(1 - average, 0.93);
}

std::string materialError(const std::string& material) {
  return test::sphereMaterialError(material);
}

TEST(Coat, ScenesSayItOnDiffuseConductorAndPlasticMaterials) {
  const SceneData data = test::loadTestScene(R"({"camera": {"width": 4, "height": 4},
    "spheres": [{"position": [0, 0, 0], "radius": 1,
                 "material": {"type": "conductor", "metal": "Au", "roughness": 0.3, "coat": 0.7,
                              "coat_roughness": 0.2, "coat_ior": 1.6}},
                {"position": [3, 0, 0], "radius": 1, "material": {"type": "plastic", "coat": 1}},
                {"position": [6, 0, 0], "radius": 1, "material": {"type": "mirror", "coat": 0.5}}]})");
  const SceneView view = data.view();
  ASSERT_EQ(view.materialCount, 3u);
  EXPECT_FLOAT_EQ(view.materials[0].coatWeight, 0.7f);
  EXPECT_FLOAT_EQ(view.materials[0].coatRoughness, 0.2f);
  EXPECT_FLOAT_EQ(view.materials[0].coatIor, 1.6f);
  // The rough coat's transmittance table, at normal incidence about 1 - F(1.6) = 0.947.
  EXPECT_NEAR(view.materials[0].coatTransmittance[kPlasticTableSize - 1], 0.947f, 0.01f);
  EXPECT_FLOAT_EQ(view.materials[1].coatWeight, 1.0f);
  EXPECT_FLOAT_EQ(view.materials[1].coatRoughness, 0.0f);
  EXPECT_FLOAT_EQ(view.materials[1].coatIor, 1.5f);
  EXPECT_FLOAT_EQ(view.materials[2].coatWeight, 0.5f);
}

TEST(Coat, RefusesWhatIsNotACoat) {
  EXPECT_NE(
      materialError(R"({"type": "diffuse", "coat": 1.5})").find("expected a coat weight in [0, 1]"),
      std::string::npos);
  EXPECT_NE(
      materialError(R"({"type": "diffuse", "coat_roughness": 0.2})")
          .find(
              "coat_roughness: describes a clear coat; expected a \"coat\" (its weight) beside it"),
      std::string::npos);
  EXPECT_NE(materialError(R"({"type": "plastic", "coat": 1, "coat_ior": 0})").find("coat_ior"),
            std::string::npos);
  EXPECT_NE(materialError(R"({"type": "glass", "coat": 1})")
                .find("coat: not used by a \"glass\" material"),
            std::string::npos);
  EXPECT_NE(materialError(R"({"type": "mix", "materials": ["diffuse", "mirror"], "coat": 1})")
                .find("not used by a \"mix\" material"),
            std::string::npos);
}

}  // namespace
}  // namespace candela
