// Exact unpolarised Fresnel reflectance of a smooth dielectric interface, and of a thin sheet of
// dielectric: core, because traversal's alpha test reads the sheet's (geometry/alpha_test.h) as
// the BSDFs read the interface's (render/fresnel.h).
#pragma once

#include <cmath>

#include "core/vec3.h"

namespace candela {

// cosThetaI >= 0 is measured on the incident side; eta = eta_transmitted / eta_incident.
CANDELA_HDI float fresnelDielectric(float cosThetaI, float eta) {
  const float sin2ThetaT = maxf(0.0f, 1.0f - cosThetaI * cosThetaI) / (eta * eta);
  if (sin2ThetaT >= 1.0f) return 1.0f;  // total internal reflection
  const float cosThetaT = sqrtf(1.0f - sin2ThetaT);
  const float rParallel = (eta * cosThetaI - cosThetaT) / (eta * cosThetaI + cosThetaT);
  const float rPerpendicular = (cosThetaI - eta * cosThetaT) / (cosThetaI + eta * cosThetaT);
  return 0.5f * (rParallel * rParallel + rPerpendicular * rPerpendicular);
}

// A thin sheet of relative index eta, both faces smooth and parallel: the light it reflects after
// any number of bounces between its faces, R + T R T + T R^3 T + ... = 2 R / (1 + R) with T = 1 - R
// (Mitsuba 3's thindielectric, pbrt-v4's ThinDielectricBxDF). It sends the rest straight on.
CANDELA_HDI float thinSheetReflectance(float cosThetaI, float eta) {
  const float r = fresnelDielectric(cosThetaI, eta);
  return r < 1.0f ? 2.0f * r / (1.0f + r) : 1.0f;
}

}  // namespace candela
