// Warping of uniform numbers in [0,1)^2 to directions and points, with their densities.
// Directions are in a local frame whose +z is the normal (see core/frame.h).
#pragma once

#include <cmath>

#include "core/constants.h"
#include "core/trig.h"
#include "core/vec3.h"

namespace candela {

// Concentric (Shirley–Chiu) map of the unit square onto the unit disk: low distortion.
CANDELA_HDI void sampleUniformDisk(float u1, float u2, float* x, float* y) {
  const float a = 2.0f * u1 - 1.0f, b = 2.0f * u2 - 1.0f;
  if (a == 0.0f && b == 0.0f) {
    *x = *y = 0.0f;
    return;
  }
  // The angle is pi/4 (b/a) in the first case and pi/2 - pi/4 (a/b) in the second, where
  // cos and sin trade places; either way the polynomial's argument is within [-pi/4, pi/4].
  float s, c;
  if (fabsf(a) > fabsf(b)) {
    sinCosQuarterPi((kPi / 4.0f) * (b / a), &s, &c);
    *x = a * c;
    *y = a * s;
  } else {
    sinCosQuarterPi((kPi / 4.0f) * (a / b), &s, &c);
    *x = b * s;
    *y = b * c;
  }
}

// Cosine-weighted hemisphere around +z; pdf = cos(theta) / pi.
CANDELA_HDI Vec3 sampleCosineHemisphere(float u1, float u2) {
  float x, y;
  sampleUniformDisk(u1, u2, &x, &y);
  const float z = sqrtf(maxf(0.0f, 1.0f - x * x - y * y));
  return {x, y, z};
}
CANDELA_HDI float cosineHemispherePdf(float cosTheta) { return cosTheta > 0.0f ? cosTheta * kInvPi : 0.0f; }

// Barycentrics (b[0], b[1], b[2]) of a point uniform over a triangle's area.
CANDELA_HDI void sampleUniformTriangle(float u1, float u2, float b[3]) {
  const float su = sqrtf(u1);
  b[1] = 1.0f - su;
  b[2] = u2 * su;
  b[0] = 1.0f - b[1] - b[2];
}

// Uniform direction within the cone around +z of half-angle theta_max, given 1 - cos(theta_max)
// (which callers compute without cancellation for narrow cones); pdf = 1 / (2 pi (1 - cos)).
CANDELA_HDI Vec3 sampleUniformCone(float u1, float u2, float oneMinusCosThetaMax) {
  const float cosTheta = 1.0f - u1 * oneMinusCosThetaMax;
  const float sinTheta = sqrtf(maxf(0.0f, 1.0f - cosTheta * cosTheta));
  const float phi = 2.0f * kPi * u2;
  return {cosf(phi) * sinTheta, sinf(phi) * sinTheta, cosTheta};
}
CANDELA_HDI float uniformConePdf(float oneMinusCosThetaMax) {
  return 1.0f / (2.0f * kPi * oneMinusCosThetaMax);
}

// A number in [0, 1) whose density is proportional to (1 - x) a + x b (a, b >= 0), by the
// inversion pbrt-v4's SampleLinear uses, stable where a and b are nearly equal; u itself where
// both are 0 (a line of no mass, which bilinearPdf gives density 0).
CANDELA_HDI float sampleLinear(float u, float a, float b) {
  if (!(a + b > 0.0f)) return u;
  if (u == 0.0f && a == 0.0f) return 0.0f;
  const float x = u * (a + b) / (a + sqrtf((1.0f - u) * a * a + u * b * b));
  return x < 0.99999994f ? x : 0.99999994f;
}

// A point (x, y) in [0, 1)^2 whose density is proportional to the bilinear interpolation of the
// corner weights w[0] at (0, 0), w[1] at (1, 0), w[2] at (0, 1) and w[3] at (1, 1), all >= 0:
// y from its marginal, then x given y.
CANDELA_HDI void sampleBilinear(float u1, float u2, const float w[4], float* x, float* y) {
  *y = sampleLinear(u2, w[0] + w[1], w[2] + w[3]);
  *x = sampleLinear(u1, (1.0f - *y) * w[0] + *y * w[2], (1.0f - *y) * w[1] + *y * w[3]);
}

// The density sampleBilinear gives point (x, y); 0 where all the weights are.
CANDELA_HDI float bilinearPdf(float x, float y, const float w[4]) {
  const float sum = w[0] + w[1] + w[2] + w[3];
  if (!(sum > 0.0f)) return 0.0f;
  const float value =
      (1.0f - y) * ((1.0f - x) * w[0] + x * w[1]) + y * ((1.0f - x) * w[2] + x * w[3]);
  return 4.0f * value / sum;
}

// Power heuristic (beta = 2) weight of a strategy with density `pdfA` against one with `pdfB`.
CANDELA_HDI float powerHeuristic(float pdfA, float pdfB) {
  const float a = pdfA * pdfA, b = pdfB * pdfB;
  return a / (a + b);
}

}  // namespace candela
