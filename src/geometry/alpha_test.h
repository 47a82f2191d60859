// The alpha test of traversal (geometry/alpha_mask.h): whether a triangle hit is a surface.
#pragma once

#include <cstdint>

#include "core/dielectric_fresnel.h"
#include "core/float_error.h"
#include "core/rng.h"
#include "core/texture.h"
#include "geometry/geometry_view.h"
#include "geometry/motion.h"
#include "geometry/ray.h"
#include "geometry/surface_uv.h"

namespace candela {

// A hash of a vertex's position.
CANDELA_HDI uint64_t hashPosition(const Vec3& p) {
  return mix64(floatToBits(p.x) ^ (uint64_t(floatToBits(p.y)) << 32) ^ mix64(floatToBits(p.z)));
}

// The number in [0, 1) that a hit of `ray` on triangle `tri` passes when it is below the
// triangle's alpha there: a pure function of the ray's key (Ray::alphaKey, from its sample's
// random stream) and the triangle's vertices (in any order: not its index, which the own BVH's
// build reorders and Embree's does not). Not of the ray's bits, which rounding makes differ
// between the backends (fused multiply-adds on the GPU) and so would make their images part;
// and not of the ray alone, which would pass two half-transparent sheets together half the time
// instead of a quarter.
CANDELA_HDI float alphaThreshold(const GeometryView& scene, const Triangle& tri, const Ray& ray) {
  const uint64_t corners = hashPosition(scene.positions[tri.v[0]]) +
                           hashPosition(scene.positions[tri.v[1]]) +
                           hashPosition(scene.positions[tri.v[2]]);
  return toUnitFloat(mix64(corners ^ ray.alphaKey));
}

// The alpha of triangle `tri` at barycentrics (b1, b2) for `ray`, in [0, 1]; the scene must have
// masks.
CANDELA_HDI float triangleAlpha(const GeometryView& scene, const Triangle& tri, float b1, float b2,
                                const Ray& ray) {
  const AlphaMask& mask = scene.alphaMasks[tri.material];
  float alpha = mask.constant;
  if (mask.texture.index >= 0) {
    const Vec2 uv = triangleUv(scene, tri, b1, b2);
    const TextureSample s = lookupTexture(scene.texturePool(), mask.texture, uv.x, uv.y);
    alpha *= textureChannel(s, mask.channel);
  }
  if (mask.thinSheetIor > 0.0f) {
    Vec3 p[3];
    triangleCornersAt(scene, tri, ray.time, p);
    const Vec3 normal = cross(p[1] - p[0], p[2] - p[0]);
    const Vec3& direction = ray.direction;
    const float cosTheta = fabsf(dot(normal, direction)) / (length(normal) * length(direction));
    alpha *= thinSheetReflectance(minf(cosTheta, 1.0f), mask.thinSheetIor);
  }
  return alpha;
}

// Whether `ray`'s hit of `tri` at (b1, b2) counts where the scene has masks; never at alpha 0.
// Out of line: inlined into traversal, it slowed scenes without any mask by a tenth.
CANDELA_HD_COLD inline bool maskedAlphaKeepsHit(const GeometryView& scene, const Triangle& tri,
                                                float b1, float b2, const Ray& ray) {
  const float alpha = triangleAlpha(scene, tri, b1, b2, ray);
  if (alpha >= 1.0f) return true;
  if (!(alpha > 0.0f)) return false;
  return alphaThreshold(scene, tri, ray) < alpha;
}

// Whether `ray`'s hit of `tri` at (b1, b2) counts: always without masks.
CANDELA_HDI bool alphaKeepsHit(const GeometryView& scene, const Triangle& tri, float b1, float b2,
                               const Ray& ray) {
  return scene.alphaMaskCount == 0 || maskedAlphaKeepsHit(scene, tri, b1, b2, ray);
}

}  // namespace candela
