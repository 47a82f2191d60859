// Checking texels; see texel_check.h.
#include "scene/read/texel_check.h"

#include <cmath>

namespace candela {

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

}  // namespace candela
