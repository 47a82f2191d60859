// The inverse error function in single precision, the same arithmetic on the CPU and the GPU.
#pragma once

#include <cmath>

#include "core/device.h"

namespace candela {

// erf^-1(x) for x in (-1, 1): Giles' single-precision polynomials ("Approximating the erfinv
// function", GPU Computing Gems, 2011), within 3e-7 of the exact value, relatively (two float
// roundings; tests/test_pixel_filter.cpp). Not CUDA's erfinvf, which the CPU does not have.
CANDELA_HDI float erfInverse(float x) {
  float w = -logf((1.0f - x) * (1.0f + x)), p;
  if (w < 5.0f) {
    w -= 2.5f;
    p = 2.81022636e-08f;
    p = 3.43273939e-07f + p * w;
    p = -3.5233877e-06f + p * w;
    p = -4.39150654e-06f + p * w;
    p = 0.00021858087f + p * w;
    p = -0.00125372503f + p * w;
    p = -0.00417768164f + p * w;
    p = 0.246640727f + p * w;
    p = 1.50140941f + p * w;
  } else {
    w = sqrtf(w) - 3.0f;
    p = -0.000200214257f;
    p = 0.000100950558f + p * w;
    p = 0.00134934322f + p * w;
    p = -0.00367342844f + p * w;
    p = 0.00573950773f + p * w;
    p = -0.0076224613f + p * w;
    p = 0.00943887047f + p * w;
    p = 1.00167406f + p * w;
    p = 2.83297682f + p * w;
  }
  return p * x;
}

}  // namespace candela
