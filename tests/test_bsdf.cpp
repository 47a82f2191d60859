// Every BSDF of render/bsdf.h: sampling against the pdf (a chi-square test over the sphere of
// directions), each sample's pdf and weight against evalBsdf, reciprocity, energy (a white
// furnace: albedo <= 1, and exactly 1 where nothing is lost), and the plastic's derived values
// against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "render/bsdf.h"
#include "render/material_prepare.h"
#include "untextured_bsdf.h"

namespace candela {
namespace {

const Vec3 kUp(0.0f, 0.0f, 1.0f);

Vec3 direction(float cosTheta, float phi) {
  const float s = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  return {s * std::cos(phi), s * std::sin(phi), cosTheta};
}

Material conductor(float roughness, bool metal) {
  Material m;
  m.type = MaterialType::Conductor;
  m.roughness = roughness;
  m.color = Vec3(1.0f);
  if (metal) {
    m.metal = true;
    m.metalEta = Vec3(0.143f, 0.375f, 1.442f);  // gold
    m.metalK = Vec3(3.983f, 2.386f, 1.603f);
  }
  return m;
}

Material glass(float roughness, float ior) {
  Material m;
  m.type = MaterialType::Glass;
  m.roughness = roughness;
  m.ior = ior;
  m.color = Vec3(1.0f);
  return m;
}

Material anisotropic(Material m, float anisotropy) {
  m.anisotropy = anisotropy;
  return m;
}

Material plastic(float roughness, const Vec3& color) {
  Material m;
  m.type = MaterialType::Plastic;
  m.roughness = roughness;
  m.color = color;
  prepareMaterial(&m);
  return m;
}

Material diffuse() {
  Material m;
  m.color = Vec3(0.7f);
  return m;
}

// A diffuse sheet that reflects `color` and lets `transmittance` through (render/bsdf_diffuse.h).
Material translucent(const Vec3& color, const Vec3& transmittance) {
  Material m;
  m.type = MaterialType::Translucent;
  m.color = color;
  m.transmittance = transmittance;
  return m;
}

// m under a sheen of colour `color` (render/bsdf_sheen.h).
Material sheened(Material m, const Vec3& color, float roughness) {
  m.sheenColor = color;
  m.sheenRoughness = roughness;
  prepareMaterial(&m);
  return m;
}

// m under a clear coat (render/bsdf_coat.h).
Material coated(Material m, float weight, float roughness) {
  m.coatWeight = weight;
  m.coatRoughness = roughness;
  prepareMaterial(&m);
  return m;
}

struct Case {
  std::string name;
  Material material;
  Vec3 wo;
  Vec3 ng = kUp;  // wo below it: the inside of glass
  Vec3 tangent = Vec3(0.0f);
};

std::vector<Case> cases() {
  const Vec3 steep = normalize(Vec3(0.3f, -0.2f, 0.9f));
  const Vec3 grazing = normalize(Vec3(0.9f, 0.3f, 0.15f));
  return {
      {"diffuse", diffuse(), steep},
      {"translucent diffuse", translucent(Vec3(0.5f, 0.3f, 0.1f), Vec3(0.2f, 0.4f, 0.6f)), steep},
      {"translucent diffuse from behind, grazing", translucent(Vec3(0.1f), Vec3(0.8f)), -grazing},
      {"rough conductor 0.3", conductor(0.3f, false), steep},
      {"rough gold 0.6 grazing", conductor(0.6f, true), grazing},
      {"rough conductor 1", conductor(1.0f, false), grazing},
      {"rough glass 0.4 outside", glass(0.4f, 1.5f), steep},
      {"rough glass 0.7 grazing", glass(0.7f, 1.5f), grazing},
      {"rough glass 0.4 inside", glass(0.4f, 1.5f), -steep},
      {"rough glass 0.5 ior 0.7", glass(0.5f, 0.7f), steep},
      {"smooth plastic", plastic(0.0f, Vec3(0.6f, 0.3f, 0.2f)), steep},
      {"rough plastic 0.3", plastic(0.3f, Vec3(0.5f)), steep},
      {"rough plastic 0.8 grazing", plastic(0.8f, Vec3(0.9f)), grazing},
      {"anisotropic conductor 0.5", anisotropic(conductor(0.5f, false), 0.8f), steep, kUp,
       Vec3(1.0f, 2.0f, 0.5f)},
      {"anisotropic gold 0.4 grazing", anisotropic(conductor(0.4f, true), 0.9f), grazing},
      {"anisotropic glass 0.5 outside", anisotropic(glass(0.5f, 1.5f), 0.6f), steep, kUp,
       Vec3(0.0f, 1.0f, 0.0f)},
      {"anisotropic glass 0.6 inside", anisotropic(glass(0.6f, 1.5f), 0.9f), -steep},
      {"smooth coat over diffuse", coated(diffuse(), 1.0f, 0.0f), steep},
      {"rough coat 0.3 over rough gold", coated(conductor(0.5f, true), 0.8f, 0.3f), steep},
      {"rough coat 0.2 over a mirror, grazing", coated(conductor(0.0f, false), 1.0f, 0.2f),
       grazing},
      {"half a rough coat over rough plastic", coated(plastic(0.4f, Vec3(0.5f)), 0.5f, 0.6f),
       steep},
      {"sheen 0.5 over diffuse", sheened(diffuse(), Vec3(0.9f, 0.6f, 0.3f), 0.5f), steep},
      {"smooth sheen 0.1 over rough gold, grazing",
       sheened(conductor(0.5f, true), Vec3(1.0f), 0.1f), grazing},
      {"sheen and a smooth coat over rough metal",
       coated(sheened(conductor(0.3f, false), Vec3(0.5f), 0.3f), 1.0f, 0.0f), steep},
      {"sheen and a rough coat over plastic",
       coated(sheened(plastic(0.3f, Vec3(0.4f)), Vec3(0.8f), 0.7f), 0.6f, 0.2f), grazing},
  };
}

Bsdf bsdfOf(const Case& c) { return untexturedBsdf(c.material, c.wo, c.ng, c.ng, c.tangent); }

// The chi-square statistic's tail as a standard normal deviate (Wilson-Hilferty).
double chiSquareZ(double chi2, int dof) {
  const double k = dof, t = 2.0 / (9.0 * k);
  return (std::cbrt(chi2 / k) - (1.0 - t)) / std::sqrt(t);
}

TEST(Bsdf, SamplesFollowThePdf) {
  constexpr int kCos = 24, kPhi = 48, kSub = 24, kSamples = 400000;
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const Bsdf b = bsdfOf(c);
    std::vector<double> observed(kCos * kPhi, 0.0), expected(kCos * kPhi, 0.0);
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (int i = 0; i < kSamples; ++i) {
      BsdfSample s;
      if (!sampleBsdf(b, uniform(rng), uniform(rng), uniform(rng), &s) || s.delta) continue;
      const float cosTheta = std::clamp(s.wi.z, -1.0f, 1.0f);
      float phi = std::atan2(s.wi.y, s.wi.x);
      if (phi < 0.0f) phi += 2.0f * kPi;
      const int ci = std::min(kCos - 1, int((cosTheta + 1.0f) * 0.5f * kCos));
      const int pi = std::min(kPhi - 1, int(phi / (2.0f * kPi) * kPhi));
      observed[ci * kPhi + pi] += 1.0;
      // What the sample reports is what evalBsdf says of its direction.
      float pdf;
      const Vec3 f = evalBsdf(b, s.wi, &pdf);
      ASSERT_NEAR(s.pdf, pdf, 1e-3f * pdf) << "sample " << i;
      for (int a = 0; a < 3; ++a) ASSERT_NEAR(s.weight[a], f[a] / pdf, 2e-3f * s.weight[a] + 1e-6f);
    }
    // Expected counts: the pdf integrated over each bin (solid angle = dcos dphi), finely: rough
    // refraction near the horizon has a steep ridge that a coarse rule overestimates.
    const double cell = (2.0 / kCos) * (2.0 * kPi / kPhi) / (kSub * kSub);
    for (int ci = 0; ci < kCos; ++ci)
      for (int pi = 0; pi < kPhi; ++pi)
        for (int sy = 0; sy < kSub; ++sy)
          for (int sx = 0; sx < kSub; ++sx) {
            const float cosTheta = -1.0f + 2.0f * (ci + (sy + 0.5f) / kSub) / kCos;
            const float phi = 2.0f * kPi * (pi + (sx + 0.5f) / kSub) / kPhi;
            float pdf;
            evalBsdf(b, direction(cosTheta, phi), &pdf);
            expected[ci * kPhi + pi] += pdf * cell * kSamples;
          }
    // Bins expecting fewer than 5 are pooled.
    double chi2 = 0.0, pooledObserved = 0.0, pooledExpected = 0.0;
    int bins = 0;
    for (size_t i = 0; i < observed.size(); ++i) {
      if (expected[i] < 5.0) {
        pooledObserved += observed[i];
        pooledExpected += expected[i];
        continue;
      }
      chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
      ++bins;
    }
    if (pooledExpected >= 5.0) {
      chi2 +=
          (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
      ++bins;
    } else {
      EXPECT_LT(pooledObserved, 25.0) << "samples where the pdf says there are almost none";
    }
    ASSERT_GT(bins, 10);
    EXPECT_LT(chiSquareZ(chi2, bins - 1), 4.5) << "chi2 " << chi2 << " over " << bins << " bins";
  }
}

// f(wo, wi) = f(wi, wo) for reflection; across an interface f(wo, wi) eta_o^-2 = f(wi, wo)
// eta_i^-2 for radiance (Veach 1997, 5.2), eta_o and eta_i the indices on each direction's side.
TEST(Bsdf, IsReciprocal) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    for (int i = 0; i < 2000; ++i) {
      const Vec3 wo = direction(uniform(rng), 2.0f * kPi * uniform(rng));
      const bool transmit = transmits(c.material) && i % 2 == 1;
      const Vec3 wi = direction(transmit ? -uniform(rng) : uniform(rng), 2.0f * kPi * uniform(rng));
      float pdf;
      const Vec3 forward =
          evalBsdf(untexturedBsdf(c.material, wo, kUp, kUp, c.tangent), wi, &pdf) / std::fabs(wi.z);
      const Vec3 backward =
          evalBsdf(untexturedBsdf(c.material, wi, kUp, kUp, c.tangent), wo, &pdf) / std::fabs(wo.z);
      // wo outside (index 1), wi inside (index ior) when transmitting.
      const bool refracts = transmit && c.material.type == MaterialType::Glass;
      const float scale = refracts ? c.material.ior * c.material.ior : 1.0f;
      for (int a = 0; a < 3; ++a)
        ASSERT_NEAR(forward[a] * scale, backward[a], 2e-3f * backward[a] + 1e-5f)
            << "wo " << wo.x << " " << wo.y << " " << wo.z << ", wi " << wi.x << " " << wi.y << " "
            << wi.z;
    }
  }
}

// Albedo: the mean sample weight, with the 1 / eta^2 of transmissions taken out.
Vec3 albedo(const Material& m, const Vec3& wo, int samples) {
  const Bsdf b = untexturedBsdf(m, wo, kUp, kUp);
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  Vec3 sum(0.0f);
  for (int i = 0; i < samples; ++i) {
    BsdfSample s;
    if (sampleBsdf(b, uniform(rng), uniform(rng), uniform(rng), &s))
      sum += s.weight * (s.eta * s.eta);
  }
  return sum / float(samples);
}

TEST(Bsdf, WhiteFurnaceNeverGainsEnergy) {
  constexpr int kSamples = 200000;
  for (float cosTheta : {0.95f, 0.6f, 0.2f, 0.05f}) {
    const Vec3 wo = direction(cosTheta, 0.7f);
    SCOPED_TRACE("cos " + std::to_string(cosTheta));
    Material white;
    white.color = Vec3(1.0f);
    EXPECT_NEAR(albedo(white, wo, kSamples).x, 1.0f, 1e-5f);
    const Vec3 sheet =
        albedo(translucent(Vec3(0.3f, 0.5f, 0.0f), Vec3(0.7f, 0.5f, 0.2f)), wo, kSamples);
    // Reflection and transmission chosen at random: within 6 standard deviations of the mean.
    EXPECT_NEAR(sheet.x, 1.0f, 3e-3f);
    EXPECT_NEAR(sheet.y, 1.0f, 3e-3f);
    EXPECT_NEAR(sheet.z, 0.2f, 3e-3f);
    EXPECT_NEAR(albedo(conductor(0.0f, false), wo, kSamples).x, 1.0f, 1e-6f);
    EXPECT_NEAR(albedo(glass(0.0f, 1.5f), wo, kSamples).x, 1.0f, 1e-5f);
    EXPECT_NEAR(albedo(plastic(0.0f, Vec3(1.0f)), wo, kSamples).x, 1.0f, 0.005f);
    for (float r : {0.2f, 0.5f, 1.0f}) {
      SCOPED_TRACE("roughness " + std::to_string(r));
      // Single scattering loses what bounces more than once among the facets; never gains.
      const float c = albedo(conductor(r, false), wo, kSamples).x;
      EXPECT_LE(c, 1.0f + 1e-4f);
      if (r <= 0.2f && cosTheta >= 0.2f) {
        EXPECT_GT(c, 0.97f);
      }
      EXPECT_LE(albedo(glass(r, 1.5f), wo, kSamples).x, 1.0f + 0.01f);
      EXPECT_LE(albedo(plastic(r, Vec3(1.0f)), wo, kSamples).x, 1.0f + 0.01f);
      EXPECT_LE(albedo(anisotropic(conductor(r, false), 0.8f), wo, kSamples).x, 1.0f + 1e-4f);
      EXPECT_LE(albedo(anisotropic(glass(r, 1.5f), 0.8f), wo, kSamples).x, 1.0f + 0.01f);
      EXPECT_LE(albedo(coated(white, 1.0f, r), wo, kSamples).x, 1.0f + 1e-3f);
      EXPECT_LE(albedo(coated(conductor(0.0f, false), 1.0f, r), wo, kSamples).x, 1.0f + 1e-3f);
      EXPECT_LE(albedo(sheened(white, Vec3(1.0f), r), wo, kSamples).x, 1.0f + 2e-3f);
      EXPECT_LE(albedo(sheened(conductor(0.0f, false), Vec3(1.0f), r * 0.1f), wo, kSamples).x,
                1.0f + 2e-3f);
    }
  }
}

// OpenPBR's anisotropy: the tangent's alpha grows and the bitangent's shrinks, (1 - a) times it,
// keeping the mean of their squares r^4; none is plain GGX of alpha r^2.
TEST(Bsdf, AnisotropySplitsAlphaAsOpenPbr) {
  Material m = conductor(0.6f, false);
  const GgxAlpha plain = pointAlpha(m, m.roughness);
  EXPECT_EQ(plain.x, 0.36f);
  EXPECT_EQ(plain.y, 0.36f);
  m.anisotropy = 0.7f;
  const GgxAlpha split = pointAlpha(m, m.roughness);
  EXPECT_NEAR(split.y / split.x, 0.3f, 1e-6f);
  EXPECT_NEAR(split.x * split.x + split.y * split.y, 2.0f * 0.36f * 0.36f, 1e-6f);
  // Full anisotropy keeps a lobe across the tangent; no roughness stays a mirror.
  m.anisotropy = 1.0f;
  EXPECT_EQ(pointAlpha(m, m.roughness).y, kSmoothAlpha);
  EXPECT_FALSE(isSmooth(m));
  m.roughness = 0.0f;
  EXPECT_TRUE(isSmooth(m));
  EXPECT_FALSE(hasSmoothLobe(m));
}

// Seen from above, an anisotropic conductor reflects more towards a direction tilted along its
// tangent than across it (its highlight stretches along the tangent); the tangent turns the lobe
// with it, and only its part in the surface's plane counts (+y as +y tilted up).
TEST(Bsdf, AnisotropicLobeFollowsTheTangent) {
  const Material m = anisotropic(conductor(0.4f, false), 0.8f);
  const Vec3 tangent(0.0f, 1.0f, 0.0f);
  const Bsdf b = untexturedBsdf(m, kUp, kUp, kUp, tangent);
  const float tilt = 0.35f;
  const Vec3 alongTangent(0.0f, std::sin(tilt), std::cos(tilt));
  const Vec3 acrossTangent(std::sin(tilt), 0.0f, std::cos(tilt));
  float pdf;
  const float along = evalBsdf(b, alongTangent, &pdf).x;
  const float across = evalBsdf(b, acrossTangent, &pdf).x;
  EXPECT_GT(along, 5.0f * across);
  const Material plain = conductor(0.4f, false);
  const Bsdf isotropic = untexturedBsdf(plain, kUp, kUp, kUp, tangent);
  EXPECT_FLOAT_EQ(evalBsdf(isotropic, alongTangent, &pdf).x,
                  evalBsdf(isotropic, acrossTangent, &pdf).x);

  // With tangent +y the local frame is (y, -x, z): the same as no tangent (tangent +x) with
  // every direction turned so.
  const auto turn = [](const Vec3& v) { return Vec3(v.y, -v.x, v.z); };
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (int i = 0; i < 200; ++i) {
    const Vec3 wo = direction(uniform(rng), 2.0f * kPi * uniform(rng));
    const Vec3 wi = direction(uniform(rng), 2.0f * kPi * uniform(rng));
    float pdfTangent, pdfTurned, pdfTilted;
    const float f = evalBsdf(untexturedBsdf(m, wo, kUp, kUp, tangent), wi, &pdfTangent).x;
    const float turned = evalBsdf(untexturedBsdf(m, turn(wo), kUp, kUp), turn(wi), &pdfTurned).x;
    const float fromTilted =
        evalBsdf(untexturedBsdf(m, wo, kUp, kUp, Vec3(0.0f, 1.0f, 3.0f)), wi, &pdfTilted).x;
    ASSERT_NEAR(f, turned, 1e-4f * f + 1e-7f);
    ASSERT_NEAR(pdfTangent, pdfTurned, 1e-4f * pdfTangent + 1e-7f);
    ASSERT_NEAR(f, fromTilted, 1e-4f * f + 1e-7f);
  }
}

// Rough glass of index 1 is prepared as smooth glass: its facets would bend nothing, and the
// microfacet lobe has no half vector for the straight path. Any other index stays rough.
TEST(Bsdf, RoughGlassOfIndexOneIsPreparedSmooth) {
  Material clear = glass(0.5f, 1.0f);
  prepareMaterial(&clear);
  EXPECT_EQ(clear.roughness, 0.0f);
  EXPECT_FALSE(hasSmoothLobe(clear));
  const Vec3 wo = direction(0.6f, 0.7f);
  BsdfSample s;
  ASSERT_TRUE(sampleBsdf(untexturedBsdf(clear, wo, kUp, kUp), 0.5f, 0.5f, 0.5f, &s));
  EXPECT_NEAR(s.wi.x, -wo.x, 1e-6f);
  EXPECT_NEAR(s.wi.z, -wo.z, 1e-6f);
  EXPECT_NEAR(s.weight.x, 1.0f, 1e-6f);
  Material near = glass(0.5f, 1.01f);
  prepareMaterial(&near);
  EXPECT_EQ(near.roughness, 0.5f);
}

// A white rough plastic's albedo against Mitsuba 3.9.1's roughplastic (GGX, int_ior 1.5,
// nonlinear false), the mean weight of 20,000 samples of its sample() at wo = (cos, phi 0.7).
TEST(Bsdf, PlasticAlbedoMatchesMitsuba) {
  const struct {
    float roughness, cosTheta, mitsuba;
  } references[] = {
      {0.5f, 0.95f, 0.7400f}, {0.5f, 0.2f, 0.6985f}, {1.0f, 0.95f, 0.3312f}, {1.0f, 0.2f, 0.1959f}};
  for (const auto& r : references)
    EXPECT_NEAR(albedo(plastic(r.roughness, Vec3(1.0f)), direction(r.cosTheta, 0.7f), 200000).x,
                r.mitsuba, 0.01f * r.mitsuba)
        << "roughness " << r.roughness << ", cos " << r.cosTheta;
}

// The smooth coat's internal reflectance is the hemispherical average of the Fresnel reflectance
// from inside; for ior 1.5 the literature value is 0.5963 (Egan and Hilgeman's fit, which
// Mitsuba's fresnel_diffuse_reflectance uses, gives 0.5968).
TEST(Bsdf, PlasticInternalReflectance) {
  EXPECT_NEAR(plastic(0.0f, Vec3(0.5f)).plasticInternalReflectance, 0.5963f, 0.002f);
  // A rough coat reflects less of the light inside back down than a smooth one: masking.
  const Material rough = plastic(0.5f, Vec3(0.5f));
  EXPECT_LT(rough.plasticInternalReflectance, 0.5963f);
  EXPECT_GT(rough.plasticInternalReflectance, 0.4f);
  // At normal incidence a rough coat transmits about what a smooth one does (1 - 0.04).
  EXPECT_NEAR(plastic(0.1f, Vec3(0.5f)).plasticTransmittance[kPlasticTableSize - 1], 0.96f, 0.01f);
}

TEST(Bsdf, SmoothLobesAndLobeChoice) {
  EXPECT_TRUE(hasSmoothLobe(diffuse()));
  EXPECT_FALSE(hasSmoothLobe(conductor(0.0f, true)));
  EXPECT_TRUE(hasSmoothLobe(conductor(0.1f, true)));
  EXPECT_FALSE(hasSmoothLobe(glass(0.0f, 1.5f)));
  EXPECT_TRUE(hasSmoothLobe(glass(0.3f, 1.5f)));
  EXPECT_TRUE(hasSmoothLobe(plastic(0.0f, Vec3(0.5f))));
  EXPECT_FALSE(usesLobeChoice(glass(0.0f, 1.5f)));
  EXPECT_TRUE(usesLobeChoice(glass(0.3f, 1.5f)));
  EXPECT_TRUE(usesLobeChoice(plastic(0.0f, Vec3(0.5f))));
  EXPECT_FALSE(usesLobeChoice(conductor(0.5f, false)));
  // A translucent sheet chooses between its two sides, and is no longer bare diffuse.
  const Material sheet = translucent(Vec3(0.4f), Vec3(0.3f));
  EXPECT_TRUE(usesLobeChoice(sheet) && transmits(sheet) && hasSmoothLobe(sheet));
  EXPECT_FALSE(isBareDiffuse(sheet) || boundsAnInside(sheet));
  EXPECT_FALSE(usesLobeChoice(diffuse()) || transmits(diffuse()));
}

}  // namespace
}  // namespace candela
