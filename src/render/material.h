// Materials: a plain tag and the parameters of every kind, read by render/bsdf.h.
//
// The scene description and the kernel share this struct: a material has one home.
#pragma once

#include <cstdint>

#include "core/texture.h"
#include "core/vec3.h"
#include "geometry/alpha_mask.h"

namespace candela {

enum class MaterialType : uint32_t { Diffuse = 0, Mirror = 1, Glass = 2, Emissive = 3 };

struct Material {
  MaterialType type = MaterialType::Diffuse;
  Vec3 color{0.8f};     // diffuse albedo, mirror tint or glass transmission tint
  float ior = 1.5f;     // glass: relative index, outside -> inside
  Vec3 radiance{0.0f};  // emissive: emitted radiance from the front side
  TextureRef colorTexture;  // diffuse: a texture that `color` tints (render/surface_color.h)
  AlphaMask alpha;          // how much of the surface is there (geometry/alpha_mask.h)
};

}  // namespace candela
