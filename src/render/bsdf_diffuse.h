// Lambertian reflection, and a translucent surface's Lambertian transmission beside it (pbrt-v4's
// DiffuseTransmissionBxDF), in the local shading frame of render/bsdf.h (+z the shading normal on
// wo's side). Functions return f |cos(wi)|, the pdf, or a sample's f |cos| / pdf.
#pragma once

#include "core/sampling.h"
#include "render/bsdf_sample.h"

namespace candela {

CANDELA_HDI Vec3 diffuseEval(const Vec3& color, const Vec3& wi) {
  return wi.z > 0.0f ? color * (wi.z * kInvPi) : Vec3(0.0f);
}

CANDELA_HDI bool diffuseSample(const Vec3& color, float u1, float u2, BsdfSample* s) {
  s->wi = sampleCosineHemisphere(u1, u2);
  s->pdf = cosineHemispherePdf(s->wi.z);
  s->weight = color;  // (albedo / pi) cos / (cos / pi)
  return s->pdf > 0.0f;
}

// The chance that a translucent surface samples its reflection rather than its transmission: by
// their largest channels, as pbrt-v4.
CANDELA_HDI float diffuseReflectionProbability(const Vec3& color, const Vec3& transmittance) {
  const float r = maxComponent(color), t = maxComponent(transmittance);
  return r + t > 0.0f ? r / (r + t) : 0.5f;
}

// Reflection of `color` into wo's hemisphere (wi.z > 0) and transmission of `transmittance` into
// the other (wi.z < 0).
CANDELA_HDI Vec3 translucentEvalPdf(const Vec3& color, const Vec3& transmittance, const Vec3& wi,
                                    float* pdf) {
  const float reflect = diffuseReflectionProbability(color, transmittance);
  const float cosTheta = fabsf(wi.z);
  *pdf = (wi.z > 0.0f ? reflect : 1.0f - reflect) * cosineHemispherePdf(cosTheta);
  return (wi.z > 0.0f ? color : transmittance) * (cosTheta * kInvPi);
}

CANDELA_HDI bool translucentSample(const Vec3& color, const Vec3& transmittance, float uc, float u1,
                                   float u2, BsdfSample* s) {
  const float reflect = diffuseReflectionProbability(color, transmittance);
  const bool reflects = uc < reflect;
  const float chance = reflects ? reflect : 1.0f - reflect;
  s->wi = sampleCosineHemisphere(u1, u2);
  if (!reflects) s->wi.z = -s->wi.z;
  s->pdf = chance * cosineHemispherePdf(fabsf(s->wi.z));
  s->weight = (reflects ? color : transmittance) / chance;
  s->delta = false;
  s->eta = 1.0f;
  return s->pdf > 0.0f;
}

}  // namespace candela
