// Glass: a dielectric interface, smooth (Fresnel-weighted choice of mirror reflection and Snell
// refraction) or rough (GGX microfacets, Walter et al. 2007, in pbrt-v4's DielectricBxDF form
// with Smith's separable masking). Local shading frame of render/bsdf.h: +z on wo's side, wo.z > 0
// expected, eta = eta_t / eta_i for light leaving towards wo's side from the other. Transmitted
// radiance is scaled by 1 / eta^2 and tinted by the material's colour.
#pragma once

#include <cmath>

#include "render/bsdf_sample.h"
#include "render/fresnel.h"
#include "render/material.h"
#include "render/microfacet.h"

namespace candela {

// The microfacet normal that takes wo to wi (reflection when both lie above, else refraction),
// turned up; false for a pair no visible facet connects.
CANDELA_HDI bool dielectricHalfVector(const Vec3& wo, const Vec3& wi, float eta, Vec3* wm,
                                      float* etap) {
  const bool reflection = wi.z > 0.0f;
  *etap = reflection ? 1.0f : eta;
  const Vec3 sum = wi * *etap + wo;
  if (wi.z == 0.0f || wo.z <= 0.0f || lengthSquared(sum) == 0.0f) return false;
  *wm = faceForward(normalize(sum), Vec3(0.0f, 0.0f, 1.0f));
  // Facets seen from behind by either direction connect nothing.
  return dot(*wm, wi) * wi.z >= 0.0f && dot(*wm, wo) * wo.z >= 0.0f;
}

// f |cos(wi)| and the pdf of sampling wi, together (they share the half vector).
CANDELA_HDI Vec3 dielectricEvalPdf(const Vec3& color, GgxAlpha alpha, float eta, const Vec3& wo,
                                   const Vec3& wi, float* pdf) {
  *pdf = 0.0f;
  Vec3 wm;
  float etap;
  if (alpha.smooth() || !dielectricHalfVector(wo, wi, eta, &wm, &etap)) return Vec3(0.0f);
  const float F = fresnelDielectric(dot(wo, wm), eta);
  const float d = ggxD(wm, alpha), g1o = ggxG1(wo, wm, alpha);
  const float visible = ggxVisiblePdf(wo, wm, g1o, d);
  const float dg = d * (g1o * ggxG1(wi, wm, alpha));
  if (wi.z > 0.0f) {
    *pdf = visible / (4.0f * fabsf(dot(wo, wm))) * F;
    return Vec3(dg * F / (4.0f * wo.z));
  }
  const float denom = dot(wi, wm) + dot(wo, wm) / etap;
  if (denom == 0.0f) return Vec3(0.0f);
  const float dwmDwi = fabsf(dot(wi, wm)) / (denom * denom);
  *pdf = visible * dwmDwi * (1.0f - F);
  // D G (1 - F) |wi.wm wo.wm| / (|wi.z wo.z| denom^2) |wi.z|, radiance scaled by 1 / eta^2.
  const float ft =
      dg * (1.0f - F) * fabsf(dot(wi, wm) * dot(wo, wm)) / (wo.z * denom * denom * etap * etap);
  return color * ft;
}

// Both lobes of smooth glass, for a path that follows each (render/path_branch.h): the refraction
// in *refraction, weight (1 - F) color / eta^2, and the mirror reflection in *reflection, weight
// F; what dielectricSample picks between. False where refraction is impossible (total internal
// reflection, F = 1) or wo lies below.
CANDELA_HDI bool smoothDielectricBothLobes(const Vec3& color, float eta, const Vec3& wo,
                                           BsdfSample* refraction, BsdfSample* reflection) {
  if (wo.z <= 0.0f || !refract(wo, Vec3(0.0f, 0.0f, 1.0f), eta, &refraction->wi)) return false;
  const float reflectance = fresnelDielectric(wo.z, eta);
  refraction->weight = color * ((1.0f - reflectance) / (eta * eta));
  refraction->pdf = 0.0f;
  refraction->delta = true;
  refraction->eta = eta;
  reflection->wi = Vec3(-wo.x, -wo.y, wo.z);
  reflection->weight = Vec3(reflectance);
  reflection->pdf = 0.0f;
  reflection->delta = true;
  reflection->eta = 1.0f;
  return true;
}

// uc picks reflection or refraction of a rough surface; a smooth one picks with u1.
CANDELA_HDI bool dielectricSample(const Vec3& color, GgxAlpha alpha, float eta, const Vec3& wo,
                                  float uc, float u1, float u2, BsdfSample* s) {
  if (wo.z <= 0.0f) return false;
  if (alpha.smooth()) {
    const float reflectance = fresnelDielectric(wo.z, eta);
    s->pdf = 0.0f;
    s->delta = true;
    if (u1 < reflectance) {
      s->wi = Vec3(-wo.x, -wo.y, wo.z);
      s->weight = Vec3(1.0f);  // F / (probability F)
      s->eta = 1.0f;
      return true;
    }
    // (1 - F) / (probability 1 - F), radiance scaled by (eta_i / eta_t)^2, tinted by color.
    if (!refract(wo, Vec3(0.0f, 0.0f, 1.0f), eta, &s->wi)) return false;  // F = 1 under TIR
    s->weight = color * (1.0f / (eta * eta));
    s->eta = eta;
    return true;
  }
  const Vec3 wm = sampleGgxVisible(wo, alpha, u1, u2);
  const float F = fresnelDielectric(dot(wo, wm), eta);
  if (uc < F) {
    s->wi = reflect(wo, wm);
    if (s->wi.z <= 0.0f) return false;
    s->eta = 1.0f;
  } else {
    if (!refract(wo, wm, eta, &s->wi) || s->wi.z >= 0.0f) return false;
    s->eta = eta;
  }
  const Vec3 f = dielectricEvalPdf(color, alpha, eta, wo, s->wi, &s->pdf);
  if (!(s->pdf > 0.0f)) return false;
  s->weight = f / s->pdf;
  s->delta = false;
  return true;
}

}  // namespace candela
