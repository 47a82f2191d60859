// The Henyey-Greenstein phase function of a scattering medium (render/medium.h): how a medium
// scatters light by the angle between where it travelled and where it goes on, with one parameter
// g in (-1, 1), the mean cosine of that angle (g > 0 forward, as Mitsuba's and pbrt's `hg`).
#pragma once

#include <cmath>

#include "core/constants.h"
#include "core/device.h"
#include "core/frame.h"
#include "core/vec3.h"

namespace candela {

// Below this |g| the medium scatters uniformly: the inversion below divides by g.
constexpr float kIsotropicPhaseG = 1e-3f;

// The density of scattering into a direction at cosine `cosTheta` to the direction of travel,
// per unit solid angle (it integrates to 1 over the sphere).
CANDELA_HDI float henyeyGreenstein(float cosTheta, float g) {
  if (fabsf(g) < kIsotropicPhaseG) return kInv4Pi;  // as sampleHenyeyGreenstein draws it
  const float denominator = 1.0f + g * g - 2.0f * g * cosTheta;
  return kInv4Pi * (1.0f - g * g) / (denominator * sqrtf(maxf(denominator, 0.0f)));
}

// A direction scattered from travel direction `travel` (unit) by exactly the density above, by
// inverting its distribution of cos(theta) (pbrt-v4's SampleHenyeyGreenstein, written for the
// direction of travel); the sample's weight, density over pdf, is 1.
CANDELA_HDI Vec3 sampleHenyeyGreenstein(const Vec3& travel, float g, float u1, float u2) {
  float cosTheta;
  if (fabsf(g) < kIsotropicPhaseG) {
    cosTheta = 1.0f - 2.0f * u1;
  } else {
    const float s = (1.0f - g * g) / (1.0f + g - 2.0f * g * u1);
    cosTheta = (1.0f + g * g - s * s) / (2.0f * g);
  }
  cosTheta = minf(1.0f, maxf(-1.0f, cosTheta));
  const float sinTheta = sqrtf(maxf(0.0f, 1.0f - cosTheta * cosTheta));
  const float phi = 2.0f * kPi * u2;
  return Frame(travel).toWorld(Vec3(cosf(phi) * sinTheta, sinf(phi) * sinTheta, cosTheta));
}

}  // namespace candela
