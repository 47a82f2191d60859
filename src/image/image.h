// ImageRGB: a linear-radiance float image, row-major from the top-left pixel, RGB interleaved.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace candela {

struct ImageRGB {
  uint32_t width = 0, height = 0;
  std::vector<float> pixels;  // 3 * width * height

  ImageRGB() = default;
  ImageRGB(uint32_t w, uint32_t h) : width(w), height(h), pixels(size_t(3) * w * h, 0.0f) {}

  Vec3 at(uint32_t x, uint32_t y) const {
    const size_t i = 3 * (size_t(y) * width + x);
    return {pixels[i], pixels[i + 1], pixels[i + 2]};
  }
  void set(uint32_t x, uint32_t y, const Vec3& c) {
    const size_t i = 3 * (size_t(y) * width + x);
    pixels[i] = c.x;
    pixels[i + 1] = c.y;
    pixels[i + 2] = c.z;
  }
};

// ImageRgba: an 8- or 16-bit image as decoded from PNG or JPEG (16 bits from PNG only), expanded
// to RGBA (alpha at its largest value where the file has none), row-major from the top-left pixel.
struct ImageRgba {
  uint32_t width = 0, height = 0;
  uint32_t channels = 0;           // in the file: 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA
  uint32_t bits = 8;               // per channel: 8 or 16
  std::vector<uint8_t> pixels8;    // 4 * width * height for 8 bits, else empty
  std::vector<uint16_t> pixels16;  // 4 * width * height for 16 bits, else empty
};

}  // namespace candela
