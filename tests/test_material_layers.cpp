// The layers over a material, rendered against closed forms written here from the models'
// definitions. Clear coats (render/bsdf_coat.h), f = w f_coat + (1 - w + w T(wi) T(wo)) f_base:
// a coated diffuse plane under the sun seen straight down (no noise), and a coated white ball in
// a uniform sky (a furnace, against the hemispherical integral of the coat's transmittance).
// Sheen (render/bsdf_sheen.h), f = c f_sheen + (1 - s K(wi)) (1 - s K(wo)) f_base: the same
// plane, and a black velvet ball in the sky, against the Charlie lobe integrated here. Textures
// of a coat's weight and a sheen's colour, stripe by stripe. Then how scenes say them and the
// refusals. The BSDFs' sampling, reciprocity and energy are tested with
// every other material's in test_bsdf.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/constants.h"
#include "render/bsdf_plastic.h"
#include "render/bsdf_sheen.h"
#include "render/material_prepare.h"
#include "render/surface_layers.h"
#include "render_test_util.h"
#include "shading_normal_test_util.h"
#include "texture_test_util.h"

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

// A diffuse plane of albedo 0.5 under `layers` (JSON fields) lit by the sun travelling along
// `sun`, seen by an orthographic camera from `eye` (JSON; straight above by default), one bounce:
// every pixel sees it from the same direction.
RenderResult sunlitPlane(const std::string& layers, const double* sun = kSunDirection,
                         const std::string& eye = R"([0, 5, 0], "up": [0, 0, -1])") {
  const std::string plane = test::writePlaneObj("layers_plane.obj", 10);
  return test::renderTestScene(R"({
    "camera": {"width": 12, "height": 8, "projection": "orthographic", "view_width": 3,
               "look_at": [0, 0, 0], "spp": 2, "position": )" +
                               eye + R"(},
    "render": {"antialiasing": false, "max_depth": 1},
    "objects": [{"file": ")" + plane +
                               R"(", "material": {"type": "diffuse", "color": )" + num(kAlbedo) +
                               ", " + layers + R"(}}],
    "lights": [{"type": "directional", "direction": [)" +
                               num(sun[0]) + ", " + num(sun[1]) + ", " + num(sun[2]) +
                               R"(], "intensity": )" + num(kIrradiance) + "}]}");
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

// A normal map tilts the diffuse base under a smooth coat (weight 0.7) to n: seen from straight
// above with the sun at l, the base's rho / pi E (n . l) passes the coat through its
// transmittance at the coat's normal, the plane's own, T(l . y) T(1), as Blender's and glTF's
// coat lies smooth over the base's relief; with that map as the coat's own `coat_normal_map` too,
// T(l . n) T(y . n). (A coat that followed the base's map alone would give the second where the
// first is expected: 5.7% apart here, against 2e-4 checked.)
TEST(Coat, LiesSmoothOverTheMaterialsNormalMapUnlessItHasItsOwn) {
  const std::filesystem::path dir = test::mapTestFolder("coat_normal");
  test::writeMappedPlane(dir / "plane.obj");
  const uint8_t texel[3] = {210, 150, 200};
  std::vector<uint8_t> bytes;
  for (int i = 0; i < 12; ++i) bytes.push_back(texel[i % 3]);
  ASSERT_TRUE(test::writeTestPng((dir / "n.png").string(), 2, 2, 3, bytes));
  double t[3], n[3] = {0, 0, 0};
  for (int c = 0; c < 3; ++c) t[c] = 2.0 * texel[c] / 255.0 - 1.0;
  // Tangent +x, bitangent -z (v's way on the plane), normal +y.
  const double nx = t[0], ny = t[2], nz = -t[1], nLength = std::sqrt(nx * nx + ny * ny + nz * nz);
  n[0] = nx / nLength, n[1] = ny / nLength, n[2] = nz / nLength;
  const double sunLength =
      std::sqrt(kSunDirection[0] * kSunDirection[0] + 1 + kSunDirection[2] * kSunDirection[2]);
  const double l[3] = {-kSunDirection[0] / sunLength, 1 / sunLength, -kSunDirection[2] / sunLength};
  const double cosBase = n[0] * l[0] + n[1] * l[1] + n[2] * l[2];
  ASSERT_GT(cosBase, 0.0);
  const double base = kAlbedo / kPi * kIrradiance * cosBase, w = 0.7;
  const auto render = [&](const std::string& coatMap) {
    return test::renderTestScene(R"({
      "camera": {"width": 12, "height": 8, "projection": "orthographic", "view_width": 3,
                 "position": [0, 5, 0], "up": [0, 0, -1], "look_at": [0, 0, 0], "spp": 2},
      "render": {"antialiasing": false, "max_depth": 1},
      "objects": [{"file": "plane.obj", "material": {"type": "diffuse", "color": )" +
                                     num(kAlbedo) + R"(, "normal_map": {"texture": "n.png"},
                   "coat": )" + num(w) +
                                     coatMap + R"(}}],
      "lights": [{"type": "directional", "direction": [)" +
                                     num(kSunDirection[0]) + ", " + num(kSunDirection[1]) + ", " +
                                     num(kSunDirection[2]) + R"(], "intensity": )" +
                                     num(kIrradiance) + "}]}",
                                 0, dir.string());
  };
  const double smooth = (1 - fresnel(l[1], kIor)) * (1 - fresnel(1, kIor));
  const double mapped = (1 - fresnel(cosBase, kIor)) * (1 - fresnel(n[1], kIor));
  ASSERT_GT(std::fabs(smooth - mapped), 0.02 * smooth);
  expectUniform(render(""), base * (1 - w + w * smooth));
  expectUniform(render(R"(, "coat_normal_map": {"texture": "n.png"})"),
                base * (1 - w + w * mapped));
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

// The Charlie sheen lobe of alpha a at cos theta_h, and its directional albedo with Ashikhmin's
// visibility at cos mu, by the midpoint rule over cos_i = t^2 and the whole circle of azimuths.
double charlie(double cosH, double a) {
  return (2 + 1 / a) * std::pow(1 - cosH * cosH, 0.5 / a) / (2 * kPi);
}
double sheenAlbedo(double mu, double a, int kT = 400) {
  const int kPhi = kT;
  double sum = 0;
  for (int i = 0; i < kT; ++i) {
    const double t = (i + 0.5) / kT, cosI = t * t, sinI = std::sqrt(1 - cosI * cosI);
    for (int j = 0; j < kPhi; ++j) {
      const double phi = 2 * kPi * (j + 0.5) / kPhi;
      // wo = (sqrt(1 - mu^2), 0, mu), wi = (sinI cos phi, sinI sin phi, cosI).
      const double hx = std::sqrt(1 - mu * mu) + sinI * std::cos(phi), hy = sinI * std::sin(phi),
                   hz = mu + cosI;
      const double cosH = hz / std::sqrt(hx * hx + hy * hy + hz * hz);
      sum +=
          charlie(cosH, a) * cosI / (4 * (cosI + mu - cosI * mu)) * (2 * t / kT) * (2 * kPi / kPhi);
    }
  }
  return sum;
}

// Seen at a slant from +z and lit from behind the camera, where a sheen glows: the base under
// the sheen's share both ways, 1 - s K, plus the sheen's c D(h) V cos_i E. At roughness 0.5 the
// lobe's albedo stays below 1 (checked), so K is that albedo.
TEST(Sheen, ASunlitSheenedPlaneMatchesItsClosedForm) {
  const double sun[3] = {0, -0.5, -1}, eye[3] = {0, 3, 10};
  const double sunLength = std::sqrt(0.25 + 1), eyeLength = std::sqrt(9.0 + 100.0);
  const double wi[3] = {0, 0.5 / sunLength, 1 / sunLength},
               wo[3] = {0, 3 / eyeLength, 10 / eyeLength};
  const double cosI = wi[1], cosO = wo[1], roughness = 0.5, a = roughness * roughness;
  const double colour[3] = {0.9, 0.5, 0.2}, s = 0.9;
  const double hy = wi[1] + wo[1], hz = wi[2] + wo[2];
  const double cosH = hy / std::sqrt(hy * hy + hz * hz);
  const double visibility = 1 / (4 * (cosI + cosO - cosI * cosO));
  const double kI = sheenAlbedo(cosI, a), kO = sheenAlbedo(cosO, a);
  ASSERT_LT(sheenAlbedo(0.001, a), 1.0);
  const double base = kAlbedo / kPi * kIrradiance * cosI * (1 - s * kI) * (1 - s * kO);
  const RenderResult r =
      sunlitPlane(R"("sheen": [0.9, 0.5, 0.2], "sheen_roughness": )" + num(roughness), sun,
                  "[" + num(eye[0]) + ", " + num(eye[1]) + ", " + num(eye[2]) + "]");
  for (int c = 0; c < 3; ++c) {
    const double sheen = colour[c] * charlie(cosH, a) * visibility * cosI * kIrradiance;
    ASSERT_GT(sheen, 0.3 * base);  // the sheen is much of what is checked
    const double expected = base + sheen;
    // The tables' linear interpolation between 64 cosines: within 1e-3.
    for (uint32_t y = 0; y < r.image.height; ++y)
      for (uint32_t x = 0; x < r.image.width; ++x)
        ASSERT_NEAR(r.image.at(x, y)[c], expected, 1e-3 * expected) << x << "," << y << " " << c;
  }
}

// A black ball under a grey sheen in a sky of radiance 1, seen by an orthographic camera: at a
// point seen at cos_o it shows c K(cos_o), the sheen's albedo there. Each ring of pixels by cos_o
// is within its noise of that.
TEST(Sheen, ABlackVelvetBallInAUniformSkyShowsTheSheensAlbedo) {
  const double roughness = 0.6, a = roughness * roughness, c = 0.8;
  const RenderResult r =
      test::renderTestScene(R"({
    "camera": {"width": 48, "height": 48, "projection": "orthographic", "view_width": 2.4,
               "position": [0, 0, 5], "look_at": [0, 0, 0], "spp": 64},
    "render": {"antialiasing": false, "max_depth": 2},
    "environment": {"color": 1},
    "spheres": [{"position": [0, 0, 0], "radius": 1,
                 "material": {"type": "diffuse", "color": 0, "sheen": )" +
                            num(c) + R"(, "sheen_roughness": )" + num(roughness) + "}}]}");
  constexpr int kRings = 6;
  double rings[kRings][3] = {};  // sum of differences, of their squares, of the expected values
  int count[kRings] = {};
  double lastRing = -1, expected = 0;
  for (uint32_t y = 0; y < 48; ++y)
    for (uint32_t x = 0; x < 48; ++x) {
      const double px = (x + 0.5 - 24) / 20, py = (24 - y - 0.5) / 20, r2 = px * px + py * py;
      if (r2 > 0.95) continue;
      const double cosO = std::sqrt(1 - r2);
      if (cosO != lastRing) expected = c * sheenAlbedo(cosO, a, 100), lastRing = cosO;
      const double difference = r.image.at(x, y).y - expected;
      const int ring = std::min(kRings - 1, int(r2 / 0.95 * kRings));
      rings[ring][0] += difference;
      rings[ring][1] += difference * difference;
      rings[ring][2] += expected;
      ++count[ring];
    }
  for (int ring = 0; ring < kRings; ++ring) {
    ASSERT_GT(count[ring], 50);
    const double mean = rings[ring][0] / count[ring];
    const double sd = std::sqrt(rings[ring][1] / count[ring] - mean * mean);
    EXPECT_NEAR(mean, 0, 4 * sd / std::sqrt(count[ring]) + 2e-3 * rings[ring][2] / count[ring])
        << "ring " << ring << ", expected about " << rings[ring][2] / count[ring];
  }
}

// A smooth sheen's lobe would reflect more than it receives near the horizon; normalized, its
// albedo stays within 1 there and equals the lobe's where that is below 1.
TEST(Sheen, ASmoothSheenIsNormalizedNearTheHorizon) {
  Material m;
  m.sheenColor = Vec3(1.0f);
  m.sheenRoughness = 0.2f;
  prepareMaterial(&m);
  EXPECT_GT(m.sheenAlbedo[0], 1.2f);  // the raw lobe at the horizon
  for (uint32_t k = 0; k < kPlasticTableSize; ++k) {
    EXPECT_LE(m.sheenKept[k], 1.0f + 1e-3f) << k;
    EXPECT_LE(m.sheenKept[k], m.sheenAlbedo[k] * (1.0f + 1e-4f)) << k;
  }
  EXPECT_NEAR(m.sheenAlbedo[kPlasticTableSize / 2],
              sheenAlbedo(double(kPlasticTableSize / 2) / (kPlasticTableSize - 1), 0.04), 2e-3);
}

// A sheen of textured roughness reads its tables at kSheenLevels levels, evenly spaced in
// log(alpha): at a level, that roughness's own tables; halfway between two, the lobe's
// normalization max(1, E) within 0.5% of its own (0.19% measured; E reaches 12 at the horizon at
// the smoothest levels) and the kept share K within 0.015 (0.0136 measured, near the horizon
// at roughness about 0.3, where the normalization sets in: a kink that the levels blend over).
TEST(Sheen, TexturedRoughnessReadsTablesByLevel) {
  const std::vector<float> levels = sheenLevelTables(0, kSheenLevels - 1);
  ASSERT_EQ(levels.size(), size_t(kSheenLevels) * kSheenRow);
  // A scene whose textures reach only some levels gets those alone, the rest zero.
  const std::vector<float> some = sheenLevelTables(3, 5);
  for (size_t i = 0; i < some.size(); ++i)
    ASSERT_EQ(some[i], i >= 3 * kSheenRow && i < 6 * kSheenRow ? levels[i] : 0.0f) << i;
  float normError = 0, keptError = 0;
  for (uint32_t level = 0; level + 1 < kSheenLevels; ++level)
    for (const float blend : {0.0f, 0.5f}) {
      Material m;
      m.sheenColor = Vec3(1.0f);
      m.sheenRoughness = blend == 0.0f
                             ? sheenLevelRoughness(level)
                             : std::sqrt(std::sqrt(sheenAlpha(sheenLevelRoughness(level)) *
                                                   sheenAlpha(sheenLevelRoughness(level + 1))));
      prepareMaterial(&m);
      SurfaceLayers l = untexturedLayers(m);
      l.sheenTable = levels.data() + size_t(level) * kSheenRow;
      l.sheenBlend = blend;
      for (uint32_t k = 0; k < kPlasticTableSize; ++k) {
        const float mu = float(k) / float(kPlasticTableSize - 1);
        if (blend == 0.0f) {
          ASSERT_EQ(sheenAlbedoAt(l, mu), m.sheenAlbedo[k]) << "level " << level << ", k " << k;
          ASSERT_EQ(sheenKeptAt(l, mu), m.sheenKept[k]) << "level " << level << ", k " << k;
        }
        const float norm = std::max(1.0f, m.sheenAlbedo[k]);
        normError =
            std::max(normError, std::fabs(std::max(1.0f, sheenAlbedoAt(l, mu)) - norm) / norm);
        keptError = std::max(keptError, std::fabs(sheenKeptAt(l, mu) - m.sheenKept[k]));
      }
    }
  EXPECT_LT(normError, 5e-3f);
  EXPECT_LT(keptError, 0.015f);
}

// The values of every pixel of planeUnderSun's mapped plane (shading_normal_test_util.h) in
// `material`, 2 spp, in folder `dir`.
std::vector<float> mappedPlane(const std::filesystem::path& dir, const std::string& material) {
  const RenderResult r =
      test::renderTestScene(test::planeUnderSun(material, {0.3, -1, 0.5}, 2), 0, dir.string());
  return r.image.pixels;
}

// Stripes of a coat's weight (0 and 1, in the texture's G), of its roughness (two of the levels
// of its tables, render/bsdf_plastic.h), of a sheen's colour and of its roughness (two of its
// levels, render/surface_layers.h) across the plane: each pixel renders as the layer's number of
// its stripe does, to rounding, but where the lookup blends a stripe's edge; each stripe in many
// pixels.
TEST(Layers, TexturesGiveTheLayersValuesPointByPoint) {
  const std::filesystem::path dir = test::mapTestFolder("layer_stripes");
  test::writeMappedPlane(dir / "plane.obj");
  const Vec3 zero(1, 0, 1), one(0, 1, 0);
  test::writeRowPfm(dir / "stripes.pfm", {zero, zero, zero, zero, one, one, one, one});
  const std::string base = R"({"type": "conductor", "color": [0.8, 0.3, 0.2], "roughness": 0.4, )";
  const std::string stripes = R"({"texture": "stripes.pfm", "scale": [40, 1])";
  const float smoother = plasticCoatLevelRoughness(3), rougher = plasticCoatLevelRoughness(17);
  const Vec3 s(smoother), r(rougher);
  test::writeRowPfm(dir / "coat_roughness.pfm", {s, s, s, s, r, r, r, r});
  const float thinner = sheenLevelRoughness(5), fuller = sheenLevelRoughness(24);
  const Vec3 t(thinner), f(fuller);
  test::writeRowPfm(dir / "sheen_roughness.pfm", {t, t, t, t, f, f, f, f});
  const struct {
    std::string textured, first, second;
  } cases[] = {
      {base + R"("coat": )" + stripes + R"(, "channel": "g"}, "coat_roughness": 0.2})",
       base + R"("coat": 0, "coat_roughness": 0.2})",
       base + R"("coat": 1, "coat_roughness": 0.2})"},
      {base + R"("coat": 1, "coat_roughness": {"texture": "coat_roughness.pfm", "scale": [40, 1],
                                                 "channel": "r"}})",
       base + R"("coat": 1, "coat_roughness": )" + test::num(smoother) + "}",
       base + R"("coat": 1, "coat_roughness": )" + test::num(rougher) + "}"},
      {base + R"("sheen": [0.9, 0.8, 0.7], "sheen_roughness": {"texture": "sheen_roughness.pfm",
                                                                 "scale": [40, 1]}})",
       base + R"("sheen": [0.9, 0.8, 0.7], "sheen_roughness": )" + test::num(thinner) + "}",
       base + R"("sheen": [0.9, 0.8, 0.7], "sheen_roughness": )" + test::num(fuller) + "}"},
      // The sheen is the stripes' colours, (1, 0, 1) and (0, 1, 0).
      {base + R"("sheen": {"texture": "stripes.pfm", "scale": [40, 1]}, "sheen_roughness": 0.9})",
       base + R"("sheen": [1, 0, 1], "sheen_roughness": 0.9})",
       base + R"("sheen": [0, 1, 0], "sheen_roughness": 0.9})"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.textured);
    const std::vector<float> textured = mappedPlane(dir, c.textured);
    const std::vector<float> first = mappedPlane(dir, c.first);
    const std::vector<float> second = mappedPlane(dir, c.second);
    test::expectEachPixelAsOneStripe(textured, first, second, 0.002f);
  }
}

// In the room under a lamp (render_test_util.h), the ceiling (a bright patch over the lamp that
// lights most of the room) and the ball in layered materials: with light subpaths, whose
// connections weigh each layered BSDF's densities both ways against the camera paths', the
// room renders as it does without them. Without them the glossy patch lights the room through
// rare samples (the noise those subpaths take away), a long tail that a pixel's few samples
// hide; so the two are held to each other by the whole image's mean over 8 seeds each, within 4
// standard errors of those means: the difference measured 1.5 of them (and at 8 seeds of 1024
// samples every 8 x 8 block agreed within 1.6), where light vertices that lost their layers, a
// bias of 1.2%, give 4.6.
TEST(Layers, LightSubpathsAgreeWithCameraPaths) {
  const auto imageMean = [](const std::string& lightPaths, int seed) {
    std::string json =
        test::lampUnderTheCeiling(R"("width": 32, "height": 32, "spp": 128)",
                                  R"("max_depth": 3, "light_paths": ")" + lightPaths +
                                      R"(", "seed": )" + std::to_string(seed));
    const std::string ceiling = R"({"position": [0, 1006, 0], "radius": 1000, "color": 0.8})";
    json.replace(json.find(ceiling), ceiling.size(),
                 R"({"position": [0, 1006, 0], "radius": 1000, "material": {"type": "conductor",
                     "metal": "Cu", "roughness": 0.5, "coat": 0.7, "coat_roughness": 0.3,
                     "sheen": [0.6, 0.5, 0.4], "sheen_roughness": 0.4}})");
    const std::string ball = R"({"position": [1, 1, -1], "radius": 1, "color": 0.5})";
    json.replace(json.find(ball), ball.size(),
                 R"({"position": [1, 1, -1], "radius": 1, "material": {"type": "diffuse",
                     "color": [0.2, 0.5, 0.3], "coat": 1, "coat_roughness": 0.2, "sheen": 0.7,
                     "sheen_roughness": 0.6}})");
    const RenderResult r = test::renderTestScene(json);
    double sum = 0;
    for (const float v : r.image.pixels) sum += v;
    return sum / double(r.image.pixels.size());
  };
  constexpr int kSeeds = 8;
  double mean[2] = {}, squares[2] = {};
  for (int side = 0; side < 2; ++side)
    for (int seed = 1; seed <= kSeeds; ++seed) {
      const double m = imageMean(side == 0 ? "on" : "off", seed);
      mean[side] += m / kSeeds;
      squares[side] += m * m / kSeeds;
    }
  double variance = 0;  // of the difference of the two means
  for (int side = 0; side < 2; ++side)
    variance += (squares[side] - mean[side] * mean[side]) * kSeeds / (kSeeds - 1) / kSeeds;
  EXPECT_NEAR(mean[0], mean[1], 4 * std::sqrt(variance))
      << "with light subpaths " << mean[0] << ", without " << mean[1];
  EXPECT_LT(4 * std::sqrt(variance), 0.015 * mean[1]);  // tight enough to see a bias of 1.5%
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

TEST(Sheen, ScenesSayItAndRefuseWhatIsNotASheen) {
  const SceneData data = test::loadTestScene(R"({"camera": {"width": 4, "height": 4},
    "spheres": [{"position": [0, 0, 0], "radius": 1,
                 "material": {"type": "diffuse", "color": 0.2, "sheen": [1, 0.5, 0.25],
                              "sheen_roughness": 0.3}},
                {"position": [3, 0, 0], "radius": 1, "material": {"type": "plastic", "sheen": 0.5}}]})");
  const SceneView view = data.view();
  EXPECT_FLOAT_EQ(view.materials[0].sheenColor.y, 0.5f);
  EXPECT_FLOAT_EQ(view.materials[0].sheenRoughness, 0.3f);
  EXPECT_GT(view.materials[0].sheenKept[0], 0.1f);  // prepared (at the horizon)
  EXPECT_FLOAT_EQ(view.materials[1].sheenColor.x, 0.5f);
  EXPECT_FLOAT_EQ(view.materials[1].sheenRoughness, 0.5f);
  EXPECT_NE(materialError(R"({"type": "diffuse", "sheen": [1, 2, 0]})")
                .find("sheen: expected a colour of channels in [0, 1], got [1, 2, 0]"),
            std::string::npos);
  EXPECT_NE(
      materialError(R"({"type": "diffuse", "sheen_roughness": 0.2})")
          .find("sheen_roughness: describes a sheen; expected a \"sheen\" (its colour) beside it"),
      std::string::npos);
  EXPECT_NE(materialError(R"({"type": "glass", "sheen": 1})")
                .find("sheen: not used by a \"glass\" material"),
            std::string::npos);
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
  EXPECT_NE(materialError(R"({"type": "plastic", "coat_normal_map": {"texture": "n.png"}})")
                .find("coat_normal_map: describes a clear coat"),
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
