// Exact unpolarised Fresnel reflectance of a smooth dielectric interface, and the reflection and
// refraction directions. Directions point away from the surface; n is on the side of wi.
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

CANDELA_HDI Vec3 reflect(const Vec3& wo, const Vec3& n) { return -wo + n * (2.0f * dot(wo, n)); }

// Refraction of wo (on n's side) into the other medium; false on total internal reflection.
CANDELA_HDI bool refract(const Vec3& wo, const Vec3& n, float eta, Vec3* wt) {
  const float cosThetaI = dot(n, wo);
  const float sin2ThetaT = maxf(0.0f, 1.0f - cosThetaI * cosThetaI) / (eta * eta);
  if (sin2ThetaT >= 1.0f) return false;
  const float cosThetaT = sqrtf(1.0f - sin2ThetaT);
  *wt = -wo / eta + n * (cosThetaI / eta - cosThetaT);
  return true;
}

}  // namespace candela
