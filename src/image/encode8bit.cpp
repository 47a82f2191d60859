// encode8bit: linear radiance -> one 8-bit display value (exposure, tone map, gamma or sRGB curve).
#include <algorithm>
#include <cmath>

#include "image/image_io.h"

namespace candela {

namespace {

// The exact sRGB transfer function (IEC 61966-2-1), v in [0, 1].
double srgbCurve(double v) {
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

// The tone map of v > 0, in [0, 1]. At v = +inf the curves' ratios are NaN; their limit is 1.
double toneMapped(double v, ToneMap toneMap) {
  if (std::isinf(v)) return 1.0;
  switch (toneMap) {
    case ToneMap::Reinhard:
      return v / (1.0 + v);
    case ToneMap::Aces:
      return std::min(1.0, v * (2.51 * v + 0.03) / (v * (2.43 * v + 0.59) + 0.14));
    case ToneMap::Clamp:
      break;
  }
  return std::min(1.0, v);
}

}  // namespace

uint8_t encode8bit(float linear, const OutputDesc& output) {
  // Double precision keeps the rounding to 255 levels independent of float error in pow.
  double v = double(linear) * std::exp2(double(output.exposure));
  if (!(v > 0.0)) return 0;  // also maps NaN to black
  v = toneMapped(v, output.toneMap);
  v = output.curve == GammaCurve::Srgb ? srgbCurve(v) : std::pow(v, 1.0 / double(output.gamma));
  return uint8_t(std::lround(v * 255.0));
}

}  // namespace candela
