// The colour of a material at a surface point: `color` alone, or its texture times `color` (a
// tint, 1 unless the scene or the MTL's Kd sets another).
#pragma once

#include "core/texture.h"
#include "geometry/surface.h"
#include "render/material.h"
#include "render/scene_view.h"

namespace candela {

CANDELA_HDI Vec3 surfaceColor(const SceneView& scene, const Material& m, const Hit& hit,
                              const SurfacePoint& sp) {
  if (m.colorTexture.index < 0) return m.color;
  const Vec2 uv = surfaceUv(scene, hit, sp);
  return m.color * lookupTexture(scene.texturePool(), m.colorTexture, uv.x, uv.y).rgb;
}

}  // namespace candela
