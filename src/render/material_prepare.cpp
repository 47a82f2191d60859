// Derived material values; see material_prepare.h.
#include "render/material_prepare.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <utility>
#include <vector>

#include "core/constants.h"
#include "render/bsdf_plastic.h"
#include "render/bsdf_sheen.h"
#include "render/fresnel.h"
#include "render/microfacet.h"

namespace candela {
namespace {

// The mean over the visible normals m of wo = (sqrt(1 - mu^2), 0, mu) of term(wo, m), by the
// midpoint rule on the square that sampleGgxVisible maps to them; `points` per axis.
template <class Term>
double overVisibleNormals(double mu, float alpha, int points, Term term) {
  mu = std::clamp(mu, 1e-6, 1.0);
  const Vec3 wo(float(std::sqrt(1.0 - mu * mu)), 0.0f, float(mu));
  double sum = 0.0;
  for (int j = 0; j < points; ++j)
    for (int i = 0; i < points; ++i) {
      const float u1 = (i + 0.5f) / points, u2 = (j + 0.5f) / points;
      sum += term(wo, sampleGgxVisible(wo, GgxAlpha::isotropic(alpha), u1, u2));
    }
  return sum / (double(points) * points);
}

// Light meeting the coat from inside (eta < 1) is totally reflected beyond the critical angle, a
// kink in the integrand that needs a finer rule.
int quadraturePoints(float eta) { return eta > 1.0f ? 64 : 128; }

}  // namespace

// Sampling visible normals, a reflection's weight is F(wo.m) G1(wi) (D and G1(wo) cancel).
double roughCoatReflectance(double mu, float eta, float alpha) {
  return overVisibleNormals(mu, alpha, quadraturePoints(eta), [&](const Vec3& wo, const Vec3& m) {
    const Vec3 wi = reflect(wo, m);
    return wi.z > 0.0f ? double(fresnelDielectric(dot(wo, m), eta) *
                                ggxG1(wi, m, GgxAlpha::isotropic(alpha)))
                       : 0.0;
  });
}

// Likewise a refraction's weight is (1 - F(wo.m)) G1(wt).
double roughCoatTransmittance(double mu, float eta, float alpha) {
  return overVisibleNormals(mu, alpha, quadraturePoints(eta), [&](const Vec3& wo, const Vec3& m) {
    Vec3 wt;
    if (!refract(wo, m, eta, &wt) || wt.z >= 0.0f) return 0.0;
    return double((1.0f - fresnelDielectric(dot(wo, m), eta)) *
                  ggxG1(wt, m, GgxAlpha::isotropic(alpha)));
  });
}

namespace {

struct RoughCoat {
  float transmittance[kPlasticTableSize];
  float internalReflectance;
};

// As Mitsuba 3's roughplastic: the table samples mu = i / (n - 1), and the internal reflectance
// is the mean of 2 mu R(mu) over the same points (slightly below the integral, kept so that the
// two renderers agree).
RoughCoat roughCoat(float eta, float alpha) {
  RoughCoat coat;
  double internal = 0.0;
  for (uint32_t i = 0; i < kPlasticTableSize; ++i) {
    const double mu = double(i) / (kPlasticTableSize - 1);
    coat.transmittance[i] = float(roughCoatTransmittance(mu, eta, alpha));
    internal += 2.0 * std::max(mu, 1e-6) * roughCoatReflectance(mu, 1.0f / eta, alpha);
  }
  coat.internalReflectance = float(internal / kPlasticTableSize);
  return coat;
}

// roughCoat, computed once per (eta, alpha): an MTL file of many glossy materials shares a few
// coatings, and a textured plastic's levels serve every textured plastic of its index.
RoughCoat sharedRoughCoat(float eta, float alpha) {
  static std::mutex mutex;
  static std::map<std::pair<float, float>, RoughCoat> coats;
  std::lock_guard<std::mutex> lock(mutex);
  auto found = coats.find({eta, alpha});
  if (found == coats.end())
    found = coats.emplace(std::make_pair(eta, alpha), roughCoat(eta, alpha)).first;
  return found->second;
}

// The sheen lobe's directional albedo at the table's cosines, and the normalized lobe's
// (render/bsdf_sheen.h), by the midpoint rule over cos(theta_i) = t^2 (dense near the horizon,
// where a smooth sheen's lobe lies) and the azimuth; mirror-symmetric in the azimuth, so half.
struct SheenTables {
  float albedo[kPlasticTableSize];
  float kept[kPlasticTableSize];
};

SheenTables sheenTables(float alpha) {
  constexpr int kT = 128, kPhi = 64;
  SheenTables tables;
  for (int pass = 0; pass < 2; ++pass)
    for (uint32_t k = 0; k < kPlasticTableSize; ++k) {
      const double mu = std::max(double(k) / (kPlasticTableSize - 1), 1e-4);
      const Vec3 wo(float(std::sqrt(1.0 - mu * mu)), 0.0f, float(mu));
      const float normO = pass == 0 ? 1.0f : std::max(1.0f, tables.albedo[k]);
      double sum = 0.0;
      for (int i = 0; i < kT; ++i) {
        const double t = (i + 0.5) / kT, cosI = t * t, sinI = std::sqrt(1.0 - cosI * cosI);
        const float normI =
            pass == 0 ? 1.0f : std::max(1.0f, cosineTableAt(tables.albedo, float(cosI)));
        double ring = 0.0;
        for (int j = 0; j < kPhi; ++j) {
          const double phi = kPiDouble * (j + 0.5) / kPhi;
          const Vec3 wi(float(sinI * std::cos(phi)), float(sinI * std::sin(phi)), float(cosI));
          ring += sheenLobeCos(alpha, wo, wi);
        }
        // d(cos) = 2 t dt; the azimuth's half circle counted twice.
        sum += ring * (kPiDouble / kPhi) * 2.0 * (2.0 * t / kT) / std::max(normI, normO);
      }
      (pass == 0 ? tables.albedo : tables.kept)[k] = float(sum);
    }
  return tables;
}

SheenTables sharedSheenTables(float alpha) {
  static std::mutex mutex;
  static std::map<float, SheenTables> tables;
  std::lock_guard<std::mutex> lock(mutex);
  auto found = tables.find(alpha);
  if (found == tables.end()) found = tables.emplace(alpha, sheenTables(alpha)).first;
  return found->second;
}

}  // namespace

void prepareMaterial(Material* m) {
  // Glass of index 1 bends no ray, whatever its facets: each refracts wo to -wo with F = 0, a
  // delta transmission that the microfacet lobe cannot hold (its half vector wo + wi vanishes,
  // so every path through it ended black). As pbrt-v4's DielectricBxDF, it is smooth glass.
  if (m->type == MaterialType::Glass && m->ior == 1.0f) {
    m->roughness = 0.0f;
    m->roughnessTexture = TextureRef();
  }
  const float coatAlpha = roughnessToAlpha(m->coatRoughness);
  if (m->coatWeight > 0.0f && coatAlpha >= kSmoothAlpha) {
    const RoughCoat coat = sharedRoughCoat(m->coatIor, coatAlpha);
    std::copy(coat.transmittance, coat.transmittance + kPlasticTableSize, m->coatTransmittance);
  }
  if (hasSheen(*m)) {
    const SheenTables sheen = sharedSheenTables(sheenAlpha(m->sheenRoughness));
    std::copy(sheen.albedo, sheen.albedo + kPlasticTableSize, m->sheenAlbedo);
    std::copy(sheen.kept, sheen.kept + kPlasticTableSize, m->sheenKept);
  }
  if (m->type != MaterialType::Plastic) return;
  const float alpha = roughnessToAlpha(m->roughness);
  const float eta = m->ior;
  if (alpha < kSmoothAlpha) {
    // The hemispherical average 2 int_0^1 mu F(mu) dmu of the reflectance from inside, where
    // light meets the coating from the denser side (index 1 / eta); midpoint rule.
    constexpr int kIntervals = 1024;
    double sum = 0.0;
    for (int i = 0; i < kIntervals; ++i) {
      const double mu = (i + 0.5) / kIntervals;
      sum += 2.0 * mu * fresnelDielectric(float(mu), 1.0f / eta);
    }
    m->plasticInternalReflectance = float(sum / kIntervals);
    return;
  }
  const RoughCoat coat = sharedRoughCoat(eta, alpha);
  std::copy(coat.transmittance, coat.transmittance + kPlasticTableSize, m->plasticTransmittance);
  m->plasticInternalReflectance = coat.internalReflectance;
}

std::vector<float> sheenLevelTables(uint32_t first, uint32_t last) {
  static std::mutex mutex;
  static std::vector<float> made(size_t(kSheenLevels) * kSheenRow);
  static bool isMade[kSheenLevels] = {};
  std::lock_guard<std::mutex> lock(mutex);
  last = std::min(last, kSheenLevels - 1);
  // The levels not made yet share the machine's cores.
  std::vector<uint32_t> missing;
  for (uint32_t level = first; level <= last; ++level)
    if (!isMade[level]) missing.push_back(level);
  tbb::parallel_for(size_t(0), missing.size(), [&](size_t i) {
    const SheenTables sheen = sheenTables(sheenAlpha(sheenLevelRoughness(missing[i])));
    float* row = made.data() + size_t(missing[i]) * kSheenRow;
    std::copy(sheen.albedo, sheen.albedo + kPlasticTableSize, row);
    std::copy(sheen.kept, sheen.kept + kPlasticTableSize, row + kPlasticTableSize);
  });
  for (const uint32_t level : missing) isMade[level] = true;
  std::vector<float> table(made.size(), 0.0f);
  for (uint32_t level = first; level <= last; ++level)
    std::copy_n(made.begin() + std::ptrdiff_t(level) * kSheenRow, kSheenRow,
                table.begin() + std::ptrdiff_t(level) * kSheenRow);
  return table;
}

std::vector<float> plasticCoatTable(float eta) {
  std::vector<float> table(kPlasticCoatLevels * kPlasticCoatRow);
  for (uint32_t level = 0; level < kPlasticCoatLevels; ++level) {
    const float roughness = plasticCoatLevelRoughness(level);
    const RoughCoat coat =
        sharedRoughCoat(eta, std::max(roughnessToAlpha(roughness), kSmoothAlpha));
    float* row = table.data() + level * kPlasticCoatRow;
    std::copy(coat.transmittance, coat.transmittance + kPlasticTableSize, row);
    row[kPlasticTableSize] = coat.internalReflectance;
  }
  return table;
}

}  // namespace candela
