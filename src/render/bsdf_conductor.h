// Conductors: GGX microfacet reflection (render/microfacet.h) with the exact conductor Fresnel of
// a named metal, or a plain reflectance `color` without Fresnel falloff (Mitsuba 3's conductor
// with material "none" and specular_reflectance). Below kSmoothAlpha a perfect mirror. Local
// shading frame of render/bsdf.h, wo.z > 0 expected.
#pragma once

#include "render/bsdf_sample.h"
#include "render/fresnel.h"
#include "render/material.h"
#include "render/microfacet.h"

namespace candela {

CANDELA_HDI Vec3 conductorFresnel(const Material& m, const Vec3& color, float cosThetaI) {
  return m.metal ? color * fresnelConductor(cosThetaI, m.metalEta, m.metalK) : color;
}

// f |cos(wi)| and the pdf of sampling wi, together (they share D and G1(wo)).
CANDELA_HDI Vec3 conductorEvalPdf(const Material& m, const Vec3& color, GgxAlpha alpha,
                                  const Vec3& wo, const Vec3& wi, float* pdf) {
  *pdf = 0.0f;
  if (alpha.smooth() || wo.z <= 0.0f || wi.z <= 0.0f) return Vec3(0.0f);
  const Vec3 h = normalize(wo + wi);
  const float d = ggxD(h, alpha), g1o = ggxG1(wo, h, alpha);
  *pdf = g1o * d / (4.0f * wo.z);
  const float dg = d * (g1o * ggxG1(wi, h, alpha));
  return conductorFresnel(m, color, dot(wo, h)) * (dg / (4.0f * wo.z));
}

CANDELA_HDI bool conductorSample(const Material& m, const Vec3& color, GgxAlpha alpha,
                                 const Vec3& wo, float u1, float u2, BsdfSample* s) {
  if (wo.z <= 0.0f) return false;
  if (alpha.smooth()) {
    s->wi = Vec3(-wo.x, -wo.y, wo.z);
    s->weight = conductorFresnel(m, color, wo.z);
    s->pdf = 0.0f;
    s->delta = true;
    return true;
  }
  const Vec3 h = sampleGgxVisible(wo, alpha, u1, u2);
  s->wi = reflect(wo, h);
  if (s->wi.z <= 0.0f) return false;
  s->pdf = ggxG1(wo, h, alpha) * ggxD(h, alpha) / (4.0f * wo.z);
  // f cos / pdf = F D G1(wo) G1(wi) / (4 wo.z) / (G1(wo) D / (4 wo.z)).
  s->weight = conductorFresnel(m, color, dot(wo, h)) * ggxG1(s->wi, h, alpha);
  s->delta = false;
  return s->pdf > 0.0f;
}

}  // namespace candela
