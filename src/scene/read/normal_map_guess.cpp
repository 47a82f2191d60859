// Telling a normal map from a height map; see normal_map_guess.h.
#include "scene/read/normal_map_guess.h"

#include <cmath>
#include <cstddef>

#include "scene/read/texture_reader.h"

namespace candela {

bool holdsUnitNormals(const TextureDesc& texture) {
  const size_t count = size_t(texture.width) * texture.height;
  if (count == 0) return false;
  size_t unit = 0, grey = 0;
  for (size_t i = 0; i < count; ++i) {
    float c[3];
    for (int k = 0; k < 3; ++k) c[k] = texelValue(texture, i, uint32_t(k));
    const float x = 2.0f * c[0] - 1.0f, y = 2.0f * c[1] - 1.0f, z = 2.0f * c[2] - 1.0f;
    const float length = std::sqrt(x * x + y * y + z * z);
    unit += z > 0.0f && std::fabs(length - 1.0f) < 0.1f;
    // Two 8-bit steps apart at most: a grey texel.
    grey += std::fabs(c[0] - c[1]) < 0.008f && std::fabs(c[1] - c[2]) < 0.008f;
  }
  return unit >= count * 9 / 10 && grey < count / 2;
}

}  // namespace candela
