// The check that an image read as radiance or as a float texture holds only finite,
// non-negative values (environment maps, float textures).
#pragma once

#include <string>

#include "image/image.h"

namespace candela {

// The first texel that is NaN, infinite or negative, as "texel (x, y) is NaN" (x from the left,
// y from the top), or "" when there is none.
std::string firstBadTexel(const ImageRGB& image);

}  // namespace candela
