// The alpha test of traversal (geometry/alpha_mask.h): whether a triangle hit is a surface.
#pragma once

#include <cstdint>

#include "core/float_error.h"
#include "core/rng.h"
#include "core/texture.h"
#include "geometry/geometry_view.h"
#include "geometry/ray.h"
#include "geometry/surface_uv.h"

namespace candela {

// A number in [0, 1) that is a pure function of the ray's origin and direction: the same ray
// meets the same threshold in every engine and on every run.
CANDELA_HDI float rayHash(const Ray& ray) {
  const float words[6] = {ray.origin.x,    ray.origin.y,    ray.origin.z,
                          ray.direction.x, ray.direction.y, ray.direction.z};
  uint64_t h = 0x9e3779b97f4a7c15ull;
  for (int i = 0; i < 6; ++i) h = mix64(h ^ floatToBits(words[i]));
  return toUnitFloat(h);
}

// The alpha of triangle `tri` at barycentrics (b1, b2), in [0, 1]; the scene must have masks.
CANDELA_HDI float triangleAlpha(const GeometryView& scene, const Triangle& tri, float b1,
                                float b2) {
  const AlphaMask& mask = scene.alphaMasks[tri.material];
  float alpha = mask.constant;
  if (mask.texture.index >= 0) {
    const Vec2 uv = triangleUv(scene, tri, b1, b2);
    const TextureSample s = lookupTexture(scene.texturePool(), mask.texture, uv.x, uv.y);
    alpha *= mask.channel == 3 ? s.alpha : s.rgb.x;
  }
  return alpha;
}

// Whether `ray`'s hit of `tri` at (b1, b2) counts where the scene has masks; never at alpha 0.
// Out of line: inlined into traversal, it slowed scenes without any mask by a tenth.
CANDELA_HD_COLD inline bool maskedAlphaKeepsHit(const GeometryView& scene, const Triangle& tri,
                                                float b1, float b2, const Ray& ray) {
  const float alpha = triangleAlpha(scene, tri, b1, b2);
  if (alpha >= 1.0f) return true;
  if (!(alpha > 0.0f)) return false;
  return rayHash(ray) < alpha;
}

// Whether `ray`'s hit of `tri` at (b1, b2) counts: always without masks.
CANDELA_HDI bool alphaKeepsHit(const GeometryView& scene, const Triangle& tri, float b1, float b2,
                               const Ray& ray) {
  return scene.alphaMaskCount == 0 || maskedAlphaKeepsHit(scene, tri, b1, b2, ray);
}

}  // namespace candela
