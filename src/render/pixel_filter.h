// The pixel filter: how a pixel's samples spread about its centre, and so how much each point of
// the image plane counts towards the pixel.
//
// Filters are sampled, not splatted (pbrt-v4's choice): each sample of pixel p lands at p's centre
// plus an offset drawn with density proportional to the filter, and the pixel is the plain mean of
// its samples, as with the box. A pixel then depends on its own samples alone, so renders split
// into tiles, sample ranges or machines merge exactly as before, and a filter costs nothing.
// Each filter is separable, f(x) f(y), and each axis's offset comes from its own number by the
// inverse of the filter's distribution, which keeps the sampler's stratification.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/device.h"
#include "core/erf_inverse.h"

namespace candela {

enum class FilterType : uint32_t {
  Box = 0,       // uniform over the pixel
  Tent = 1,      // 1 - |x| / radius within radius pixels of the centre
  Gaussian = 2,  // exp(-x^2 / (2 stddev^2)), cut off at 4 stddev (Mitsuba 3's window)
};

// The filter's name and its width's, as the scene format spells them (the box has no width).
constexpr const char* filterName(FilterType type) {
  return type == FilterType::Box ? "box" : type == FilterType::Tent ? "tent" : "gaussian";
}
constexpr const char* filterWidthName(FilterType type) {
  return type == FilterType::Box ? nullptr : type == FilterType::Tent ? "radius" : "stddev";
}

struct PixelFilter {
  FilterType type = FilterType::Box;
  float width = 0.5f;  // the tent's radius, the Gaussian's standard deviation, in pixels
};

// The Gaussian is cut off where Mitsuba 3 cuts it, 4 standard deviations from the centre, and
// erf(4 / sqrt 2) of its mass lies within.
constexpr float kGaussianCutoff = 4.0f;
constexpr float kErfOfGaussianCutoff = 0.999936657f;

// How far from the pixel's centre the filter reaches, in pixels.
CANDELA_HDI float filterRadius(const PixelFilter& f) {
  return f.type == FilterType::Box    ? 0.5f
         : f.type == FilterType::Tent ? f.width
                                      : kGaussianCutoff * f.width;
}

// A sample's place along one axis of its pixel, in pixels from the pixel's low edge (its centre
// at 0.5), for u uniform in [0, 1): the inverse of the filter's cumulative distribution at u. The
// box's is u itself, so its samples stay where they always were.
CANDELA_HDI float sampleFilter(const PixelFilter& f, float u) {
  switch (f.type) {
    case FilterType::Tent:
      return 0.5f + (u < 0.5f ? f.width * (sqrtf(2.0f * u) - 1.0f)
                              : f.width * (1.0f - sqrtf(2.0f - 2.0f * u)));
    case FilterType::Gaussian:
      return 0.5f + f.width * 1.41421356f * erfInverse((2.0f * u - 1.0f) * kErfOfGaussianCutoff);
    default:
      return u;
  }
}

}  // namespace candela
