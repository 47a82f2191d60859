// The checks of texels read as radiance or as float textures: only finite, non-negative values
// (environment maps, float textures), and none that a radiance's scale carries beyond single
// precision (environment maps, emission textures).
#pragma once

#include <string>

#include "core/vec3.h"
#include "image/image.h"
#include "scene/scene_desc.h"

namespace candela {

// The first texel that is NaN, infinite or negative, as "texel (x, y) is NaN" (x from the left,
// y from the top), or "" when there is none.
std::string firstBadTexel(const ImageRGB& image);

// The first texel whose value times `scale` (the tint and strength a radiance map is rendered
// with) is not finite in single precision, as "texel (x, y), [r, g, b]", or "" when there is
// none. An 8-bit texture's texels are at most 1: "" for it where `scale` is finite.
std::string firstTexelBeyondFloat(const ImageRGB& image, const Vec3& scale);
std::string firstTexelBeyondFloat(const TextureDesc& texture, const Vec3& scale);

}  // namespace candela
