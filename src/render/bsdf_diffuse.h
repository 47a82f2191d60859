// Lambertian reflection, in the local shading frame of render/bsdf.h (+z the shading normal on
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

}  // namespace candela
