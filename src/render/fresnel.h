// Exact unpolarised Fresnel reflectance of smooth dielectric and conductor interfaces, and the
// reflection and refraction directions. Directions point away from the surface; n is on the side
// of wi.
#pragma once

#include <cmath>

#include "core/dielectric_fresnel.h"
#include "core/vec3.h"

namespace candela {

// A conductor of complex relative index eta + i k, per colour channel ("Optics", K. D. Moeller,
// 1988, as in Mitsuba 3's fresnel_conductor); cosThetaI in [0, 1].
CANDELA_HDI float fresnelConductor(float cosThetaI, float eta, float k) {
  const float cos2 = cosThetaI * cosThetaI, sin2 = 1.0f - cos2, sin4 = sin2 * sin2;
  const float temp = eta * eta - k * k - sin2;
  const float a2pb2 = sqrtf(maxf(0.0f, temp * temp + 4.0f * k * k * eta * eta));
  const float a = sqrtf(maxf(0.0f, 0.5f * (a2pb2 + temp)));
  const float term1 = a2pb2 + cos2, term2 = 2.0f * cosThetaI * a;
  const float rs = (term1 - term2) / (term1 + term2);
  const float term3 = a2pb2 * cos2 + sin4, term4 = term2 * sin2;
  const float rp = rs * (term3 - term4) / (term3 + term4);
  return 0.5f * (rs + rp);
}

CANDELA_HDI Vec3 fresnelConductor(float cosThetaI, const Vec3& eta, const Vec3& k) {
  return {fresnelConductor(cosThetaI, eta.x, k.x), fresnelConductor(cosThetaI, eta.y, k.y),
          fresnelConductor(cosThetaI, eta.z, k.z)};
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
