// What of a shadow query's contribution reaches its point: 1 where nothing blocks its ray, 0 where
// something does, and in scenes with glass of index 1 (render/index_matched.h) what the media
// inside such glass let through, the ray crossing their boundaries as the paths do.
#pragma once

#include <cstdint>

#include "core/float_error.h"
#include "geometry/surface.h"
#include "render/absorption.h"
#include "render/index_matched.h"
#include "render/scene_view.h"
#include "render/shadow_query.h"
#include "render/surface_color.h"

namespace candela {

// The most index-matched boundaries one shadow ray crosses (then it counts as blocked): enough
// for any scene of boxes of smoke, and a bound where a surface would be met again and again.
constexpr uint32_t kMostShadowCrossings = 64;

// What reaches the far end of shadow query q's ray, per channel. Outside scenes with
// index-matched glass this is the occlusion query alone; within them the ray is traced hit by hit:
// index-matched surfaces tint it by their colour, the media it travels through (from q.medium on)
// by their transmittance, and anything else blocks it.
template <class Tracer>
CANDELA_HDI Vec3 shadowTransmittance(const SceneView& scene, const Tracer& tracer,
                                     const ShadowQuery& q) {
  if (!scene.indexMatchedMedia) return tracer.occluded(q.ray, q.skipPrim) ? Vec3(0.0f) : Vec3(1.0f);
  Ray ray = q.ray;
  int32_t medium = q.medium;
  Vec3 kept(1.0f);
  for (uint32_t crossing = 0; crossing <= kMostShadowCrossings; ++crossing) {
    Hit hit;
    const bool found = tracer.closest(ray, &hit);
    const bool reached = !found || hit.prim == q.skipPrim;  // the light's own surface is its end
    if (medium >= 0) {
      const Material& inside = scene.materials[medium];
      kept *= beerTransmittance(inside.absorption + inside.scattering, reached ? ray.tMax : hit.t);
    }
    if (reached) return kept;
    const SurfacePoint sp = surfaceAt(scene, ray, hit);
    const Material& m = scene.materials[sp.material];
    if (!isIndexMatched(m) || crossing == kMostShadowCrossings) return Vec3(0.0f);
    kept *= surfaceColor(scene, m, hit, sp);
    medium = mediumAlong(m, sp.material, ray.direction, sp.ng);
    const Vec3 origin = offsetRayOrigin(sp.p, sp.error, sp.ng, ray.direction);
    ray.tMax -= length(origin - ray.origin);
    ray.origin = origin;
    if (!(ray.tMax > 0.0f)) return kept;
  }
  return Vec3(0.0f);
}

}  // namespace candela
