// Trigonometry by polynomials where sampling and lookups need no more than float accuracy and
// a library call (with its range reduction and special cases) costs more than the work.
#pragma once

#include <cmath>

#include "core/device.h"

namespace candela {

// sin(x) and cos(x) for |x| <= pi/4, from their Taylor series to x^9 and x^8; the first omitted
// terms are below 2e-9 there, so the results are within a few float ulps of the exact values.
// The host's sincosf is a library call with range reduction that sampling never needs: the
// concentric disk map's angle is already in this range.
CANDELA_HDI void sinCosQuarterPi(float x, float* s, float* c) {
  const float x2 = x * x;
  *s = x * (1.0f + x2 * (-1.0f / 6.0f +
                         x2 * (1.0f / 120.0f + x2 * (-1.0f / 5040.0f + x2 * (1.0f / 362880.0f)))));
  *c = 1.0f + x2 * (-0.5f + x2 * (1.0f / 24.0f + x2 * (-1.0f / 720.0f + x2 * (1.0f / 40320.0f))));
}

// atan2(y, x) for finite arguments, within 3.5e-7 (1.5 ulp of pi) of the exact angle;
// 0 for (0, 0). atan on [0, 1] is a minimax fit of x P(x^2), P of degree 7; the octant folds
// the rest onto it. The environment map's lookup calls it twice per ray that leaves the scene,
// where libm's atan2f cost a twentieth of the render.
CANDELA_HDI float atan2Approx(float y, float x) {
  const float ax = fabsf(x), ay = fabsf(y);
  const float hi = ax > ay ? ax : ay, lo = ax > ay ? ay : ax;
  const float a = hi > 0.0f ? lo / hi : 0.0f;
  const float z = a * a;
  float r = -0.004054622259f;
  r = r * z + 0.021863156930f;
  r = r * z - 0.055912613869f;
  r = r * z + 0.096422180533f;
  r = r * z - 0.139086380601f;
  r = r * z + 0.199465677142f;
  r = r * z - 0.333298623562f;
  r = r * z + 0.999999344349f;
  r *= a;
  if (ay > ax) r = 1.57079632679f - r;
  if (x < 0.0f) r = 3.14159265359f - r;
  return copysignf(r, y);
}

}  // namespace candela
