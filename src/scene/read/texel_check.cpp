// Checking texels; see texel_check.h.
#include "scene/read/texel_check.h"

#include <cmath>
#include <cstddef>

#include "scene/scene_error.h"

namespace candela {
namespace {

// The first of a width x height image's texels, `at`(x, y), that `scale` carries beyond single
// precision, described; or "".
template <class At>
std::string firstBeyondFloat(uint32_t width, uint32_t height, const At& at, const Vec3& scale) {
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      const Vec3 t = at(x, y);
      if (!isFinite(t * scale))
        return "texel (" + std::to_string(x) + ", " + std::to_string(y) + "), " + formatVec3(t);
    }
  return "";
}

}  // namespace

std::string firstBadTexel(const ImageRGB& image) {
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const float v = image.at(x, y)[c];
        if (v >= 0.0f && std::isfinite(v)) continue;
        return "texel (" + std::to_string(x) + ", " + std::to_string(y) + ") is " +
               (std::isnan(v) ? "NaN" : (std::isinf(v) ? "infinite" : "negative"));
      }
  return "";
}

std::string firstTexelBeyondFloat(const ImageRGB& image, const Vec3& scale) {
  return firstBeyondFloat(
      image.width, image.height, [&](uint32_t x, uint32_t y) { return image.at(x, y); }, scale);
}

std::string firstTexelBeyondFloat(const TextureDesc& texture, const Vec3& scale) {
  if (texture.texelsF.empty()) return "";  // 8-bit texels are at most 1
  return firstBeyondFloat(
      texture.width, texture.height,
      [&](uint32_t x, uint32_t y) {
        const float* t = &texture.texelsF[4 * (size_t(y) * texture.width + x)];
        return Vec3(t[0], t[1], t[2]);
      },
      scale);
}

}  // namespace candela
