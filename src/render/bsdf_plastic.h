// Plastic: a diffuse base of colour `color` under a dielectric coating of index `ior`, smooth
// (a mirror-reflecting coat) or rough (a GGX coat), as Mitsuba 3's plastic and roughplastic with
// nonlinear = false. Light that enters the coat, scatters diffusely and leaves again is weighted
// by the coat's transmittance on both ways, 1 / eta^2 for the change of solid angle, and
// 1 / (1 - R_int) for its repeated internal reflections (render/material_prepare.h computes R_int
// and the rough coat's transmittance table, a table per roughness level where a texture gives
// the roughness). Local shading frame of render/bsdf.h, wo.z > 0.
#pragma once

#include "core/sampling.h"
#include "render/bsdf_sample.h"
#include "render/fresnel.h"
#include "render/material.h"
#include "render/microfacet.h"

namespace candela {

// The coat at one point: its transmittance by cos(theta) (a table of kPlasticTableSize, blended
// with the row after it by `blend` where the roughness is textured) and its internal
// reflectance.
struct PlasticCoat {
  const float* transmittance = nullptr;
  float blend = 0.0f;
  float internalReflectance = 0.0f;
};

// The roughness of level `level` of a textured plastic's coat table: from the smoothest rough
// surface to 1, denser at the smooth end, where a grazing ray's transmittance changes fastest.
CANDELA_HDI float plasticCoatLevelRoughness(uint32_t level) {
  const float lowest = smoothestRoughRoughness();
  const float t = float(level) / float(kPlasticCoatLevels - 1);
  return lowest + (1.0f - lowest) * t * t;
}

// The row of a coat table (kPlasticCoatLevels rows of kPlasticCoatRow, from
// plasticCoatLevelRoughness) that a coat of roughness `roughness` reads, blended by *blend with
// the row after it: the two levels around it.
CANDELA_HDI const float* coatTableRow(const float* table, float roughness, float* blend) {
  const float lowest = smoothestRoughRoughness();
  const float x = sqrtf((minf(maxf(roughness, lowest), 1.0f) - lowest) / (1.0f - lowest)) *
                  float(kPlasticCoatLevels - 1);
  const uint32_t level = x < float(kPlasticCoatLevels - 2) ? uint32_t(x) : kPlasticCoatLevels - 2;
  *blend = x - float(level);
  return table + level * kPlasticCoatRow;
}

// A coat's transmittance at cos(theta) from its table `row` (of kPlasticTableSize), blended by
// `blend` with the row after it (coatTableRow; 0: the row alone).
CANDELA_HDI float coatTableAt(const float* row, float blend, float cosTheta) {
  return levelTableAt(row, kPlasticCoatRow, blend, cosTheta);
}

// m's coat at a point of roughness `roughness` (render/surface_color.h); coatTables is
// SceneView::plasticCoats, which a textured roughness reads between its two nearest levels.
CANDELA_HDI PlasticCoat plasticCoatAt(const Material& m, const float* coatTables, float roughness) {
  PlasticCoat coat;
  if (m.plasticCoatTable < 0) {
    coat.transmittance = m.plasticTransmittance;
    coat.internalReflectance = m.plasticInternalReflectance;
    return coat;
  }
  coat.transmittance = coatTableRow(coatTables + m.plasticCoatTable, roughness, &coat.blend);
  const float* internal = coat.transmittance + kPlasticTableSize;
  coat.internalReflectance =
      (1.0f - coat.blend) * internal[0] + coat.blend * internal[kPlasticCoatRow];
  return coat;
}

// The coat's transmittance at cos(theta): 1 - F for a smooth coat; for a rough one the table
// of what its BTDF transmits (masking takes some of it, so it is less than 1 - reflectance).
CANDELA_HDI float plasticTransmittance(const Material& m, const PlasticCoat& coat, float cosTheta) {
  if (isSmooth(m)) return 1.0f - fresnelDielectric(cosTheta, m.ior);
  return coatTableAt(coat.transmittance, coat.blend, cosTheta);
}

// Probability of sampling the coat's reflection rather than the base (Mitsuba's choice: the
// coat's reflectance against the base's mean albedo).
CANDELA_HDI float plasticCoatProbability(const Vec3& color, float transmittanceO) {
  const float coatWeight = 1.0f / (1.0f + (color.x + color.y + color.z) * (1.0f / 3.0f));
  const float coat = (1.0f - transmittanceO) * coatWeight;
  const float base = transmittanceO * (1.0f - coatWeight);
  return coat + base > 0.0f ? coat / (coat + base) : 0.0f;
}

// plasticEvalPdf given wo's transmittance `to` and the coat's sampling probability.
CANDELA_HDI Vec3 plasticEvalPdfAt(const Material& m, const PlasticCoat& coat, GgxAlpha alpha,
                                  const Vec3& color, const Vec3& wo, const Vec3& wi, float to,
                                  float coatProbability, float* pdf) {
  *pdf = 0.0f;
  if (wo.z <= 0.0f || wi.z <= 0.0f) return Vec3(0.0f);
  const float ti = plasticTransmittance(m, coat, wi.z);
  const Vec3 base =
      color * (kInvPi * wi.z * to * ti / (m.ior * m.ior * (1.0f - coat.internalReflectance)));
  *pdf = (1.0f - coatProbability) * cosineHemispherePdf(wi.z);
  if (alpha.smooth()) return base;
  const Vec3 h = normalize(wo + wi);
  const float d = ggxD(h, alpha), g1o = ggxG1(wo, h, alpha);
  *pdf += coatProbability * g1o * d / (4.0f * wo.z);
  const float reflected =
      fresnelDielectric(dot(wo, h), m.ior) * d * (g1o * ggxG1(wi, h, alpha)) / (4.0f * wo.z);
  return base + Vec3(reflected);
}

// The smooth part (base, and a rough coat's reflection): f |cos(wi)| and its pdf.
CANDELA_HDI Vec3 plasticEvalPdf(const Material& m, const PlasticCoat& coat, GgxAlpha alpha,
                                const Vec3& color, const Vec3& wo, const Vec3& wi, float* pdf) {
  const float to = wo.z > 0.0f ? plasticTransmittance(m, coat, wo.z) : 0.0f;
  return plasticEvalPdfAt(m, coat, alpha, color, wo, wi, to, plasticCoatProbability(color, to),
                          pdf);
}

CANDELA_HDI bool plasticSample(const Material& m, const PlasticCoat& coat, GgxAlpha alpha,
                               const Vec3& color, const Vec3& wo, float uc, float u1, float u2,
                               BsdfSample* s) {
  if (wo.z <= 0.0f) return false;
  const float to = plasticTransmittance(m, coat, wo.z);
  const float coatProbability = plasticCoatProbability(color, to);
  if (uc < coatProbability) {
    if (alpha.smooth()) {
      s->wi = Vec3(-wo.x, -wo.y, wo.z);
      s->weight = Vec3(fresnelDielectric(wo.z, m.ior) / coatProbability);
      s->pdf = 0.0f;
      s->delta = true;
      return true;
    }
    s->wi = reflect(wo, sampleGgxVisible(wo, alpha, u1, u2));
  } else {
    s->wi = sampleCosineHemisphere(u1, u2);
  }
  const Vec3 f = plasticEvalPdfAt(m, coat, alpha, color, wo, s->wi, to, coatProbability, &s->pdf);
  if (!(s->pdf > 0.0f)) return false;
  s->weight = f / s->pdf;
  s->delta = false;
  return true;
}

}  // namespace candela
