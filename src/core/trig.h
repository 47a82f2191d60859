// Sine and cosine on [-pi/4, pi/4] by polynomials: what sampling needs, without a library call.
#pragma once

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

}  // namespace candela
